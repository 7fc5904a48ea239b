// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/trace/SignalHistory.h"
#include "core/trace/SignalSample.h"
#include "core/trace/TraceStore.h"

#include <atomic>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <vector>

namespace coscope {

// The sample history of one signal (DESIGN.md "Data flow": plot buffers fed by the ingest
// worker). One writer (the ingest thread) appends; any thread reads; a mutex guards both and
// is held for a batch (writer) or one query (reader), never across a frame loop of the other
// side. Bounded (issue 38): when `capacity` samples are exceeded the oldest chunk (65536 samples)
// leaves the buffer for its decimated history (SignalHistory, a fixed number of buckets with
// their extremes), so the whole signal stays in view: every query covers the history too, at
// its resolution (first(), at(), nearest(), samples() name its buckets' first and last samples;
// range(), decimate() and envelope() use their extremes). size() counts the detailed samples.
//
// Min/max pyramid (the plot's redraw cost follows pixels, not samples): each chunk keeps
// summaries (min, max, AND and OR of the integer value) of blocks of 16, 256, 4096 and 65536
// samples (the whole chunk), built as samples arrive, so the extremes of any stretch cost at
// most ~15 block reads per level whatever the zoom and the length of the history. AND/OR give
// the extremes of one bit of the value (digital traces of 6041h/6040h bits) the same way.
class SignalBuffer {
public:
    static constexpr size_t kChunkSize = 65536;
    // 2 chunks of detail behind the one filling (~6 MiB at most, 2 to 3 min at 1 kHz); older
    // samples are in the history.
    static constexpr size_t kDefaultCapacity = size_t(2) * kChunkSize;

    explicit SignalBuffer(size_t capacity = kDefaultCapacity);
    ~SignalBuffer();
    SignalBuffer(const SignalBuffer&) = delete;
    SignalBuffer& operator=(const SignalBuffer&) = delete;

    // Writer side.
    void append(const SignalSample& s) { append(std::span<const SignalSample>(&s, 1)); }
    void append(std::span<const SignalSample> samples);
    void clear();

    // Reader side (any thread).
    size_t size() const;
    // Samples appended since construction (dropped ones included): changes when data arrives.
    uint64_t appended() const { return appended_.load(std::memory_order_acquire); }
    uint64_t dropped() const;  // samples no longer held one by one (in the history)
    // Buckets of the decimated history, and samples in each of them.
    size_t historyBuckets() const;
    size_t historySamplesPerBucket() const;
    std::optional<SignalSample> first() const;
    std::optional<SignalSample> last() const;
    // The last sample at or before t (the value a cursor at t reads), else the first after it.
    std::optional<SignalSample> at(int64_t timeNs) const;
    // The sample closest in time to t.
    std::optional<SignalSample> nearest(int64_t timeNs) const;
    // Every sample with t0 <= time <= t1 (exports).
    std::vector<SignalSample> samples(int64_t t0, int64_t t1) const;
    // Extremes over t0 <= time <= t1 (bit >= 0: of that bit of the integer value, 0 or 1).
    SignalRange range(int64_t t0, int64_t t1, int bit = -1) const;
    // A polyline of the samples in [t0, t1] for a plot `buckets` pixels wide: the samples
    // themselves when there are at most 2 per bucket, else per bucket its min and max (in the
    // order they occurred). The samples just outside the window are included so lines reach
    // the edges. bit >= 0: that bit of the integer value.
    std::vector<SignalPoint> decimate(int64_t t0, int64_t t1, int buckets, int bit = -1) const;
    // What the plot draws: decimate(t0, t1, columns) (into `out`, reusing its memory), except
    // that when a column holds at least 64 samples the edges between columns snap to blocks of
    // at most a quarter column (the window's own ends stay exact). A sample near an edge may
    // count in the neighbouring column, about a quarter pixel away at most; in exchange a replot
    // reads one contiguous run of block summaries per chunk (the "edge index", 4-8 reads a
    // column) instead of searching and climbing the pyramid at every column edge.
    void envelope(int64_t t0, int64_t t1, int columns, std::vector<SignalPoint>& out) const;

private:
    struct Summary {
        double min, max;
        uint64_t andBits, orBits;
    };
    struct MinMax {
        double min, max;
    };
    struct Bits {
        uint64_t andBits, orBits;
    };
    struct Chunk;
    struct Edge;
    // Global sample indexes: first() is base_, the newest base_ + size - 1.
    size_t countLocked() const;
    size_t lowerBoundLocked(int64_t timeNs) const;  // first index with time >= t
    size_t lowerBoundNearLocked(int64_t timeNs, size_t hint, size_t from,
                                size_t n) const;  // same in [from, n], galloping from `hint`
    SignalPoint pointLocked(size_t r) const;      // time and value only (no frame)
    const SignalSample sampleLocked(size_t r) const;
    template <bool WithBits>
    Summary reduceLocked(size_t from, size_t to) const;  // [from, to), non-empty; AND/OR only WithBits
    void prefetchLocked(size_t r, size_t span) const;    // hints the reads of a column edge there
    std::vector<SignalSample> samplesLocked(size_t from, size_t to) const;
    void decimateLocked(size_t from, size_t to, int64_t t0, int64_t t1, int buckets, int bit,
                        std::vector<SignalPoint>& out) const;

    // [t0, t1] split where the detailed samples begin: the part before it is the history's.
    bool historyPartLocked(int64_t t0, int64_t t1, int64_t* historyEnd) const;
    SignalRange rangeLocked(int64_t t0, int64_t t1, int bit) const;  // the detailed samples only

    size_t capacityChunks_;
    mutable std::mutex mutex_;
    SignalHistory history_;  // the samples of the chunks that left
    std::deque<std::unique_ptr<Chunk>> chunks_;
    std::vector<int64_t> chunkStart_;  // first time of each chunk (searched without touching them)
    uint64_t base_ = 0;                // global index of chunks_.front()'s first sample
    std::atomic<uint64_t> appended_{0};
};

}  // namespace coscope
