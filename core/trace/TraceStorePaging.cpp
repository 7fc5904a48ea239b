// SPDX-License-Identifier: GPL-3.0-or-later
// TraceStore's bounded memory (issue 16): eviction of least recently read durable chunks and
// loading them back from the pager.
#include "core/trace/TracePager.h"
#include "core/trace/TraceStore.h"

#include <algorithm>
#include <chrono>
#include <limits>

#include <spdlog/spdlog.h>

namespace coscope {

void TraceStore::setPager(std::shared_ptr<TracePager> pager) {
    std::lock_guard lock(pageMutex_);
    pager_ = std::move(pager);
}

void TraceStore::setMemoryBudget(size_t bytes) {
    budget_.store(bytes, std::memory_order_relaxed);
    std::lock_guard lock(pageMutex_);
    evictOverBudget(std::numeric_limits<uint32_t>::max());
}

size_t TraceStore::residentChunks() const {
    size_t n = 0;
    const size_t used = chunksUsed();
    for (size_t c = 0; c < used; ++c)
        if (chunks_[c].load(std::memory_order_acquire)) ++n;
    return n;
}

void TraceStore::pin(FrameNo first, FrameNo last) const {
    for (uint32_t c = first >> kChunkBits; c <= (last >> kChunkBits); ++c)
        pins_[c].fetch_add(1, std::memory_order_relaxed);
}

void TraceStore::unpin(FrameNo first, FrameNo last) const {
    for (uint32_t c = first >> kChunkBits; c <= (last >> kChunkBits); ++c)
        pins_[c].fetch_sub(1, std::memory_order_relaxed);
}

bool TraceStore::isResident(FrameNo n) const {
    return n < size() && chunks_[n >> kChunkBits].load(std::memory_order_acquire) != nullptr;
}

void TraceStore::requestPageIn(FrameNo n) const {
    if (n >= size()) return;
    const uint32_t c = n >> kChunkBits;
    if (chunks_[c].load(std::memory_order_acquire)) return;
    {
        std::lock_guard lock(requestMutex_);
        if (stopLoader_) return;
        if (std::find(requests_.begin(), requests_.end(), c) == requests_.end()) requests_.push_back(c);
        if (!loader_.joinable()) loader_ = std::thread([this] { loaderLoop(); });
    }
    requestWake_.notify_one();
}

void TraceStore::loaderLoop() const {
    std::unique_lock lock(requestMutex_);
    for (;;) {
        requestWake_.wait(lock, [this] { return stopLoader_ || !requests_.empty(); });
        if (stopLoader_) return;
        const uint32_t c = requests_.front();
        requests_.erase(requests_.begin());
        lock.unlock();
        if (!chunks_[c].load(std::memory_order_acquire)) pageIn(c);
        lock.lock();
    }
}

void TraceStore::stopLoader() {
    {
        std::lock_guard lock(requestMutex_);
        stopLoader_ = true;
    }
    requestWake_.notify_all();
    if (loader_.joinable()) loader_.join();
}

void TraceStore::evictOverBudget(uint32_t keep) const {
    const size_t budget = budget_.load(std::memory_order_relaxed);
    if (budget && pager_) {
        const uint64_t durable = pager_->durableFrames();
        const size_t used = chunksUsed();
        while (residentBytes_.load(std::memory_order_relaxed) + indexBytes_.load(std::memory_order_relaxed) > budget) {
            uint32_t victim = std::numeric_limits<uint32_t>::max();
            uint32_t oldest = std::numeric_limits<uint32_t>::max();
            for (uint32_t c = 0; c < used; ++c) {
                // Only a whole chunk the pager holds can come back; the one being written never is.
                if (c == keep || (uint64_t{c} + 1) * kChunkSize > durable) continue;
                if (!chunks_[c].load(std::memory_order_relaxed) || pins_[c].load(std::memory_order_relaxed)) continue;
                const uint32_t use = lastUse_[c].load(std::memory_order_relaxed);
                if (use < oldest) {
                    oldest = use;
                    victim = c;
                }
            }
            if (victim == std::numeric_limits<uint32_t>::max()) break;
            Chunk* p = chunks_[victim].exchange(nullptr, std::memory_order_acq_rel);
            residentBytes_.fetch_sub(p->bytes(), std::memory_order_relaxed);
            retired_.emplace_back(p, nowMs());
        }
    }
    freeRetired(false);
}

void TraceStore::freeRetired(bool all) const {
    const int64_t now = nowMs();
    size_t drop = 0;  // retired_ is in eviction order: free from the front
    while (drop < retired_.size() &&
           (all || retired_.size() - drop > kMaxRetired || now - retired_[drop].second >= kGraceMs))
        delete retired_[drop++].first;
    retired_.erase(retired_.begin(), retired_.begin() + static_cast<std::ptrdiff_t>(drop));
}

TraceStore::Chunk* TraceStore::pageIn(uint32_t c) const {
    if ((uint64_t{c} << kChunkBits) >= size()) {  // not a frame of this store (a caller's bug)
        static Chunk* const none = new Chunk();
        return none;
    }
    std::lock_guard loading(loadMutex_);
    if (Chunk* p = chunks_[c].load(std::memory_order_acquire)) return p;  // loaded meanwhile
    const uint64_t first = uint64_t{c} << kChunkBits;
    const size_t size = this->size();
    std::shared_ptr<TracePager> pager;
    {
        std::lock_guard lock(pageMutex_);
        pager = pager_;
    }
    auto* chunk = new Chunk();  // value-initialised: a frame that cannot be loaded reads as zeros
    size_t bytes = sizeof(Chunk);
    {
        const auto count = static_cast<uint32_t>(std::min<uint64_t>(kChunkSize, size - first));
        std::vector<CanFrame> frames;
        std::string why = "no journal to load from";
        if (pager && pager->load(first, count, frames, &why) && frames.size() == count) {
            for (uint32_t i = 0; i < count; ++i) bytes += fill(*chunk, chunk->records[i], frames[i]);
        } else {
            // Said, not dropped silently: the frames read as empty until the file is back.
            pageErrors_.fetch_add(1, std::memory_order_relaxed);
            spdlog::error("trace: cannot load frames {}..{} back from the journal: {}", first, first + count - 1, why);
        }
    }
    pageIns_.fetch_add(1, std::memory_order_relaxed);
    if (std::this_thread::get_id() == watched_.load(std::memory_order_relaxed))
        watchedPageIns_.fetch_add(1, std::memory_order_relaxed);
    std::lock_guard lock(pageMutex_);
    lastUse_[c].store(clock_.fetch_add(2, std::memory_order_relaxed) + 1, std::memory_order_relaxed);
    residentBytes_.fetch_add(bytes, std::memory_order_relaxed);
    chunks_[c].store(chunk, std::memory_order_release);
    evictOverBudget(c);
    return chunk;
}

}  // namespace coscope
