// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/trace/SignalHistory.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace coscope {

namespace {
uint64_t bitsOfValue(double v) {
    if (!std::isfinite(v)) return 0;
    if (v >= 0 && v >= 9.2e18) return static_cast<uint64_t>(v);
    return static_cast<uint64_t>(static_cast<int64_t>(v));
}
double bitOf(uint64_t bits, int bit) { return double((bits >> bit) & 1); }
bool isBit(int bit) { return bit >= 0 && bit < 64; }
}  // namespace

void SignalHistory::merge(Bucket& into, const Bucket& next) {
    if (next.count == 0) return;
    if (into.count == 0) {
        into = next;
        return;
    }
    if (next.min < into.min) into.min = next.min, into.tMin = next.tMin;
    if (next.max > into.max) into.max = next.max, into.tMax = next.tMax;
    into.andBits &= next.andBits;
    into.orBits |= next.orBits;
    into.tLast = next.tLast;
    into.last = next.last;
    into.frameLast = next.frameLast;
    into.count += next.count;
}

void SignalHistory::add(int64_t timeNs, double value, FrameNo frame) {
    // Taken at once and touched: the resident memory does not creep up as the buckets fill.
    if (store_.empty()) store_.resize(kBuckets);
    const uint64_t b = bitsOfValue(value);
    merge(open_, Bucket{timeNs, timeNs, timeNs, timeNs, value, value, value, value, b, b, frame, frame, 1});
    ++samples_;
    if (open_.count < perBucket_) return;
    if (used_ == store_.size()) halve();
    store_[used_++] = open_;
    open_ = Bucket{};
}

void SignalHistory::halve() {
    size_t j = 0;
    for (size_t i = 0; i + 1 < used_; i += 2, ++j) {
        Bucket m = store_[i];
        merge(m, store_[i + 1]);
        store_[j] = m;
    }
    if (used_ % 2) store_[j++] = store_[used_ - 1];
    used_ = j;
    perBucket_ *= 2;
}

void SignalHistory::clear() {
    used_ = 0;
    open_ = Bucket{};
    perBucket_ = kFirstSamplesPerBucket;
    samples_ = 0;
}

int64_t SignalHistory::lastTime() const {
    if (open_.count) return open_.tLast;
    return used_ ? store_[used_ - 1].tLast : 0;
}

size_t SignalHistory::lowerBound(int64_t timeNs) const {
    const auto it = std::lower_bound(store_.begin(), store_.begin() + static_cast<std::ptrdiff_t>(used_), timeNs,
                                     [](const Bucket& b, int64_t t) { return b.tLast < t; });
    const auto i = static_cast<size_t>(it - store_.begin());
    if (i < used_) return i;
    return open_.count && open_.tLast >= timeNs ? used_ : buckets();
}

std::optional<SignalSample> SignalHistory::first() const {
    if (empty()) return std::nullopt;
    const Bucket& b = bucket(0);
    return SignalSample{b.tFirst, b.first, b.frameFirst};
}

std::optional<SignalSample> SignalHistory::at(int64_t timeNs) const {
    if (empty()) return std::nullopt;
    const size_t i = lowerBound(timeNs);
    if (i >= buckets()) {
        const Bucket& b = bucket(buckets() - 1);
        return SignalSample{b.tLast, b.last, b.frameLast};
    }
    const Bucket& b = bucket(i);
    if (timeNs >= b.tFirst || i == 0) return SignalSample{b.tFirst, b.first, b.frameFirst};
    const Bucket& p = bucket(i - 1);
    return SignalSample{p.tLast, p.last, p.frameLast};
}

std::optional<SignalSample> SignalHistory::nearest(int64_t timeNs) const {
    if (empty()) return std::nullopt;
    const size_t i = lowerBound(timeNs);
    if (i >= buckets()) {
        const Bucket& b = bucket(buckets() - 1);
        return SignalSample{b.tLast, b.last, b.frameLast};
    }
    const Bucket& b = bucket(i);
    SignalSample best{b.tFirst, b.first, b.frameFirst};
    if (timeNs >= b.tFirst && b.tLast - timeNs < timeNs - b.tFirst) best = {b.tLast, b.last, b.frameLast};
    if (timeNs < b.tFirst && i > 0) {
        const Bucket& p = bucket(i - 1);
        if (timeNs - p.tLast < b.tFirst - timeNs) best = {p.tLast, p.last, p.frameLast};
    }
    return best;
}

void SignalHistory::samples(int64_t t0, int64_t t1, std::vector<SignalSample>& out) const {
    for (size_t i = lowerBound(t0); i < buckets(); ++i) {
        const Bucket& b = bucket(i);
        if (b.tFirst > t1) break;
        if (b.tFirst >= t0) out.push_back({b.tFirst, b.first, b.frameFirst});
        if (b.count > 1 && b.tLast <= t1) out.push_back({b.tLast, b.last, b.frameLast});
    }
}

SignalRange SignalHistory::range(int64_t t0, int64_t t1, int bit) const {
    SignalRange r;
    r.min = std::numeric_limits<double>::infinity();
    r.max = -std::numeric_limits<double>::infinity();
    uint64_t andBits = ~uint64_t(0), orBits = 0;
    for (size_t i = lowerBound(t0); i < buckets(); ++i) {
        const Bucket& b = bucket(i);
        if (b.tFirst > t1) break;
        r.valid = true;
        r.min = std::min(r.min, b.min);
        r.max = std::max(r.max, b.max);
        andBits &= b.andBits;
        orBits |= b.orBits;
    }
    if (!r.valid) return {};
    if (isBit(bit)) r = {bitOf(andBits, bit), bitOf(orBits, bit), true};
    return r;
}

void SignalHistory::points(int64_t t0, int64_t t1, int columns, int bit, bool withBefore,
                           std::vector<SignalPoint>& out) const {
    if (empty() || t1 < t0) return;
    columns = std::max(1, columns);
    const bool bits = isBit(bit);
    auto value = [&](double v) { return bits ? bitOf(bitsOfValue(v), bit) : v; };
    size_t i = lowerBound(t0);
    if (withBefore && i > 0 && i <= buckets()) {
        const Bucket& p = bucket(i - 1);
        out.push_back({p.tLast, value(p.last)});
    }
    const double scale = double(columns) / std::max(1.0, double(t1) - double(t0));
    auto columnOf = [&](int64_t t) { return std::clamp(int((double(t) - double(t0)) * scale), 0, columns - 1); };
    // Per column the buckets in it merged: its extremes, in the order they occurred.
    auto put = [&](const Bucket& c) {
        if (c.count == 1) {
            out.push_back({c.tFirst, value(c.first)});
            return;
        }
        if (bits) {
            const double lo = bitOf(c.andBits, bit), hi = bitOf(c.orBits, bit);
            const bool rising = value(c.last) >= value(c.first);
            out.push_back({c.tFirst, rising ? lo : hi});
            out.push_back({c.tLast, rising ? hi : lo});
            return;
        }
        // Two points a column, as SignalBuffer::envelope(): the extremes in the order they came.
        if (c.tMin <= c.tMax) {
            out.push_back({c.tMin, c.min});
            out.push_back({c.tMax, c.max});
        } else {
            out.push_back({c.tMax, c.max});
            out.push_back({c.tMin, c.min});
        }
    };
    Bucket acc;
    int column = -1;
    for (; i < buckets(); ++i) {
        const Bucket& b = bucket(i);
        if (b.tFirst > t1) {
            if (acc.count) put(acc);
            out.push_back({b.tFirst, value(b.first)});  // the line reaches the window's end
            return;
        }
        const int c = columnOf(b.tFirst);
        if (c != column && acc.count) {
            put(acc);
            acc = Bucket{};
        }
        column = c;
        merge(acc, b);
    }
    if (acc.count) put(acc);
}

}  // namespace coscope
