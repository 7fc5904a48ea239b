// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/trace/TraceDecoder.h"

#include "dissectors/DictionaryCatalog.h"

#include <algorithm>
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
    checkpoints_.emplace(0, std::make_shared<const NetworkContext>(base_));
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
    checkpoints_.emplace(0, std::make_shared<const NetworkContext>(base_));
    cache_.clear();
    wanted_.clear();
    built_ = 1;
    stride_ = 1;
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
    return built_;
}

size_t TraceDecoder::keptCheckpoints() const {
    std::lock_guard lock(mutex_);
    return checkpoints_.size() + cache_.size();
}

size_t TraceDecoder::checkpointStride() const {
    std::lock_guard lock(mutex_);
    return stride_;
}

void TraceDecoder::thinLocked() const {
    if (built_ <= kRecent + 1) return;
    const size_t recentFrom = built_ - kRecent;
    // The one that just left the newest kRecent stays only on the grid.
    const size_t left = recentFrom - 1;
    if (left % stride_ != 0) checkpoints_.erase(left);
    size_t sparse = 0;
    for (auto it = checkpoints_.begin(); it != checkpoints_.end() && it->first < recentFrom; ++it) ++sparse;
    if (sparse <= kSparse) return;
    stride_ *= 2;
    for (auto it = checkpoints_.begin(); it != checkpoints_.end() && it->first < recentFrom;)
        it = it->first % stride_ != 0 ? checkpoints_.erase(it) : std::next(it);
}

std::shared_ptr<const NetworkContext> TraceDecoder::findLocked(size_t k) const {
    if (const auto it = checkpoints_.find(k); it != checkpoints_.end()) return it->second;
    if (const auto it = cache_.find(k); it != cache_.end()) {
        it->second.used = ++useClock_;
        return it->second.context;
    }
    return nullptr;
}

std::shared_ptr<const NetworkContext> TraceDecoder::rebuildLocked(std::unique_lock<std::mutex>& lock, size_t k) const {
    // The nearest snapshot at or before k, kept or cached (0 is always kept).
    auto from = std::prev(checkpoints_.upper_bound(k));
    size_t j = from->first;
    std::shared_ptr<const NetworkContext> start = from->second;
    if (auto c = cache_.upper_bound(k); c != cache_.begin() && std::prev(c)->first > j) {
        --c;
        j = c->first;
        start = c->second.context;
    }
    if (j == k) return start;
    const auto store = store_;
    const uint64_t rev = revision();
    lock.unlock();
    // The snapshots of the last chunk's worth of positions up to k are kept as they are passed:
    // the rows next to the one asked for are asked next.
    constexpr size_t kPerChunk = TraceStore::kChunkSize / kInterval;
    NetworkContext context(*start);
    Dissection scratch;
    std::vector<std::pair<size_t, std::shared_ptr<const NetworkContext>>> made;
    for (size_t p = j; p < k; ++p) {
        for (uint64_t n = p * kInterval; n < (p + 1) * kInterval; ++n)
            context.dissect(store->frame(static_cast<FrameNo>(n)), scratch, Dissection::Level::Stats);
        if (p + 1 + kPerChunk > k) made.emplace_back(p + 1, std::make_shared<const NetworkContext>(context));
    }
    lock.lock();
    std::shared_ptr<const NetworkContext> out = made.back().second;
    if (revision() != rev) return out;
    for (auto& [p, c] : made)
        if (!checkpoints_.count(p)) cache_[p] = Cached{std::move(c), ++useClock_};
    while (cache_.size() > kCached) {
        auto oldest = cache_.begin();
        for (auto it = cache_.begin(); it != cache_.end(); ++it)
            if (it->second.used < oldest->second.used) oldest = it;
        cache_.erase(oldest);
    }
    rebuilt_.fetch_add(1, std::memory_order_acq_rel);
    return out;
}

bool TraceDecoder::readyAt(const TraceStore& store, FrameNo n) const {
    const size_t k = n / kInterval;
    std::lock_guard lock(mutex_);
    if (&store != store_.get() || k >= built_ || findLocked(k)) return true;
    if (std::find(wanted_.begin(), wanted_.end(), k) == wanted_.end()) wanted_.push_back(k);
    wake_.notify_all();
    return false;
}

// Builds the next snapshot from the last one, without holding the lock while dissecting.
bool TraceDecoder::extendOnceLocked(std::unique_lock<std::mutex>& lock) const {
    while (extending_) wake_.wait(lock);
    if (stop_ || !store_) return false;
    const size_t have = built_;
    if (store_->size() < have * kInterval) return false;
    const auto from = checkpoints_.at(have - 1);
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
    if (revision() == rev && built_ == have) {
        checkpoints_.emplace(have, std::move(next));
        ++built_;
        thinLocked();
    }
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
        if (!wanted_.empty()) {  // readyAt()'s older rows first: someone looks at them
            const size_t k = wanted_.back();
            wanted_.pop_back();
            if (k < built_ && !findLocked(k) && store_) rebuildLocked(lock, k);
            continue;
        }
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
        base = checkpoints_.begin()->second;
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
            if (built_ > k) break;
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
            auto snapshot = findLocked(k);
            if (!snapshot) snapshot = rebuildLocked(lock, k);
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
