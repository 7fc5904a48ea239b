// SPDX-License-Identifier: GPL-3.0-or-later
// Folder core/trace/ owns the trace: the frame store (compact records, indexes), the capture
// session (the ingest worker that drains a live bus into the store and its consumers) and the
// signal buffers of the plots.
#pragma once

#include "core/can/CanFrame.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <span>
#include <thread>
#include <unordered_map>
#include <vector>

namespace coscope {

class IndexSpill;
class TracePager;

using FrameNo = uint32_t;  // stable frame number: position in the store, 0-based

// One stored frame: 24 bytes. Classic payloads (≤ 8 bytes) are inline; CAN FD payloads longer
// than 8 bytes live out of line in the FD blocks of the frame's chunk and `fdRef` locates them.
struct TraceRecord {
    int64_t timestampNs;
    uint32_t id;
    uint8_t len;
    uint8_t flags;
    uint8_t bus;
    uint8_t reserved;
    union {
        uint8_t data[8];
        uint64_t fdRef;
    };
};
static_assert(sizeof(TraceRecord) == 24, "trace records must stay 24 bytes");

// Append-only store for tens of millions of frames (one writer, any number of readers):
// fixed-size records in chunks of 64Ki frames (no reallocation, so readers never see memory
// move), FD payloads out of line in their chunk, and a per-COB-ID index of frame numbers. A frame
// number, once given, always names the same frame. Readers see frames [0, size()) and may read
// them while the writer appends; size() is published with release semantics after each append,
// before the frames enter their index, so index entries never point at or past size().
// Memory per classic frame: 24 bytes of record + 4 bytes of index entry.
//
// Bounded memory (issue 16): with a pager (the capture journal) and a budget, the store keeps
// at most the budget in RAM. When over it, the least recently read chunks that the pager holds
// durably are evicted; reading a frame of an evicted chunk loads the whole chunk back from the
// pager (any thread, transparently). Never evicted: a chunk not yet in the pager, a pinned one.
// An evicted chunk's memory is freed only after a grace period (kGraceMs, or when more than
// kMaxRetired are waiting), so a reference from record()/payload() stays valid while it is used
// right away; do not keep one across calls. The per-COB-ID indexes keep their newest block of
// 4096 frame numbers per key in RAM; their full blocks go to an IndexSpill file next to the
// journal (the pager's spillDirectory()), so memory stays flat however long the capture runs.
class TraceStore {
public:
    static constexpr uint32_t kChunkBits = 16;  // 65536 records (1.5 MiB) per chunk
    static constexpr uint32_t kChunkSize = 1u << kChunkBits;
    static constexpr uint32_t kMaxChunks = 1u << 16;  // up to 2^32 frames
    static constexpr int kGraceMs = 1000;
    static constexpr size_t kMaxRetired = 16;

    TraceStore();
    ~TraceStore();
    TraceStore(const TraceStore&) = delete;
    TraceStore& operator=(const TraceStore&) = delete;

    // Writer side (one thread at a time).
    FrameNo append(const CanFrame& frame);
    void append(std::span<const CanFrame> frames);

    // Reader side (any thread).
    size_t size() const { return size_.load(std::memory_order_acquire); }
    bool empty() const { return size() == 0; }
    const TraceRecord& record(FrameNo n) const { return chunk(n >> kChunkBits)->records[n & (kChunkSize - 1)]; }
    CanFrame frame(FrameNo n) const;
    // The payload bytes of frame n (empty for remote frames).
    std::span<const uint8_t> payload(FrameNo n) const;

    // Index key of a frame: the identifier plus a bit for 29-bit ids and one for error frames,
    // so 123h standard and 00000123h extended are different keys.
    static uint32_t keyOf(uint32_t id, bool extended, bool error = false) {
        return id | (extended ? 0x80000000u : 0u) | (error ? 0x40000000u : 0u);
    }
    static uint32_t keyOf(const TraceRecord& r) {
        return keyOf(r.id, r.flags & CanFrame::Extended, r.flags & CanFrame::Error);
    }
    // Frames with this key, in order: count and the i-th frame number.
    size_t countFor(uint32_t key) const;
    FrameNo frameFor(uint32_t key, size_t i) const;
    std::vector<FrameNo> framesFor(uint32_t key) const;
    // Keys seen so far, ascending.
    std::vector<uint32_t> keys() const;

    // Bytes held in RAM (resident chunks, their FD payloads, indexes), for the benchmark and
    // the status bar.
    size_t memoryBytes() const;

    // Paging. The pager holds frame n of this store as its frame n (the journal of a live
    // capture). Set it and the budget before the first append or while no reader runs.
    void setPager(std::shared_ptr<TracePager> pager);
    // 0: unlimited (the default; nothing is evicted).
    void setMemoryBudget(size_t bytes);
    size_t memoryBudget() const { return budget_.load(std::memory_order_relaxed); }
    // Chunks in RAM now, and how many times a chunk was loaded back / failed to load.
    size_t residentChunks() const;
    uint64_t pageIns() const { return pageIns_.load(std::memory_order_relaxed); }
    uint64_t pageErrors() const { return pageErrors_.load(std::memory_order_relaxed); }
    // Page-ins made on one thread, which then waited for the disk: the GUI thread must not
    // (issue 16: stalls under 100 ms). For the tests and the soak benchmark. Any thread.
    void watchPageInsOn(std::thread::id thread) { watched_.store(thread, std::memory_order_relaxed); }
    uint64_t watchedPageIns() const { return watchedPageIns_.load(std::memory_order_relaxed); }
    // Keeps the chunks of frames [first, last] in RAM until unpin() with the same range (the
    // rows a view shows). Any thread.
    void pin(FrameNo first, FrameNo last) const;
    void unpin(FrameNo first, FrameNo last) const;
    // True if frame n is in RAM now: reading it does not wait for the disk. Any thread.
    bool isResident(FrameNo n) const;
    // Loads frame n's chunk back on the store's loader thread and returns at once, so a GUI
    // thread never waits for the disk: it asks for the rows it is about to show, draws them as
    // loading, and draws them again once pageIns() has grown. Any thread.
    void requestPageIn(FrameNo n) const;
    // A gap in a live capture (issue 16 "Lost adapter"): the adapter was lost at lostNs and back
    // at backNs; frames from firstFrame on came after it. Not a frame: no consumer or CANopen
    // dispatcher sees it, views mark the first frame after it. Any thread.
    struct Gap {
        FrameNo firstFrame;
        int64_t lostNs;
        int64_t backNs;
    };
    // Kept in frame order; gaps before the same frame in the order they were added.
    void addGap(const Gap& gap) {
        std::lock_guard lock(gapMutex_);
        gaps_.insert(std::upper_bound(gaps_.begin(), gaps_.end(), gap.firstFrame,
                                      [](FrameNo n, const Gap& g) { return n < g.firstFrame; }),
                     gap);
    }
    std::vector<Gap> gaps() const {
        std::lock_guard lock(gapMutex_);
        return gaps_;
    }
    // The gaps that end right before frame n (usually none; two when the adapter was lost again
    // before its first frame came). A binary search: views ask for every row they paint.
    std::vector<Gap> gapsAt(FrameNo n) const {
        std::lock_guard lock(gapMutex_);
        const auto [b, e] = std::equal_range(gaps_.begin(), gaps_.end(), Gap{n, 0, 0},
                                             [](const Gap& x, const Gap& y) { return x.firstFrame < y.firstFrame; });
        return {b, e};
    }

private:
    static int64_t nowMs();                       // steady clock, for the retired index tables' age
    static constexpr uint32_t kFdBlockBits = 20;  // FD payloads: 1 MiB blocks per chunk
    static constexpr uint32_t kFdBlocks = 4;      // 65536 frames x 64 bytes
    struct Chunk {
        TraceRecord records[kChunkSize];
        std::atomic<uint8_t*> fd[kFdBlocks] = {};
        uint32_t fdUsed = 0;  // filled by one thread (writer or loader) before publication
        ~Chunk();
        // Chunks and FD blocks are mapped from and given back to the kernel directly: from
        // malloc, a 1.5 MiB block freed on another thread than the one that allocated it stays
        // in that thread's arena, and the process grows although the store does not.
        static void* operator new(size_t bytes);
        static void operator delete(void* p, size_t bytes);
        size_t bytes() const;
    };
    class Index;
    Index* indexForWrite(uint32_t key);
    IndexSpill* spillForWrite();  // writer only; nullptr without bounded memory
    const Index* indexForRead(uint32_t key) const;
    static uint64_t storeFdPayload(Chunk& c, const uint8_t* data, uint8_t len, size_t* added);
    static size_t fill(Chunk& c, TraceRecord& r, const CanFrame& f);  // FD bytes allocated
    static std::span<const uint8_t> payloadOf(const Chunk& c, const TraceRecord& r);
    Chunk* chunk(uint32_t c) const {
        Chunk* p = chunks_[c].load(std::memory_order_acquire);
        if (!p) return pageIn(c);
        const uint32_t now = clock_.load(std::memory_order_relaxed);
        if (lastUse_[c].load(std::memory_order_relaxed) != now) lastUse_[c].store(now, std::memory_order_relaxed);
        return p;
    }
    Chunk* pageIn(uint32_t c) const;
    void loaderLoop() const;
    void stopLoader();
    void evictOverBudget(uint32_t keep) const;  // pageMutex_ held
    void freeRetired(bool all) const;           // pageMutex_ held
    size_t chunksUsed() const { return (size() + kChunkSize - 1) >> kChunkBits; }

    std::unique_ptr<std::atomic<Chunk*>[]> chunks_;
    // Written once per appended batch and read by every reader: a cache line of its own, so the
    // writer's stores do not evict what readers read on each frame (chunks_, clock_).
    alignas(64) std::atomic<size_t> size_{0};
    alignas(64) mutable std::atomic<size_t> residentBytes_{0};

    // Paging state: the LRU clock advances by 2 on each chunk allocation and page-in, which
    // stamps its chunk with the odd value between; a read stamps its chunk with the clock, so
    // a chunk read after a page-in is younger than the chunk paged in.
    std::shared_ptr<TracePager> pager_;
    std::atomic<size_t> budget_{0};
    mutable std::atomic<uint32_t> clock_{1};
    std::unique_ptr<std::atomic<uint32_t>[]> lastUse_;
    std::unique_ptr<std::atomic<uint32_t>[]> pins_;
    mutable std::mutex loadMutex_;                             // one page-in at a time (disk reads outside pageMutex_)
    mutable std::mutex pageMutex_;                             // eviction, installation, retired_
    mutable std::vector<std::pair<Chunk*, int64_t>> retired_;  // chunk, steady ms when evicted
    mutable std::atomic<uint64_t> pageIns_{0};
    mutable std::atomic<uint64_t> pageErrors_{0};
    std::atomic<std::thread::id> watched_{};
    mutable std::atomic<uint64_t> watchedPageIns_{0};
    // Asynchronous page-ins: chunk numbers asked for, served by loader_ (started on first use).
    mutable std::mutex requestMutex_;
    mutable std::condition_variable requestWake_;
    mutable std::vector<uint32_t> requests_;
    mutable std::thread loader_;
    mutable bool stopLoader_ = false;

    // Index: direct table for the 2048 standard ids, a map for the rest. Full index blocks of a
    // store with a budget and a pager go to spill_ (declared before indexes_,
    // so it outlives them).
    std::unique_ptr<IndexSpill> spill_;
    bool spillTried_ = false;
    std::unique_ptr<std::atomic<Index*>[]> stdIndex_;
    std::unordered_map<uint32_t, Index*> writerOther_;  // writer's private view
    mutable std::shared_mutex otherMutex_;
    std::unordered_map<uint32_t, Index*> other_;   // readers' view
    std::vector<std::unique_ptr<Index>> indexes_;  // owner (writer only)
    std::atomic<size_t> indexBytes_{0};

    mutable std::mutex gapMutex_;
    std::vector<Gap> gaps_;
};

}  // namespace coscope
