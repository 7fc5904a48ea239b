// SPDX-License-Identifier: GPL-3.0-or-later
// SignalBuffer's min/max pyramid against a plain scan over the same samples: random values and
// times, appended in random batches (the pyramid grows while it is queried), random zoom windows
// and pixel widths. Every pixel column of decimate() must carry exactly the min and max of the
// samples whose time falls in it; range() the extremes of the window (and of one bit). envelope()
// (what the plot draws) may count a sample in the neighbouring column, never lose or invent one.
#include "core/trace/SignalBuffer.h"

#include <QtTest>

#include <algorithm>
#include <random>

using namespace coscope;

namespace {

uint64_t bitsOf(double v) { return static_cast<uint64_t>(static_cast<int64_t>(v)); }

// What decimate() promises, computed by scanning every sample.
std::vector<SignalPoint> plainDecimate(const std::vector<SignalSample>& all, int64_t t0, int64_t t1, int buckets,
                                       int bit) {
    std::vector<SignalPoint> out;
    auto valueOf = [bit](double v) { return bit >= 0 ? double((bitsOf(v) >> bit) & 1) : v; };
    auto lower = [&](int64_t t) {
        return static_cast<size_t>(
            std::lower_bound(all.begin(), all.end(), t, [](const SignalSample& s, int64_t x) { return s.timeNs < x; }) -
            all.begin());
    };
    const size_t from = lower(t0), to = lower(t1 + 1);
    const size_t lo = from > 0 ? from - 1 : from, hi = to < all.size() ? to + 1 : to;
    if (to - from <= size_t(2) * size_t(buckets)) {
        for (size_t i = lo; i < hi; ++i) out.push_back({all[i].timeNs, valueOf(all[i].value)});
        return out;
    }
    if (lo < from) out.push_back({all[lo].timeNs, valueOf(all[lo].value)});
    const double span = double(t1) - double(t0);
    size_t i = from;
    for (int b = 0; b < buckets; ++b) {
        // Pixel column b: t0 + span * b / buckets <= time < t0 + span * (b + 1) / buckets.
        const int64_t left = b == 0 ? t0 : static_cast<int64_t>(double(t0) + span * double(b) / double(buckets));
        const int64_t right =
            b + 1 == buckets ? t1 + 1 : static_cast<int64_t>(double(t0) + span * double(b + 1) / double(buckets));
        std::vector<SignalSample> col;
        for (; i < to && all[i].timeNs < right; ++i)
            if (all[i].timeNs >= left) col.push_back(all[i]);
        if (col.empty()) continue;
        if (col.size() <= 2) {
            for (const SignalSample& s : col) out.push_back({s.timeNs, valueOf(s.value)});
            continue;
        }
        double mn = valueOf(col.front().value), mx = mn;
        for (const SignalSample& s : col) {
            mn = std::min(mn, valueOf(s.value));
            mx = std::max(mx, valueOf(s.value));
        }
        const bool rising = valueOf(col.back().value) >= valueOf(col.front().value);
        out.push_back({col.front().timeNs, rising ? mn : mx});
        out.push_back({col.back().timeNs, rising ? mx : mn});
    }
    if (hi > to) out.push_back({all[to].timeNs, valueOf(all[to].value)});
    return out;
}

QByteArray describe(const std::vector<SignalPoint>& got, const std::vector<SignalPoint>& want) {
    size_t i = 0;
    while (i < got.size() && i < want.size() && got[i].timeNs == want[i].timeNs && got[i].value == want[i].value) ++i;
    QByteArray s = "sizes " + QByteArray::number(qulonglong(got.size())) + "/" +
                   QByteArray::number(qulonglong(want.size())) + ", first difference at " +
                   QByteArray::number(qulonglong(i));
    if (i < got.size() && i < want.size())
        s += ": got (" + QByteArray::number(qlonglong(got[i].timeNs)) + ", " + QByteArray::number(got[i].value) +
             ") want (" + QByteArray::number(qlonglong(want[i].timeNs)) + ", " + QByteArray::number(want[i].value) +
             ")";
    return s;
}

}  // namespace

class TestSignalPyramid : public QObject {
    Q_OBJECT
private slots:
    // Random data over several chunks, queried while it grows: decimate() and range() equal a
    // plain scan for random windows (inside, across and beyond the data) and widths.
    void pyramidEqualsPlainScan() {
        std::mt19937_64 rng(20261125);
        SignalBuffer buf(8 * SignalBuffer::kChunkSize);  // no history: the pyramid itself
        std::vector<SignalSample> all;
        int64_t t = 1'000'000;
        int checks = 0;
        while (all.size() < 3 * SignalBuffer::kChunkSize + 12345) {
            std::vector<SignalSample> batch(1 + rng() % 20000);
            for (SignalSample& s : batch) {
                t += static_cast<int64_t>(rng() % 1000);  // equal times happen too
                // Mostly a noisy wave, with rare spikes a block summary must not lose.
                double v = double(int64_t(rng() % 2001) - 1000);
                if (rng() % 5000 == 0) v = double(int64_t(rng() % 2'000'001) - 1'000'000);
                s = {t, v, static_cast<FrameNo>(all.size())};
                all.push_back(s);
            }
            buf.append(batch);
            for (int q = 0; q < 25; ++q, ++checks) {
                const int64_t first = all.front().timeNs, last = all.back().timeNs, span = last - first + 1;
                int64_t t0 = first - span / 20 + static_cast<int64_t>(rng() % uint64_t(span + span / 10));
                int64_t len =
                    q % 3 == 0 ? static_cast<int64_t>(rng() % 5000) : static_cast<int64_t>(rng() % uint64_t(span));
                if (q == 0) t0 = first, len = last - first;  // the whole history
                const int64_t t1 = t0 + len;
                const int buckets = 1 + static_cast<int>(rng() % 1500);
                const int bit = q % 4 == 1 ? static_cast<int>(rng() % 12) : -1;
                const auto got = buf.decimate(t0, t1, buckets, bit);
                const auto want = plainDecimate(all, t0, t1, buckets, bit);
                const bool same =
                    got.size() == want.size() &&
                    std::equal(got.begin(), got.end(), want.begin(), [](const SignalPoint& a, const SignalPoint& b) {
                        return a.timeNs == b.timeNs && a.value == b.value;
                    });
                QVERIFY2(same, "decimate [" + QByteArray::number(qlonglong(t0)) + ", " +
                                   QByteArray::number(qlonglong(t1)) + "] in " + QByteArray::number(buckets) +
                                   " columns, bit " + QByteArray::number(bit) + ": " + describe(got, want));

                double mn = 0, mx = 0, bmn = 1, bmx = 0;
                bool any = false;
                for (const SignalSample& s : all) {
                    if (s.timeNs < t0) continue;
                    if (s.timeNs > t1) break;
                    const double b = double((bitsOf(s.value) >> 3) & 1);
                    mn = any ? std::min(mn, s.value) : s.value;
                    mx = any ? std::max(mx, s.value) : s.value;
                    bmn = std::min(bmn, b);
                    bmx = std::max(bmx, b);
                    any = true;
                }
                const SignalRange r = buf.range(t0, t1);
                QCOMPARE(r.valid, any);
                if (any) {
                    QCOMPARE(r.min, mn);
                    QCOMPARE(r.max, mx);
                    const SignalRange rb = buf.range(t0, t1, 3);
                    QCOMPARE(rb.min, bmn);
                    QCOMPARE(rb.max, bmx);
                }
            }
        }
        QVERIFY(checks > 100);
    }

    // One sample at a time: every partly filled block of every level is read while it grows.
    void growingBlocksAreExact() {
        std::mt19937_64 rng(7);
        SignalBuffer buf(8 * SignalBuffer::kChunkSize);  // no history: the pyramid itself
        std::vector<SignalSample> all;
        for (int i = 0; i < 5000; ++i) {
            const SignalSample s{int64_t(i) * 10, double(int64_t(rng() % 200) - 100), FrameNo(i)};
            all.push_back(s);
            buf.append(s);
            const int64_t t0 = static_cast<int64_t>(rng() % uint64_t(i + 1)) * 10;
            const auto got = buf.decimate(t0, s.timeNs, 7, -1);
            const auto want = plainDecimate(all, t0, s.timeNs, 7, -1);
            QVERIFY2(got.size() == want.size() && std::equal(got.begin(), got.end(), want.begin(),
                                                             [](const SignalPoint& a, const SignalPoint& b) {
                                                                 return a.timeNs == b.timeNs && a.value == b.value;
                                                             }),
                     "after sample " + QByteArray::number(i) + ": " + describe(got, want));
        }
    }
    // The plot's envelope against a plain scan: each drawn column's extremes are samples of that
    // column or a neighbour, and every sample lies within the extremes drawn in its column or a
    // neighbour (spikes are never lost). Zoomed in (under 64 samples a column) it is decimate().
    void envelopeKeepsEverySample() {
        std::mt19937_64 rng(20261126);
        SignalBuffer buf(8 * SignalBuffer::kChunkSize);  // no history: the pyramid itself
        std::vector<SignalSample> all;
        int64_t t = 0;
        while (all.size() < 5 * SignalBuffer::kChunkSize + 777) {
            t += 500 + static_cast<int64_t>(rng() % 1000);
            double v = double(int64_t(rng() % 2001) - 1000);
            if (rng() % 3000 == 0) v = double(int64_t(rng() % 2'000'001) - 1'000'000);
            all.push_back({t, v, static_cast<FrameNo>(all.size())});
        }
        buf.append(all);
        std::vector<SignalPoint> got;
        int snapped = 0;
        for (int q = 0; q < 60; ++q) {
            const int64_t first = all.front().timeNs, span = all.back().timeNs - first;
            const int64_t len = q == 0 ? span : static_cast<int64_t>(rng() % uint64_t(span));
            const int64_t t0 = q == 0 ? first : first - span / 20 + static_cast<int64_t>(rng() % uint64_t(span));
            const int64_t t1 = t0 + len;
            const int columns = 50 + static_cast<int>(rng() % 1500);
            buf.envelope(t0, t1, columns, got);
            const auto exact = plainDecimate(all, t0, t1, columns, -1);
            struct Span {
                double min = 0, max = 0;
                bool any = false;
                void add(double v) { min = any ? std::min(min, v) : v, max = any ? std::max(max, v) : v, any = true; }
            };
            const double scale = double(columns) / double(std::max<int64_t>(1, t1 - t0));
            auto columnOf = [&](int64_t time) {
                return std::clamp(static_cast<int>((double(time) - double(t0)) * scale), 0, columns - 1);
            };
            std::vector<Span> drawn(size_t(columns) + 2), plain(size_t(columns) + 2);  // index column + 1
            for (const SignalPoint& p : got)
                if (p.timeNs >= t0 && p.timeNs <= t1) drawn[size_t(columnOf(p.timeNs)) + 1].add(p.value);
            size_t inWindow = 0;
            for (const SignalSample& s : all)
                if (s.timeNs >= t0 && s.timeNs <= t1) plain[size_t(columnOf(s.timeNs)) + 1].add(s.value), ++inWindow;
            const QByteArray where = "[" + QByteArray::number(qlonglong(t0)) + ", " +
                                     QByteArray::number(qlonglong(t1)) + "] in " + QByteArray::number(columns) +
                                     " columns";
            if (inWindow < size_t(64) * size_t(columns)) {
                QVERIFY2(got.size() == exact.size() && std::equal(got.begin(), got.end(), exact.begin(),
                                                                  [](const SignalPoint& a, const SignalPoint& b) {
                                                                      return a.timeNs == b.timeNs && a.value == b.value;
                                                                  }),
                         where + ": " + describe(got, exact));
                continue;
            }
            ++snapped;
            QVERIFY2(got.size() <= size_t(2) * size_t(columns) + 2, where);
            for (size_t c = 1; c <= size_t(columns); ++c) {
                Span near, nearDrawn;
                for (size_t d = c - 1; d <= c + 1; ++d) {
                    if (plain[d].any) near.add(plain[d].min), near.add(plain[d].max);
                    if (drawn[d].any) nearDrawn.add(drawn[d].min), nearDrawn.add(drawn[d].max);
                }
                const QByteArray col = where + ", column " + QByteArray::number(qulonglong(c - 1));
                if (drawn[c].any)
                    QVERIFY2(near.any && drawn[c].min >= near.min && drawn[c].max <= near.max,
                             col + ": drawn beyond the samples");
                if (plain[c].any)
                    QVERIFY2(nearDrawn.any && plain[c].min >= nearDrawn.min && plain[c].max <= nearDrawn.max,
                             col + ": a sample lost");
            }
        }
        QVERIFY(snapped > 20);
    }
};

QTEST_GUILESS_MAIN(TestSignalPyramid)
#include "test_signal_pyramid.moc"
