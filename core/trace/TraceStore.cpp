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

TraceStore::Chunk::~Chunk() {
    for (auto& block : fd) delete[] block.load();
}

size_t TraceStore::Chunk::bytes() const {
    size_t n = sizeof(Chunk);
    for (const auto& block : fd)
        if (block.load(std::memory_order_relaxed)) n += size_t{1} << kFdBlockBits;
    return n;
}

TraceStore::TraceStore()
    : chunks_(new std::atomic<Chunk*>[kMaxChunks]),
      lastUse_(new std::atomic<uint32_t>[kMaxChunks]),
      pins_(new std::atomic<uint32_t>[kMaxChunks]),
      stdIndex_(new std::atomic<Index*>[2048]) {
    for (uint32_t i = 0; i < kMaxChunks; ++i) {
        chunks_[i].store(nullptr, std::memory_order_relaxed);
        lastUse_[i].store(0, std::memory_order_relaxed);
        pins_[i].store(0, std::memory_order_relaxed);
    }
    for (uint32_t i = 0; i < 2048; ++i) stdIndex_[i].store(nullptr, std::memory_order_relaxed);
}

TraceStore::~TraceStore() {
    const size_t used = (size() + kChunkSize - 1) / kChunkSize;
    for (size_t i = 0; i < used + 1 && i < kMaxChunks; ++i) delete chunks_[i].load();
    std::lock_guard lock(pageMutex_);
    freeRetired(true);
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

uint64_t TraceStore::storeFdPayload(Chunk& c, const uint8_t* data, uint8_t len, size_t* added) {
    constexpr uint32_t blockBytes = 1u << kFdBlockBits;
    uint32_t block = c.fdUsed >> kFdBlockBits;
    if ((c.fdUsed & (blockBytes - 1)) + len > blockBytes) {  // does not fit: next block
        ++block;
        c.fdUsed = block << kFdBlockBits;
    }
    if (block >= kFdBlocks) throw std::length_error("trace store: CAN FD payloads of a chunk overflow");
    uint8_t* dst = c.fd[block].load(std::memory_order_relaxed);
    if (!dst) {
        dst = new uint8_t[blockBytes];
        c.fd[block].store(dst, std::memory_order_release);
        *added += blockBytes;
    }
    const uint64_t ref = c.fdUsed;
    std::memcpy(dst + (ref & (blockBytes - 1)), data, len);
    c.fdUsed += len;
    return ref;
}

size_t TraceStore::fill(Chunk& c, TraceRecord& r, const CanFrame& f) {
    size_t added = 0;
    r.timestampNs = f.timestampNs;
    r.id = f.id;
    r.len = f.len;
    r.flags = f.flags;
    r.bus = f.bus;
    r.reserved = 0;
    r.fdRef = 0;
    const uint8_t bytes = f.payloadSize();
    if (bytes > 8) r.fdRef = storeFdPayload(c, f.data.data(), bytes, &added);
    else std::memcpy(r.data, f.data.data(), bytes);
    return added;
}

FrameNo TraceStore::append(const CanFrame& f) {
    const size_t n = size_.load(std::memory_order_relaxed);
    if (n >= static_cast<size_t>(kChunkSize) * kMaxChunks) throw std::length_error("trace store is full (2^32 frames)");
    const uint32_t c = static_cast<uint32_t>(n >> kChunkBits);
    // The chunk being written is never evicted (the pager does not hold it yet).
    Chunk* chunk = chunks_[c].load(std::memory_order_relaxed);
    if (!chunk) {
        chunk = new Chunk;
        lastUse_[c].store(clock_.fetch_add(2, std::memory_order_relaxed) + 1, std::memory_order_relaxed);
        chunks_[c].store(chunk, std::memory_order_release);
        residentBytes_.fetch_add(sizeof(Chunk), std::memory_order_relaxed);
        if (budget_.load(std::memory_order_relaxed)) {
            std::lock_guard lock(pageMutex_);
            evictOverBudget(c);
        }
    }
    if (const size_t added = fill(*chunk, chunk->records[n & (kChunkSize - 1)], f))
        residentBytes_.fetch_add(added, std::memory_order_relaxed);

    // Publish the frame before indexing it: an index entry must never name a frame a reader
    // cannot see yet (the index may lag size() by one frame, never lead it).
    size_.store(n + 1, std::memory_order_release);
    const size_t added = indexForWrite(keyOf(chunk->records[n & (kChunkSize - 1)]))->push(static_cast<FrameNo>(n));
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
    const Chunk* c = chunk(n >> kChunkBits);
    const TraceRecord& r = c->records[n & (kChunkSize - 1)];
    const uint8_t bytes = (r.flags & CanFrame::Remote) ? 0 : r.len;
    if (bytes > 8) {
        const uint8_t* block = c->fd[r.fdRef >> kFdBlockBits].load(std::memory_order_acquire);
        return {block + (r.fdRef & ((1u << kFdBlockBits) - 1)), bytes};
    }
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
    return residentBytes_.load(std::memory_order_relaxed) + indexBytes_.load(std::memory_order_relaxed);
}

}  // namespace coscope
