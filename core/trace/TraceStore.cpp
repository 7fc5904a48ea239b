// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/trace/TraceStore.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace coscope {

// Frame numbers of one key, in chunks of 4096; the chunk table grows by copying into a larger
// table, and old tables stay alive until the store dies so a reader holding one stays valid.
class TraceStore::Index {
public:
    static constexpr uint32_t kBits = 12;
    static constexpr uint32_t kSize = 1u << kBits;

    ~Index() {
        const size_t n = (count_.load() + kSize - 1) / kSize;
        Table* t = table_.load();
        for (size_t i = 0; i < n; ++i) delete[] t->chunks[i];
        for (Table* old : retired_) delete old;
        delete t;
    }

    // Writer only.
    size_t push(FrameNo f) {
        const size_t n = count_.load(std::memory_order_relaxed);
        const size_t c = n >> kBits;
        size_t added = 0;
        Table* t = table_.load(std::memory_order_relaxed);
        if ((n & (kSize - 1)) == 0) {
            if (!t || c >= t->capacity) {
                auto* bigger = new Table;
                bigger->capacity = t ? t->capacity * 2 : 4;
                bigger->chunks = std::make_unique<FrameNo*[]>(bigger->capacity);
                if (t) std::copy_n(t->chunks.get(), t->capacity, bigger->chunks.get());
                added += bigger->capacity * sizeof(FrameNo*);
                if (t) retired_.push_back(t);
                t = bigger;
                table_.store(t, std::memory_order_release);
            }
            t->chunks[c] = new FrameNo[kSize];
            added += kSize * sizeof(FrameNo);
        }
        t->chunks[c][n & (kSize - 1)] = f;
        count_.store(n + 1, std::memory_order_release);
        return added;
    }

    size_t count() const { return count_.load(std::memory_order_acquire); }
    FrameNo at(size_t i) const {
        const Table* t = table_.load(std::memory_order_acquire);
        return t->chunks[i >> kBits][i & (kSize - 1)];
    }

private:
    struct Table {
        size_t capacity = 0;
        std::unique_ptr<FrameNo*[]> chunks;
    };
    std::atomic<Table*> table_{nullptr};
    std::atomic<size_t> count_{0};
    std::vector<Table*> retired_;
};

TraceStore::TraceStore()
    : chunks_(new std::atomic<TraceRecord*>[kMaxChunks]),
      fdChunks_(new std::atomic<uint8_t*>[kMaxFdChunks]),
      stdIndex_(new std::atomic<Index*>[2048]) {
    for (uint32_t i = 0; i < kMaxChunks; ++i) chunks_[i].store(nullptr, std::memory_order_relaxed);
    for (uint32_t i = 0; i < kMaxFdChunks; ++i) fdChunks_[i].store(nullptr, std::memory_order_relaxed);
    for (uint32_t i = 0; i < 2048; ++i) stdIndex_[i].store(nullptr, std::memory_order_relaxed);
}

TraceStore::~TraceStore() {
    for (uint32_t i = 0; i < kMaxChunks; ++i) {
        TraceRecord* c = chunks_[i].load();
        if (!c) break;
        ::operator delete[](c);
    }
    for (uint32_t i = 0; i < kMaxFdChunks; ++i) delete[] fdChunks_[i].load();
}

TraceStore::Index* TraceStore::indexForWrite(uint32_t key) {
    if (key < 2048) {
        Index* idx = stdIndex_[key].load(std::memory_order_relaxed);
        if (idx) return idx;
        indexes_.push_back(std::make_unique<Index>());
        idx = indexes_.back().get();
        stdIndex_[key].store(idx, std::memory_order_release);
        return idx;
    }
    auto it = writerOther_.find(key);
    if (it != writerOther_.end()) return it->second;
    indexes_.push_back(std::make_unique<Index>());
    Index* idx = indexes_.back().get();
    writerOther_.emplace(key, idx);
    std::unique_lock lock(otherMutex_);
    other_.emplace(key, idx);
    return idx;
}

const TraceStore::Index* TraceStore::indexForRead(uint32_t key) const {
    if (key < 2048) return stdIndex_[key].load(std::memory_order_acquire);
    std::shared_lock lock(otherMutex_);
    auto it = other_.find(key);
    return it == other_.end() ? nullptr : it->second;
}

uint64_t TraceStore::storeFdPayload(const uint8_t* data, uint8_t len) {
    constexpr uint32_t chunkBytes = 1u << kFdChunkBits;
    if (fdUsed_ + len > chunkBytes) {
        const uint32_t next = fdChunks_[0].load(std::memory_order_relaxed) ? fdChunk_ + 1 : 0;
        if (next >= kMaxFdChunks) throw std::length_error("trace store: CAN FD payload arena is full");
        fdChunks_[next].store(new uint8_t[chunkBytes], std::memory_order_release);
        fdChunk_ = next;
        fdUsed_ = 0;
        fdBytes_.fetch_add(chunkBytes, std::memory_order_relaxed);
    }
    uint8_t* dst = fdChunks_[fdChunk_].load(std::memory_order_relaxed) + fdUsed_;
    std::memcpy(dst, data, len);
    const uint64_t ref = (static_cast<uint64_t>(fdChunk_) << kFdChunkBits) | fdUsed_;
    fdUsed_ += len;
    return ref;
}

const uint8_t* TraceStore::fdPayload(uint64_t ref) const {
    return fdChunks_[ref >> kFdChunkBits].load(std::memory_order_acquire) + (ref & ((1u << kFdChunkBits) - 1));
}

FrameNo TraceStore::append(const CanFrame& f) {
    const size_t n = size_.load(std::memory_order_relaxed);
    if (n >= static_cast<size_t>(kChunkSize) * kMaxChunks) throw std::length_error("trace store is full (2^32 frames)");
    const uint32_t c = static_cast<uint32_t>(n >> kChunkBits);
    TraceRecord* chunk = chunks_[c].load(std::memory_order_relaxed);
    if (!chunk) {
        chunk = static_cast<TraceRecord*>(::operator new[](sizeof(TraceRecord) * kChunkSize));
        chunks_[c].store(chunk, std::memory_order_release);
    }
    TraceRecord& r = chunk[n & (kChunkSize - 1)];
    r.timestampNs = f.timestampNs;
    r.id = f.id;
    r.len = f.len;
    r.flags = f.flags;
    r.bus = f.bus;
    r.reserved = 0;
    r.fdRef = 0;
    const uint8_t bytes = f.payloadSize();
    if (bytes > 8) r.fdRef = storeFdPayload(f.data.data(), bytes);
    else std::memcpy(r.data, f.data.data(), bytes);

    // Publish the frame before indexing it: an index entry must never name a frame a reader
    // cannot see yet (the index may lag size() by one frame, never lead it).
    size_.store(n + 1, std::memory_order_release);
    const size_t added = indexForWrite(keyOf(r))->push(static_cast<FrameNo>(n));
    if (added) indexBytes_.fetch_add(added, std::memory_order_relaxed);
    return static_cast<FrameNo>(n);
}

void TraceStore::append(std::span<const CanFrame> frames) {
    for (const CanFrame& f : frames) append(f);
}

CanFrame TraceStore::frame(FrameNo n) const {
    const TraceRecord& r = record(n);
    CanFrame f;
    f.timestampNs = r.timestampNs;
    f.id = r.id;
    f.len = r.len;
    f.flags = r.flags;
    f.bus = r.bus;
    const auto p = payload(n);
    std::memcpy(f.data.data(), p.data(), p.size());
    return f;
}

std::span<const uint8_t> TraceStore::payload(FrameNo n) const {
    const TraceRecord& r = record(n);
    const uint8_t bytes = (r.flags & CanFrame::Remote) ? 0 : r.len;
    if (bytes > 8) return {fdPayload(r.fdRef), bytes};
    return {r.data, bytes};
}

size_t TraceStore::countFor(uint32_t key) const {
    const Index* idx = indexForRead(key);
    return idx ? idx->count() : 0;
}

FrameNo TraceStore::frameFor(uint32_t key, size_t i) const { return indexForRead(key)->at(i); }

std::vector<FrameNo> TraceStore::framesFor(uint32_t key) const {
    std::vector<FrameNo> out;
    const Index* idx = indexForRead(key);
    if (!idx) return out;
    const size_t n = idx->count();
    out.reserve(n);
    for (size_t i = 0; i < n; ++i) out.push_back(idx->at(i));
    return out;
}

std::vector<uint32_t> TraceStore::keys() const {
    std::vector<uint32_t> out;
    for (uint32_t k = 0; k < 2048; ++k)
        if (stdIndex_[k].load(std::memory_order_acquire)) out.push_back(k);
    {
        std::shared_lock lock(otherMutex_);
        for (const auto& [k, idx] : other_) out.push_back(k);
    }
    std::sort(out.begin(), out.end());
    return out;
}

size_t TraceStore::memoryBytes() const {
    const size_t n = size();
    const size_t chunks = (n + kChunkSize - 1) / kChunkSize;
    return chunks * kChunkSize * sizeof(TraceRecord) + fdBytes_.load(std::memory_order_relaxed) +
           indexBytes_.load(std::memory_order_relaxed);
}

}  // namespace coscope
