// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/trace/TraceDecoder.h"

#include "dissectors/DictionaryCatalog.h"

#include <chrono>
#include <optional>
#include <unordered_map>

namespace coscope::gui {

using dissect::Dissection;
using dissect::NetworkContext;

namespace {

constexpr uint64_t kInterval = NetworkContext::checkpointInterval();

std::atomic<uint64_t> nextDecoderId{1};

// A context positioned before frame `at` of `store`, private to one thread.
struct Cursor {
    uint64_t revision = 0;
    const TraceStore* store = nullptr;
    uint64_t at = 0;
    std::optional<NetworkContext> context;
};

std::unordered_map<uint64_t, Cursor>& threadCursors() {
    thread_local std::unordered_map<uint64_t, Cursor> cursors;
    return cursors;
}

}  // namespace

TraceDecoder::TraceDecoder(bool background) : id_(nextDecoderId.fetch_add(1)) {
    checkpoints_.push_back(std::make_shared<const NetworkContext>(base_));
    if (background) worker_ = std::thread([this] { workerLoop(); });
}

TraceDecoder::~TraceDecoder() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    if (worker_.joinable()) worker_.join();
    threadCursors().erase(id_);
}

void TraceDecoder::resetCheckpointsLocked() {
    checkpoints_.clear();
    checkpoints_.push_back(std::make_shared<const NetworkContext>(base_));
    revision_.fetch_add(1, std::memory_order_acq_rel);
    wake_.notify_all();
}

void TraceDecoder::setStore(std::shared_ptr<const TraceStore> store) {
    std::lock_guard lock(mutex_);
    store_ = std::move(store);
    resetCheckpointsLocked();
}

void TraceDecoder::setDictionaries(const std::map<int, QString>& names) {
    std::lock_guard lock(mutex_);
    if (names == names_) return;
    names_ = names;
    base_ = NetworkContext();
    lastError_.clear();
    for (const auto& [node, name] : names_) {
        if (node < 1 || node > 127 || name.isEmpty()) continue;
        auto it = loaded_.find(name);
        if (it == loaded_.end()) {
            QString dictName, error;
            dissect::DictionaryPtr d = eds::DictionaryLibrary::shared().loadShared(name, &dictName, &error);
            if (!d) {
                lastError_ = error;
                continue;
            }
            it = loaded_.emplace(name, std::pair{std::move(d), dictName}).first;
        }
        base_.assignDictionary(node, it->second.first, it->second.second, true);
    }
    resetCheckpointsLocked();
}

std::map<int, QString> TraceDecoder::dictionaries() const {
    std::lock_guard lock(mutex_);
    return names_;
}

QString TraceDecoder::lastError() const {
    std::lock_guard lock(mutex_);
    return lastError_;
}

size_t TraceDecoder::checkpointCount() const {
    std::lock_guard lock(mutex_);
    return checkpoints_.size();
}

// Builds the next snapshot from the last one, without holding the lock while dissecting.
bool TraceDecoder::extendOnceLocked(std::unique_lock<std::mutex>& lock) const {
    while (extending_) wake_.wait(lock);
    if (stop_ || !store_) return false;
    const size_t have = checkpoints_.size();
    if (store_->size() < have * kInterval) return false;
    const auto from = checkpoints_.back();
    const auto store = store_;
    const uint64_t rev = revision();
    extending_ = true;
    lock.unlock();
    auto next = std::make_shared<NetworkContext>(*from);
    Dissection scratch;
    for (uint64_t n = (have - 1) * kInterval; n < have * kInterval; ++n)
        next->dissect(store->frame(static_cast<FrameNo>(n)), scratch, Dissection::Level::Stats);
    lock.lock();
    extending_ = false;
    if (revision() == rev && checkpoints_.size() == have) checkpoints_.push_back(std::move(next));
    wake_.notify_all();
    return true;
}

// Nothing to do means the store has less than one interval past the last snapshot. Nobody
// signals its growth, so the worker looks again: soon while it grows (a log being opened fills an
// interval in well under a millisecond; sleeping 250 ms there left the index that far behind
// at the end of the load), rarely when it does not.
void TraceDecoder::workerLoop() {
    std::unique_lock lock(mutex_);
    size_t seen = 0;
    while (!stop_) {
        if (extendOnceLocked(lock) || stop_) continue;
        const size_t size = store_ ? store_->size() : 0;
        const bool growing = size != seen;
        seen = size;
        wake_.wait_for(lock, growing ? std::chrono::milliseconds(10) : std::chrono::milliseconds(250));
    }
}

void TraceDecoder::decode(const CanFrame& frame, Dissection& out) const {
    std::shared_ptr<const NetworkContext> base;
    {
        std::lock_guard lock(mutex_);
        base = checkpoints_.front();
    }
    NetworkContext context(*base);
    context.dissect(frame, out, out.level());
}

void TraceDecoder::decodeAt(const TraceStore& store, FrameNo n, Dissection& out) const {
    const size_t k = n / kInterval;
    Cursor& cursor = threadCursors()[id_];
    {
        std::unique_lock lock(mutex_);
        for (;;) {
            if (&store != store_.get() || n >= store.size()) {
                lock.unlock();
                decode(store.frame(n), out);
                return;
            }
            if (checkpoints_.size() > k) break;
            if (!extendOnceLocked(lock)) {  // stopping
                lock.unlock();
                decode(store.frame(n), out);
                return;
            }
        }
        const uint64_t rev = revision();
        const bool usable = cursor.context && cursor.revision == rev && cursor.store == &store && cursor.at <= n &&
                            cursor.at >= k * kInterval;
        if (!usable) {
            const auto snapshot = checkpoints_[k];
            lock.unlock();
            cursor.context.emplace(*snapshot);
            cursor.revision = rev;
            cursor.store = &store;
            cursor.at = k * kInterval;
        }
    }
    thread_local Dissection skip;
    for (; cursor.at < n; ++cursor.at)
        cursor.context->dissect(store.frame(static_cast<FrameNo>(cursor.at)), skip, Dissection::Level::Stats);
    cursor.context->dissect(store.frame(n), out, out.level());
    cursor.at = n + 1;
}

}  // namespace coscope::gui
