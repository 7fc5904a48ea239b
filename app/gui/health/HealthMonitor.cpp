// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/health/HealthMonitor.h"

#include <algorithm>
#include <chrono>

#ifdef __linux__
#include <sys/resource.h>
#include <unistd.h>
#endif

namespace coscope::gui {

namespace {
// consumeLater()'s thread analyses this many frames per turn of its loop and publishes a report
// at most every kPublishMs (a report sorts and sums every track), and whenever it has caught up.
constexpr size_t kLaterBatch = 4096;
constexpr auto kPublishMs = std::chrono::milliseconds(250);
}  // namespace

HealthMonitor::HealthMonitor() { ctx_.setGenericNames(false); }

HealthMonitor::~HealthMonitor() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
        pending_.clear();
    }
    pendingAdded_.notify_all();
    if (later_.joinable()) later_.join();
}

void HealthMonitor::addLocked(const TraceStore& store, FrameNo first, size_t count) {
    for (size_t i = 0; i < count; ++i) {
        const CanFrame f = store.frame(first + static_cast<FrameNo>(i));
        if (!f.isError()) ctx_.dissect(f, d_, dissect::Dissection::Level::Stats);
        health_.add(f, d_, ctx_, static_cast<int64_t>(first) + static_cast<int64_t>(i));  // the trace's frame number
    }
}

void HealthMonitor::consume(const TraceStore& store, FrameNo first, size_t count) {
    if (count == 0) return;
    std::lock_guard lock(stateMutex_);
    addLocked(store, first, count);
    revision_.fetch_add(count, std::memory_order_release);
}

void HealthMonitor::consumeLater(std::shared_ptr<const TraceStore> store, FrameNo first, size_t count) {
    if (count == 0 || !store) return;
    {
        std::lock_guard lock(mutex_);
        laterMode_ = true;
        Pending* last = pending_.empty() ? nullptr : &pending_.back();
        if (last && last->store == store && last->first + last->count == first) last->count += count;
        else pending_.push_back({std::move(store), first, count});
        if (!later_.joinable()) later_ = std::thread([this] { laterLoop(); });
    }
    pendingAdded_.notify_one();
}

bool HealthMonitor::caughtUp() const {
    std::lock_guard lock(mutex_);
    return pending_.empty() && inFlight_ == 0;
}

void HealthMonitor::laterLoop() {
#ifdef __linux__
    // The lowest priority, for this thread alone (on Linux a thread's nice value is its own).
    setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), 19);
#endif
    auto lastPublished = std::chrono::steady_clock::now();
    std::unique_lock lock(mutex_);
    for (;;) {
        pendingAdded_.wait(lock, [this] { return stopping_ || !pending_.empty(); });
        if (stopping_) return;
        Pending& p = pending_.front();
        Pending work{p.store, p.first, std::min(p.count, kLaterBatch)};
        p.first += static_cast<FrameNo>(work.count);
        p.count -= work.count;
        if (p.count == 0) pending_.pop_front();
        inFlight_ += work.count;
        const bool publish = pending_.empty() || std::chrono::steady_clock::now() - lastPublished >= kPublishMs;
        const uint64_t generation = generation_.load(std::memory_order_acquire);
        lock.unlock();
        // Without mutex_: report() never waits for this thread, whose turn may come late.
        std::optional<dissect::HealthReport> report;
        {
            std::lock_guard state(stateMutex_);
            if (generation_.load(std::memory_order_acquire) == generation) {
                addLocked(*work.store, work.first, work.count);
                if (publish) report = health_.report(&ctx_, INT64_MIN);
            }
        }
        work.store.reset();
        lock.lock();
        if (generation_.load(std::memory_order_acquire) != generation) continue;  // cleared meanwhile
        if (publish && report) {
            lastPublished = std::chrono::steady_clock::now();
            published_ = std::move(report);
            inFlight_ = 0;
            revision_.fetch_add(1, std::memory_order_release);
        }
    }
}

void HealthMonitor::clear() {
    {
        std::lock_guard lock(mutex_);
        generation_.fetch_add(1, std::memory_order_acq_rel);
        pending_.clear();
        inFlight_ = 0;
        laterMode_ = false;
        published_.reset();
    }
    std::lock_guard state(stateMutex_);  // after a turn of consumeLater()'s thread, if one runs
    ctx_ = dissect::NetworkContext();
    ctx_.setGenericNames(false);
    health_ = dissect::NetworkHealth(health_.bitRate());
    revision_.fetch_add(1, std::memory_order_release);
}

dissect::HealthReport HealthMonitor::report(int64_t nowNs) const {
    {
        std::lock_guard lock(mutex_);
        if (laterMode_) return published_ ? *published_ : dissect::HealthReport{};
    }
    std::lock_guard state(stateMutex_);
    return health_.report(&ctx_, nowNs);
}

}  // namespace coscope::gui
