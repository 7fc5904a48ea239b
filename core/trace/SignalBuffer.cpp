// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/trace/SignalBuffer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace coscope {

namespace {
// Pyramid levels: blocks of kFanout^(k+1) samples; the top level is the whole chunk.
constexpr size_t kFanout = 16;
constexpr int kLevels = 4;
constexpr size_t kBlock[kLevels] = {16, 256, 4096, 65536};
static_assert(kBlock[0] == kFanout && kBlock[1] == kBlock[0] * kFanout && kBlock[2] == kBlock[1] * kFanout &&
              kBlock[3] == kBlock[2] * kFanout);
static_assert(kBlock[kLevels - 1] == SignalBuffer::kChunkSize);
constexpr size_t kTimeBlock = 64;  // samples per entry of a chunk's search index
// Edge index levels (envelope()): blocks of 16 to 4096 samples, fanout 2, so that some level
// has blocks between 1/8 and 1/4 of any pixel column of 64 samples or more (4 to 8 reads a
// column; ~5 bytes a sample).
constexpr int kEdgeLevels = 9;
constexpr size_t kEdgeBlock[kEdgeLevels] = {16, 32, 64, 128, 256, 512, 1024, 2048, 4096};
constexpr size_t kEdgeBlocksPerColumn = 4;  // a level's block is at most a quarter column
static_assert(SignalBuffer::kChunkSize % kEdgeBlock[kEdgeLevels - 1] == 0);

// The pixel columns of [t0, t1] that fall before `historyEnd` (at least one).
int historyColumns(int64_t t0, int64_t t1, int64_t historyEnd, int columns) {
    const double share = (double(historyEnd) - double(t0) + 1) / std::max(1.0, double(t1) - double(t0) + 1);
    return std::clamp(int(std::lround(share * columns)), 1, std::max(1, columns));
}

uint64_t bitsOf(double v) {
    if (!std::isfinite(v)) return 0;
    if (v >= 0 && v >= 9.2e18) return static_cast<uint64_t>(v);
    return static_cast<uint64_t>(static_cast<int64_t>(v));
}
}  // namespace

// One block of an edge index level: its first sample's time, its first and last value and its
// extremes, together (40 bytes): an envelope reads these one after the other.
struct SignalBuffer::Edge {
    int64_t t;
    double first, last, min, max;
};

struct SignalBuffer::Chunk {
    std::vector<int64_t> t;
    std::vector<double> v;
    std::vector<FrameNo> f;
    // level[k][j]: extremes of samples [j * kBlock[k], (j + 1) * kBlock[k]); bits[k][j] the AND
    // and OR of their integer values. Kept apart: an analog trace's redraw reads only the
    // extremes (16 bytes a block), so a pixel column's edge touches half the memory.
    std::vector<MinMax> level[kLevels];
    std::vector<Bits> bits[kLevels];
    std::vector<int64_t> blockTime;       // time of each 64-block's first sample: searches touch few cache lines
    std::vector<Edge> edge[kEdgeLevels];  // edge[k][j]: samples [j * kEdgeBlock[k], (j + 1) * kEdgeBlock[k])

    size_t size() const { return t.size(); }
    void reserve(size_t samples) {
        t.reserve(samples);
        v.reserve(samples);
        f.reserve(samples);
        if (samples < kChunkSize) return;
        blockTime.reserve(kChunkSize / kTimeBlock);
        for (int k = 0; k < kLevels; ++k) {
            level[k].reserve(kChunkSize / kBlock[k]);
            bits[k].reserve(kChunkSize / kBlock[k]);
        }
        for (int k = 0; k < kEdgeLevels; ++k) edge[k].reserve(kChunkSize / kEdgeBlock[k]);
    }
    size_t lowerBound(int64_t time) const {
        const auto b =
            static_cast<size_t>(std::lower_bound(blockTime.begin(), blockTime.end(), time) - blockTime.begin());
        const size_t from = b > 0 ? (b - 1) * kTimeBlock : 0;
        const size_t to = std::min(t.size(), b * kTimeBlock);
        return static_cast<size_t>(std::lower_bound(t.begin() + static_cast<std::ptrdiff_t>(from),
                                                    t.begin() + static_cast<std::ptrdiff_t>(to), time) -
                                   t.begin());
    }
    bool full() const { return t.size() >= kChunkSize; }
    void push(const SignalSample& s) {
        const size_t i = t.size();
        t.push_back(s.timeNs);
        v.push_back(s.value);
        f.push_back(s.frame);
        if (i % kTimeBlock == 0) blockTime.push_back(s.timeNs);
        const uint64_t b = bitsOf(s.value);
        for (int k = 0; k < kLevels; ++k) {
            if (i % kBlock[k] == 0) {
                level[k].push_back({s.value, s.value});
                bits[k].push_back({b, b});
                continue;
            }
            MinMax& m = level[k].back();
            m.min = std::min(m.min, s.value);
            m.max = std::max(m.max, s.value);
            Bits& x = bits[k].back();
            x.andBits &= b;
            x.orBits |= b;
        }
        for (int k = 0; k < kEdgeLevels; ++k) {
            if (i % kEdgeBlock[k] == 0) {
                edge[k].push_back({s.timeNs, s.value, s.value, s.value, s.value});
                continue;
            }
            Edge& e = edge[k].back();
            e.last = s.value;
            e.min = std::min(e.min, s.value);
            e.max = std::max(e.max, s.value);
        }
    }
};

SignalBuffer::SignalBuffer(size_t capacity)
    : capacityChunks_(std::max<size_t>(1, (capacity + kChunkSize - 1) / kChunkSize)) {}
SignalBuffer::~SignalBuffer() = default;

void SignalBuffer::append(std::span<const SignalSample> samples) {
    if (samples.empty()) return;
    std::lock_guard lock(mutex_);
    for (const SignalSample& s : samples) {
        if (chunks_.empty() || chunks_.back()->full()) {
            if (chunks_.size() >= capacityChunks_ + 1) {  // keep `capacity` whole chunks behind the one filling
                const Chunk& old = *chunks_.front();
                for (size_t i = 0; i < old.size(); ++i) history_.add(old.t[i], old.v[i], old.f[i]);
                base_ += chunks_.front()->size();
                chunks_.pop_front();
                chunkStart_.erase(chunkStart_.begin());
            }
            auto c = std::make_unique<Chunk>();
            // A signal that filled a chunk fills the next: its memory is taken at once, in the
            // same sizes as the chunk evicted (issue 38: chunks grown by doubling and freed in
            // turn left the heap fragmented, its top creeping up by ~0.7 MiB a minute).
            const size_t reserve = chunks_.empty() ? 256 : kChunkSize;
            c->reserve(reserve);
            chunks_.push_back(std::move(c));
            chunkStart_.push_back(s.timeNs);
        }
        chunks_.back()->push(s);
    }
    appended_.fetch_add(samples.size(), std::memory_order_release);
}

void SignalBuffer::clear() {
    std::lock_guard lock(mutex_);
    chunks_.clear();
    chunkStart_.clear();
    history_.clear();
    base_ = appended_.load();
}

size_t SignalBuffer::countLocked() const {
    if (chunks_.empty()) return 0;
    return (chunks_.size() - 1) * kChunkSize + chunks_.back()->size();
}

size_t SignalBuffer::size() const {
    std::lock_guard lock(mutex_);
    return countLocked();
}

uint64_t SignalBuffer::dropped() const {
    std::lock_guard lock(mutex_);
    return base_;
}

size_t SignalBuffer::historyBuckets() const {
    std::lock_guard lock(mutex_);
    return history_.buckets();
}

size_t SignalBuffer::historySamplesPerBucket() const {
    std::lock_guard lock(mutex_);
    return history_.samplesPerBucket();
}

bool SignalBuffer::historyPartLocked(int64_t t0, int64_t t1, int64_t* historyEnd) const {
    if (history_.empty() || t1 < t0) return false;
    const int64_t detailFrom = countLocked() ? chunks_.front()->t[0] : INT64_MAX;
    if (t0 >= detailFrom) return false;
    *historyEnd = std::min(t1, detailFrom - 1);
    return true;
}

SignalPoint SignalBuffer::pointLocked(size_t r) const {
    const Chunk& c = *chunks_[r / kChunkSize];
    return {c.t[r % kChunkSize], c.v[r % kChunkSize]};
}

const SignalSample SignalBuffer::sampleLocked(size_t r) const {
    const Chunk& c = *chunks_[r / kChunkSize];
    const size_t i = r % kChunkSize;
    return {c.t[i], c.v[i], c.f[i]};
}

size_t SignalBuffer::lowerBoundLocked(int64_t timeNs) const {
    // The last chunk starting before t holds the answer (or it is the next chunk's first).
    const auto k =
        static_cast<size_t>(std::lower_bound(chunkStart_.begin(), chunkStart_.end(), timeNs) - chunkStart_.begin());
    if (k == 0) return 0;
    return (k - 1) * kChunkSize + chunks_[k - 1]->lowerBound(timeNs);
}

size_t SignalBuffer::lowerBoundNearLocked(int64_t timeNs, size_t hint, size_t from, size_t n) const {
    // Galloping search from the guess (a plot's buckets hold about as many samples as the one
    // before): a steady rate needs two probes, an irregular one a few doublings.
    auto time = [this](size_t r) { return chunks_[r / kChunkSize]->t[r % kChunkSize]; };
    if (from >= n) return from;
    hint = std::clamp(hint, from, n);
    size_t lo = from, hi = n;               // the answer lies in [lo, hi]
    if (hint < n && time(hint) < timeNs) {  // later: probe hint + 1, + 2, + 4, ...
        size_t below = hint;
        for (size_t step = 1;; step *= 2) {
            if (step >= n - below) break;
            if (time(below + step) >= timeNs) {
                hi = below + step;
                break;
            }
            below += step;
        }
        lo = below + 1;
    } else if (hint > from && time(hint - 1) >= timeNs) {  // earlier: probe hint - 2, - 3, - 5, ...
        size_t atOrAfter = hint - 1;
        for (size_t step = 1;; step *= 2) {
            if (atOrAfter - from < step) break;
            if (time(atOrAfter - step) < timeNs) {
                lo = atOrAfter - step + 1;
                break;
            }
            atOrAfter -= step;
        }
        hi = atOrAfter;
    } else {
        return hint;  // time(hint - 1) < t <= time(hint)
    }
    while (lo < hi) {  // binary search: first index in [lo, hi) with time >= t, else hi
        const size_t mid = lo + (hi - lo) / 2;
        if (time(mid) < timeNs) lo = mid + 1;
        else hi = mid;
    }
    return lo;
}

template <bool WithBits>
SignalBuffer::Summary SignalBuffer::reduceLocked(size_t from, size_t to) const {
    double mn = std::numeric_limits<double>::infinity(), mx = -std::numeric_limits<double>::infinity();
    uint64_t andBits = ~uint64_t(0), orBits = 0;
    while (from < to) {
        const Chunk& c = *chunks_[from / kChunkSize];
        size_t lo = from % kChunkSize;
        const size_t hi = std::min(kChunkSize, lo + (to - from));
        from += hi - lo;
        const double* v = c.v.data();
        auto raw = [&](size_t i) {
            mn = std::min(mn, v[i]);
            mx = std::max(mx, v[i]);
            if constexpr (WithBits) {
                const uint64_t b = bitsOf(v[i]);
                andBits &= b;
                orBits |= b;
            }
        };
        auto block = [&](int k, size_t j) {
            const MinMax& m = c.level[k][j];
            mn = std::min(mn, m.min);
            mx = std::max(mx, m.max);
            if constexpr (WithBits) {
                andBits &= c.bits[k][j].andBits;
                orBits |= c.bits[k][j].orBits;
            }
        };
        // Up the pyramid: single samples, then ever larger blocks, until lo sits on the largest
        // block boundary that fits; then down again: the largest whole blocks first.
        while (lo < hi && lo % kBlock[0] != 0) raw(lo++);
        for (int k = 0; k + 1 < kLevels; ++k)
            while (lo + kBlock[k] <= hi && lo % kBlock[k + 1] != 0) {
                block(k, lo / kBlock[k]);
                lo += kBlock[k];
            }
        for (int k = kLevels - 1; k >= 0; --k)
            while (lo + kBlock[k] <= hi) {
                block(k, lo / kBlock[k]);
                lo += kBlock[k];
            }
        while (lo < hi) raw(lo++);
    }
    return {mn, mx, andBits, orBits};
}

void SignalBuffer::prefetchLocked(size_t r, size_t span) const {
    // The memory a column edge near sample r will read (its time, the raw values either side,
    // the blocks of the levels a column of `span` samples climbs), requested ahead so the
    // reads of several columns overlap instead of waiting one after the other.
    const size_t k = r / kChunkSize;
    if (k >= chunks_.size()) return;
    const Chunk& c = *chunks_[k];
    const size_t i = r % kChunkSize;
    if (i >= c.size()) return;
    __builtin_prefetch(c.t.data() + i);
    for (size_t j = i >= 16 ? i - 16 : 0; j < i + 16 && j < c.size(); j += 8) __builtin_prefetch(c.v.data() + j);
    for (int lv = 0; lv + 1 < kLevels && kBlock[lv] * 2 <= span; ++lv) {
        const size_t first = (i / kBlock[lv + 1]) * kFanout;  // the blocks of this level sharing r's parent
        const MinMax* base = c.level[lv].data();
        const size_t n = c.level[lv].size();
        for (size_t j = first; j < first + kFanout && j < n; j += 4) __builtin_prefetch(base + j);
    }
}

std::vector<SignalSample> SignalBuffer::samplesLocked(size_t from, size_t to) const {
    std::vector<SignalSample> out;
    out.reserve(to - from);
    for (size_t r = from; r < to; ++r) out.push_back(sampleLocked(r));
    return out;
}

std::optional<SignalSample> SignalBuffer::first() const {
    std::lock_guard lock(mutex_);
    if (!history_.empty()) return history_.first();
    if (!countLocked()) return std::nullopt;
    return sampleLocked(0);
}

std::optional<SignalSample> SignalBuffer::last() const {
    std::lock_guard lock(mutex_);
    const size_t n = countLocked();
    if (!n) return std::nullopt;
    return sampleLocked(n - 1);
}

std::optional<SignalSample> SignalBuffer::at(int64_t timeNs) const {
    std::lock_guard lock(mutex_);
    const size_t n = countLocked();
    if (int64_t end = 0; historyPartLocked(timeNs, timeNs, &end)) return history_.at(timeNs);
    if (!n) return std::nullopt;
    const size_t i = lowerBoundLocked(timeNs + 1);  // first sample after t
    return sampleLocked(i == 0 ? 0 : i - 1);
}

std::optional<SignalSample> SignalBuffer::nearest(int64_t timeNs) const {
    std::lock_guard lock(mutex_);
    const size_t n = countLocked();
    if (int64_t end = 0; historyPartLocked(timeNs, timeNs, &end)) {
        const auto h = history_.nearest(timeNs);
        if (!n) return h;
        const SignalSample d = sampleLocked(0);
        return h && timeNs - h->timeNs <= d.timeNs - timeNs ? *h : d;
    }
    if (!n) return std::nullopt;
    const size_t i = lowerBoundLocked(timeNs);
    if (i == 0) return sampleLocked(0);
    if (i >= n) return sampleLocked(n - 1);
    const SignalSample a = sampleLocked(i - 1), b = sampleLocked(i);
    return (timeNs - a.timeNs) <= (b.timeNs - timeNs) ? a : b;
}

std::vector<SignalSample> SignalBuffer::samples(int64_t t0, int64_t t1) const {
    std::lock_guard lock(mutex_);
    if (t1 < t0) return {};
    std::vector<SignalSample> out;
    if (int64_t end = 0; historyPartLocked(t0, t1, &end)) history_.samples(t0, end, out);
    if (!countLocked()) return out;
    std::vector<SignalSample> detail =
        samplesLocked(lowerBoundLocked(t0), lowerBoundLocked(t1 == INT64_MAX ? t1 : t1 + 1));
    if (out.empty()) return detail;
    out.insert(out.end(), detail.begin(), detail.end());
    return out;
}

SignalRange SignalBuffer::range(int64_t t0, int64_t t1, int bit) const {
    std::lock_guard lock(mutex_);
    SignalRange old;
    if (int64_t end = 0; historyPartLocked(t0, t1, &end)) old = history_.range(t0, end, bit);
    const SignalRange recent = rangeLocked(t0, t1, bit);
    if (!old.valid) return recent;
    if (!recent.valid) return old;
    return {std::min(old.min, recent.min), std::max(old.max, recent.max), true};
}

SignalRange SignalBuffer::rangeLocked(int64_t t0, int64_t t1, int bit) const {
    if (!countLocked()) return {};
    const size_t from = lowerBoundLocked(t0), to = lowerBoundLocked(t1 == INT64_MAX ? t1 : t1 + 1);
    if (from >= to) return {};
    if (bit >= 0 && bit < 64) {
        const Summary s = reduceLocked<true>(from, to);
        return {double((s.andBits >> bit) & 1), double((s.orBits >> bit) & 1), true};
    }
    const Summary s = reduceLocked<false>(from, to);
    return {s.min, s.max, true};
}

std::vector<SignalPoint> SignalBuffer::decimate(int64_t t0, int64_t t1, int buckets, int bit) const {
    std::vector<SignalPoint> out;
    std::lock_guard lock(mutex_);
    if (t1 < t0) return out;
    if (int64_t end = 0; historyPartLocked(t0, t1, &end)) {
        const int share = historyColumns(t0, t1, end, buckets);
        history_.points(t0, end, share, bit, true, out);
        if (end >= t1 || !countLocked()) return out;
        t0 = end + 1;
        buckets = std::max(1, buckets - share);
    }
    if (!countLocked()) return out;
    decimateLocked(lowerBoundLocked(t0), lowerBoundLocked(t1 == INT64_MAX ? t1 : t1 + 1), t0, t1, buckets, bit, out);
    return out;
}

void SignalBuffer::decimateLocked(size_t from, size_t to, int64_t t0, int64_t t1, int buckets, int bit,
                                  std::vector<SignalPoint>& out) const {
    const size_t n = countLocked();
    buckets = std::max(1, buckets);
    auto valueOf = [bit](double v) { return bit >= 0 && bit < 64 ? double((bitsOf(v) >> bit) & 1) : v; };
    auto push = [&](size_t r) {
        const SignalSample s = sampleLocked(r);
        out.push_back({s.timeNs, valueOf(s.value)});
    };
    const size_t lo = from > 0 ? from - 1 : from;  // one before the window
    const size_t hi = to < n ? to + 1 : to;        // one after it
    if (to - from <= size_t(2) * size_t(buckets)) {
        out.reserve(out.size() + (hi - lo));
        for (size_t r = lo; r < hi; ++r) push(r);
        return;
    }
    out.reserve(out.size() + size_t(2) * size_t(buckets) + 2);
    if (lo < from) push(lo);
    const double span = double(t1) - double(t0);
    size_t start = from;
    size_t lastCount = (to - from) / size_t(buckets);
    const bool bits = bit >= 0 && bit < 64;
    constexpr int kAhead = 3;  // columns whose memory is requested ahead
    for (int b = 0; b < buckets && start < to; ++b) {
        if (lastCount >= 16)
            if (const size_t ahead = start + size_t(kAhead) * lastCount; ahead < to) prefetchLocked(ahead, lastCount);
        size_t end = to;
        if (b + 1 < buckets) {
            const auto edge = static_cast<int64_t>(double(t0) + span * double(b + 1) / double(buckets));
            end = std::min(lowerBoundNearLocked(edge, start + lastCount, start, to), to);
        }
        if (end == start) continue;
        lastCount = end - start;
        const SignalPoint a = pointLocked(start), z = pointLocked(end - 1);
        if (end - start <= 2) {
            out.push_back({a.timeNs, valueOf(a.value)});
            if (end - start == 2) out.push_back({z.timeNs, valueOf(z.value)});
        } else {
            const Summary s = bits ? reduceLocked<true>(start, end) : reduceLocked<false>(start, end);
            double mn = s.min, mx = s.max;
            if (bits) {
                mn = double((s.andBits >> bit) & 1);
                mx = double((s.orBits >> bit) & 1);
            }
            // Rising stretch: min first; falling: max first.
            const bool rising = valueOf(z.value) >= valueOf(a.value);
            out.push_back({a.timeNs, rising ? mn : mx});
            out.push_back({z.timeNs, rising ? mx : mn});
        }
        start = end;
    }
    if (hi > to) push(to);
}

void SignalBuffer::envelope(int64_t t0, int64_t t1, int columns, std::vector<SignalPoint>& out) const {
    out.clear();
    std::lock_guard lock(mutex_);
    const size_t n = countLocked();
    if (t1 < t0) return;
    columns = std::max(1, columns);
    if (int64_t end = 0; historyPartLocked(t0, t1, &end)) {
        const int share = historyColumns(t0, t1, end, columns);
        history_.points(t0, end, share, -1, true, out);
        if (end >= t1 || !n) return;
        t0 = end + 1;
        columns = std::max(1, columns - share);
    }
    if (!n) return;
    const size_t from = lowerBoundLocked(t0), to = lowerBoundLocked(t1 == INT64_MAX ? t1 : t1 + 1);
    // The right level, chosen once: the largest whose blocks are at most a quarter column.
    const size_t perColumn = (to - from) / size_t(columns);
    int level = kEdgeLevels - 1;
    while (level >= 0 && kEdgeBlock[level] * kEdgeBlocksPerColumn > perColumn) --level;
    if (level < 0) {  // zoomed in: few samples a column, the exact edges cost little
        decimateLocked(from, to, t0, t1, columns, -1, out);
        return;
    }
    const size_t block = kEdgeBlock[level];
    out.reserve(size_t(2) * size_t(columns) + 2);
    if (from > 0) out.push_back(pointLocked(from - 1));
    // One column at a time: the blocks whose first sample falls in it (the window's partial
    // first and last block exactly, from the pyramid).
    const double scale = double(columns) / std::max(1.0, double(t1) - double(t0));
    int column = -1;
    Edge acc{};
    int64_t lastTime = 0;
    size_t count = 0;
    auto flush = [&] {
        if (column < 0) return;
        if (count <= 2) {
            out.push_back({acc.t, acc.first});
            if (count == 2) out.push_back({lastTime, acc.last});
            return;
        }
        const bool rising = acc.last >= acc.first;  // min first when rising, as decimate()
        out.push_back({acc.t, rising ? acc.min : acc.max});
        out.push_back({lastTime, rising ? acc.max : acc.min});
    };
    // tLast: where the column's last point goes (a whole block's first time: inside the column).
    auto add = [&](const Edge& e, size_t samples, int64_t tLast) {
        const int c = std::clamp(static_cast<int>((double(e.t) - double(t0)) * scale), 0, columns - 1);
        if (c != column) {
            flush();
            column = c;
            acc = e;
            count = 0;
        } else {
            acc.last = e.last;
            acc.min = std::min(acc.min, e.min);
            acc.max = std::max(acc.max, e.max);
        }
        lastTime = tLast;
        count += samples;
    };
    auto exact = [&](size_t lo, size_t hi) {  // [lo, hi) within one block
        const Summary s = reduceLocked<false>(lo, hi);
        const SignalPoint a = pointLocked(lo), z = pointLocked(hi - 1);
        add(Edge{a.timeNs, a.value, z.value, s.min, s.max}, hi - lo, z.timeNs);
    };
    size_t r = from;
    const size_t headEnd = std::min(to, (from + block - 1) / block * block);
    if (r < headEnd) exact(r, headEnd), r = headEnd;
    const size_t bodyEnd = std::max(r, to / block * block);
    while (r < bodyEnd) {  // whole blocks, read in order chunk by chunk
        const Chunk& c = *chunks_[r / kChunkSize];
        const size_t chunkEnd = std::min(bodyEnd, (r / kChunkSize + 1) * kChunkSize);
        const Edge* e = c.edge[level].data() + (r % kChunkSize) / block;
        for (; r < chunkEnd; r += block, ++e) add(*e, block, e->t);
    }
    if (r < to) exact(r, to);
    flush();
    if (to < n) out.push_back(pointLocked(to));
}

}  // namespace coscope
