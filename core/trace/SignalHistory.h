// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/trace/SignalSample.h"
#include "core/trace/TraceStore.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace coscope {

// The decimated past of one signal (issue 38: a day-long capture in bounded memory): the
// samples a SignalBuffer no longer holds one by one, as a fixed number of buckets of
// consecutive samples, each with its first and last sample, its extremes and when they
// occurred, and the AND and OR of its integer values (the extremes of one bit). The memory is
// taken once, at the first sample; when every bucket is used, neighbours merge in pairs and
// new buckets take twice as many samples, so the whole history stays in view at a resolution
// that halves as it grows (a day at 1 kHz in 8192 buckets: about 10 s a bucket, more than one
// per pixel column of a whole-day plot). Not thread-safe: SignalBuffer's mutex guards it.
class SignalHistory {
public:
    static constexpr size_t kBuckets = 8192;
    static constexpr size_t kFirstSamplesPerBucket = 64;

    void add(int64_t timeNs, double value, FrameNo frame);
    void clear();

    bool empty() const { return used_ == 0 && open_.count == 0; }
    size_t buckets() const { return used_ + (open_.count ? 1 : 0); }
    uint64_t samples() const { return samples_; }  // added since the last clear()
    size_t samplesPerBucket() const { return perBucket_; }
    size_t memoryBytes() const { return store_.capacity() * sizeof(Bucket); }
    int64_t lastTime() const;  // of the newest sample added (0 when empty)

    std::optional<SignalSample> first() const;
    // The sample at or before t that the history can name (a bucket's first or last), else the
    // first one.
    std::optional<SignalSample> at(int64_t timeNs) const;
    std::optional<SignalSample> nearest(int64_t timeNs) const;
    // The first and last sample of each bucket with t0 <= time <= t1 (exports of old data).
    void samples(int64_t t0, int64_t t1, std::vector<SignalSample>& out) const;
    // Extremes over [t0, t1] of the buckets that overlap it (bit >= 0: of that bit).
    SignalRange range(int64_t t0, int64_t t1, int bit) const;
    // A polyline of [t0, t1] for `columns` pixel columns: per column at most two points, its
    // extremes in the order they occurred (one for a single sample). With
    // `withBefore` the last point before t0 is included, so lines reach the window's edge.
    void points(int64_t t0, int64_t t1, int columns, int bit, bool withBefore, std::vector<SignalPoint>& out) const;

private:
    struct Bucket {
        int64_t tFirst = 0, tLast = 0, tMin = 0, tMax = 0;
        double first = 0, last = 0, min = 0, max = 0;
        uint64_t andBits = 0, orBits = 0;
        FrameNo frameFirst = 0, frameLast = 0;
        uint64_t count = 0;
    };
    static void merge(Bucket& into, const Bucket& next);
    const Bucket& bucket(size_t i) const { return i < used_ ? store_[i] : open_; }
    size_t lowerBound(int64_t timeNs) const;  // first bucket whose last time is >= t
    void halve();

    std::vector<Bucket> store_;  // kBuckets, taken at the first add()
    size_t used_ = 0;            // closed buckets in store_
    Bucket open_;                // the bucket filling
    size_t perBucket_ = kFirstSamplesPerBucket;
    uint64_t samples_ = 0;
};

}  // namespace coscope
