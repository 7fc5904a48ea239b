// SPDX-License-Identifier: GPL-3.0-or-later
// Folder core/trace/ owns the trace: the frame store (compact records, indexes), the capture
// session (the ingest worker that drains a live bus into the store and its consumers) and the
// signal buffers of the plots.
#pragma once

#include "core/can/CanFrame.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <span>
#include <unordered_map>
#include <vector>

namespace coscope {

using FrameNo = uint32_t;  // stable frame number: position in the store, 0-based

// One stored frame: 24 bytes. Classic payloads (≤ 8 bytes) are inline; CAN FD payloads longer
// than 8 bytes live out of line in the FD arena and `fdRef` locates them.
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
// fixed-size records in chunked arenas (no reallocation, so readers never see memory move),
// FD payloads out of line, and a per-COB-ID index of frame numbers. A frame number, once
// given, always names the same frame. Readers see frames [0, size()) and may read them
// while the writer appends; size() is published with release semantics after each append,
// before the frame enters its index, so index entries never point at or past size().
// Memory per classic frame: 24 bytes of record + 4 bytes of index entry.
class TraceStore {
public:
    static constexpr uint32_t kChunkBits = 16;  // 65536 records (1.5 MiB) per chunk
    static constexpr uint32_t kChunkSize = 1u << kChunkBits;
    static constexpr uint32_t kMaxChunks = 1u << 16;  // up to 2^32 frames

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
    const TraceRecord& record(FrameNo n) const {
        return chunks_[n >> kChunkBits].load(std::memory_order_acquire)[n & (kChunkSize - 1)];
    }
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

    // Bytes held (records, FD payloads, indexes), for the benchmark and the status bar.
    size_t memoryBytes() const;

private:
    class Index;
    Index* indexForWrite(uint32_t key);
    const Index* indexForRead(uint32_t key) const;
    uint64_t storeFdPayload(const uint8_t* data, uint8_t len);
    const uint8_t* fdPayload(uint64_t ref) const;

    std::unique_ptr<std::atomic<TraceRecord*>[]> chunks_;
    std::atomic<size_t> size_{0};

    // FD arena: 1 MiB chunks; ref = chunk << 20 | offset.
    static constexpr uint32_t kFdChunkBits = 20;
    static constexpr uint32_t kMaxFdChunks = 1u << 14;
    std::unique_ptr<std::atomic<uint8_t*>[]> fdChunks_;
    uint32_t fdChunk_ = 0;
    uint32_t fdUsed_ = 1u << kFdChunkBits;  // forces the first allocation
    std::atomic<size_t> fdBytes_{0};

    // Index: direct table for the 2048 standard ids, a map for the rest.
    std::unique_ptr<std::atomic<Index*>[]> stdIndex_;
    std::unordered_map<uint32_t, Index*> writerOther_;  // writer's private view
    mutable std::shared_mutex otherMutex_;
    std::unordered_map<uint32_t, Index*> other_;       // readers' view
    std::vector<std::unique_ptr<Index>> indexes_;      // owner (writer only)
    std::atomic<size_t> indexBytes_{0};
};

}  // namespace coscope
