// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/trace/TraceStore.h"

#include "core/trace/IndexSpill.h"
#include "core/trace/TracePager.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <new>
#include <stdexcept>

#include <spdlog/spdlog.h>
#include <sys/mman.h>

namespace coscope {

int64_t TraceStore::nowMs() {
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

// Frame numbers of one key, in blocks of 4096; the block table grows by copying into a larger
// table, and old tables stay alive until the store dies so a reader holding one stays valid.
// With bounded memory a full block moves to the store's IndexSpill (its address changes to the
// mapping, its RAM is freed after a grace period); the newest block stays in RAM.
class TraceStore::Index {
public:
    static constexpr uint32_t kBits = 12;
    static constexpr uint32_t kSize = 1u << kBits;
    static constexpr size_t kBlockBytes = kSize * sizeof(FrameNo);  // 16 KiB, whole pages

    explicit Index(const std::unique_ptr<IndexSpill>& spill) : spill_(spill) {}
    ~Index() {
        const size_t n = (count_.load() + kSize - 1) / kSize;
        Table* t = table_.load();
        for (size_t i = 0; i < n; ++i) {
            FrameNo* block = t->chunks[i].load();
            if (!spill_ || !spill_->holds(block)) delete[] block;
        }
        for (auto& [block, ms] : retiredBlocks_) delete[] block;
        for (Table* old : retired_) delete old;
        delete t;
    }

    // Writer only. Returns the change of the bytes held in RAM.
    std::ptrdiff_t push(FrameNo f, TraceStore& store) {
        const size_t n = count_.load(std::memory_order_relaxed);
        const size_t c = n >> kBits;
        std::ptrdiff_t added = 0;
        Table* t = table_.load(std::memory_order_relaxed);
        if ((n & (kSize - 1)) == 0) {
            if (!t || c >= t->capacity) {
                auto* bigger = new Table;
                bigger->capacity = t ? t->capacity * 2 : 4;
                bigger->chunks = std::make_unique<std::atomic<FrameNo*>[]>(bigger->capacity);
                for (size_t i = 0; t && i < t->capacity; ++i)
                    bigger->chunks[i].store(t->chunks[i].load(std::memory_order_relaxed), std::memory_order_relaxed);
                added += static_cast<std::ptrdiff_t>(bigger->capacity * sizeof(FrameNo*));
                if (t) retired_.push_back(t);
                t = bigger;
                table_.store(t, std::memory_order_release);
            }
            t->chunks[c].store(new FrameNo[kSize], std::memory_order_release);
            added += static_cast<std::ptrdiff_t>(kBlockBytes);
            if (c > 0) added -= spillBlock(t, c - 1, store);
        }
        t->chunks[c].load(std::memory_order_relaxed)[n & (kSize - 1)] = f;
        count_.store(n + 1, std::memory_order_release);
        return added;
    }

    size_t count() const { return count_.load(std::memory_order_acquire); }
    FrameNo at(size_t i) const {
        const Table* t = table_.load(std::memory_order_acquire);
        return t->chunks[i >> kBits].load(std::memory_order_acquire)[i & (kSize - 1)];
    }

private:
    struct Table {
        size_t capacity = 0;
        std::unique_ptr<std::atomic<FrameNo*>[]> chunks;
    };

    // Moves full block c to the spill file; returns the bytes of RAM given up.
    size_t spillBlock(Table* t, size_t c, TraceStore& store) {
        const int64_t now = nowMs();
        while (!retiredBlocks_.empty() && now - retiredBlocks_.front().second >= kGraceMs) {
            delete[] retiredBlocks_.front().first;
            retiredBlocks_.erase(retiredBlocks_.begin());
        }
        IndexSpill* spill = store.spillForWrite();
        FrameNo* block = t->chunks[c].load(std::memory_order_relaxed);
        if (!spill || spill->holds(block)) return 0;
        const auto* mapped = static_cast<const FrameNo*>(spill->write(block, kBlockBytes));
        if (!mapped) return 0;  // disk full: the block stays in RAM, nothing is lost
        t->chunks[c].store(const_cast<FrameNo*>(mapped), std::memory_order_release);
        retiredBlocks_.emplace_back(block, now);  // a reader may still hold it: freed after kGraceMs
        return kBlockBytes;
    }

    const std::unique_ptr<IndexSpill>& spill_;
    std::atomic<Table*> table_{nullptr};
    std::atomic<size_t> count_{0};
    std::vector<Table*> retired_;
    std::vector<std::pair<FrameNo*, int64_t>> retiredBlocks_;
};

namespace {
void* mapBytes(size_t bytes) {
    void* p = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    return p;
}
}  // namespace

void* TraceStore::Chunk::operator new(size_t bytes) { return mapBytes(bytes); }
void TraceStore::Chunk::operator delete(void* p, size_t bytes) { ::munmap(p, bytes); }

TraceStore::Chunk::~Chunk() {
    for (auto& block : fd)
        if (uint8_t* p = block.load()) ::munmap(p, size_t{1} << kFdBlockBits);
}

size_t TraceStore::Chunk::bytes() const {
    size_t n = sizeof(Chunk);
    for (const auto& block : fd)
        if (block.load(std::memory_order_relaxed)) n += size_t{1} << kFdBlockBits;
    return n;
}

TraceStore::TraceStore()
    : chunks_(new std::atomic<Chunk*>[kMaxChunks]), lastUse_(new std::atomic<uint32_t>[kMaxChunks]),
      pins_(new std::atomic<uint32_t>[kMaxChunks]), stdIndex_(new std::atomic<Index*>[2048]) {
    for (uint32_t i = 0; i < kMaxChunks; ++i) {
        chunks_[i].store(nullptr, std::memory_order_relaxed);
        lastUse_[i].store(0, std::memory_order_relaxed);
        pins_[i].store(0, std::memory_order_relaxed);
    }
    for (uint32_t i = 0; i < 2048; ++i) stdIndex_[i].store(nullptr, std::memory_order_relaxed);
}

TraceStore::~TraceStore() {
    stopLoader();
    const size_t used = (size() + kChunkSize - 1) / kChunkSize;
    for (size_t i = 0; i < used + 1 && i < kMaxChunks; ++i) delete chunks_[i].load();
    std::lock_guard lock(pageMutex_);
    freeRetired(true);
}

IndexSpill* TraceStore::spillForWrite() {
    if (spillTried_) return spill_ && spill_->ok() ? spill_.get() : nullptr;
    if (!budget_.load(std::memory_order_relaxed)) return nullptr;
    std::string dir;
    {
        std::lock_guard lock(pageMutex_);
        if (!pager_) return nullptr;
        dir = pager_->spillDirectory();
    }
    if (dir.empty()) return nullptr;
    spillTried_ = true;
    spill_ = std::make_unique<IndexSpill>(dir);
    if (!spill_->ok()) spdlog::warn("trace: the per-COB-ID index stays in RAM: {}", spill_->error());
    return spill_->ok() ? spill_.get() : nullptr;
}

TraceStore::Index* TraceStore::indexForWrite(uint32_t key) {
    if (key < 2048) {
        Index* idx = stdIndex_[key].load(std::memory_order_relaxed);
        if (idx) return idx;
        indexes_.push_back(std::make_unique<Index>(spill_));
        idx = indexes_.back().get();
        stdIndex_[key].store(idx, std::memory_order_release);
        return idx;
    }
    auto it = writerOther_.find(key);
    if (it != writerOther_.end()) return it->second;
    indexes_.push_back(std::make_unique<Index>(spill_));
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
        dst = static_cast<uint8_t*>(mapBytes(blockBytes));
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
    const auto n = static_cast<FrameNo>(size_.load(std::memory_order_relaxed));
    append(std::span<const CanFrame>(&f, 1));
    return n;
}

// A batch is written a chunk at a time: its records, then one publication of size_ (readers on
// other threads read the size and the chunks all the time: one store per frame made them wait
// for that cache line per frame), then its index entries.
void TraceStore::append(std::span<const CanFrame> frames) {
    while (!frames.empty()) {
        const size_t n = size_.load(std::memory_order_relaxed);
        if (n >= static_cast<size_t>(kChunkSize) * kMaxChunks)
            throw std::length_error("trace store is full (2^32 frames)");
        const uint32_t c = static_cast<uint32_t>(n >> kChunkBits);
        const size_t first = n & (kChunkSize - 1);
        const size_t count = std::min<size_t>(kChunkSize - first, frames.size());
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
        for (size_t i = 0; i < count; ++i) {
            if (const size_t added = fill(*chunk, chunk->records[first + i], frames[i])) {
                residentBytes_.fetch_add(added, std::memory_order_relaxed);
                // A chunk of FD frames grows by 1 MiB payload blocks: keep the budget when it
                // grows too, not only when a chunk starts (otherwise the store stays up to 4 MiB
                // over it).
                if (budget_.load(std::memory_order_relaxed)) {
                    std::lock_guard lock(pageMutex_);
                    evictOverBudget(c);
                }
            }
        }
        // Publish the frames before indexing them: an index entry must never name a frame a
        // reader cannot see yet (the index may lag size(), never lead it).
        size_.store(n + count, std::memory_order_release);
        std::ptrdiff_t added = 0;
        for (size_t i = 0; i < count; ++i)
            added += indexForWrite(keyOf(chunk->records[first + i]))->push(static_cast<FrameNo>(n + i), *this);
        if (added)
            indexBytes_.fetch_add(static_cast<size_t>(added), std::memory_order_relaxed);  // wraps down when negative
        frames = frames.subspan(count);
    }
}

// The payload of record r of chunk c (empty for remote frames).
std::span<const uint8_t> TraceStore::payloadOf(const Chunk& c, const TraceRecord& r) {
    const uint8_t bytes = (r.flags & CanFrame::Remote) ? 0 : r.len;
    if (bytes > 8) {
        const uint8_t* block = c.fd[r.fdRef >> kFdBlockBits].load(std::memory_order_acquire);
        return {block + (r.fdRef & ((1u << kFdBlockBits) - 1)), bytes};
    }
    return {r.data, bytes};
}

// Every analysis reads every frame through here (issue 19): one chunk lookup, and a classic
// payload as one 8-byte copy, masked to its length, instead of a call to memcpy.
CanFrame TraceStore::frame(FrameNo n) const {
    const Chunk* c = chunk(n >> kChunkBits);
    const TraceRecord& r = c->records[n & (kChunkSize - 1)];
    CanFrame f;
    f.timestampNs = r.timestampNs;
    f.id = r.id;
    f.len = r.len;
    f.flags = r.flags;
    f.bus = r.bus;
    const auto p = payloadOf(*c, r);
    if (p.size() > 8) {
        std::memcpy(f.data.data(), p.data(), p.size());
    } else {
        uint64_t v;
        std::memcpy(&v, r.data, 8);
        if (p.size() < 8) v &= (uint64_t{1} << (8 * p.size())) - 1;
        std::memcpy(f.data.data(), &v, 8);
    }
    return f;
}

std::span<const uint8_t> TraceStore::payload(FrameNo n) const {
    const Chunk* c = chunk(n >> kChunkBits);
    return payloadOf(*c, c->records[n & (kChunkSize - 1)]);
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
