// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 38 (a day-long capture in bounded memory): a signal's buffer holds a bounded number of
// samples one by one, and what left it stays in view, decimated (SignalHistory): after many times
// its capacity the buffer's memory has stopped growing, while its first sample, a spike long
// gone from the detail, the extremes of a bit and the plot's envelope of the whole signal are
// still there.
#include "core/trace/SignalBuffer.h"
#include "core/trace/SignalHistory.h"

#include <QtTest>

#include <algorithm>

using namespace coscope;

class TestSignalHistory : public QObject {
    Q_OBJECT
private slots:
    void historyHasFixedSizeAndKeepsExtremes() {
        SignalHistory h;
        const size_t n = SignalHistory::kBuckets * SignalHistory::kFirstSamplesPerBucket * 5 + 333;
        size_t memory = 0;
        for (size_t i = 0; i < n; ++i) {
            h.add(int64_t(i) * 1000, i == 12345 ? 1e6 : double(i % 100), FrameNo(i));
            if (i == 0) memory = h.memoryBytes();
        }
        QVERIFY(h.buckets() <= SignalHistory::kBuckets + 1);
        QVERIFY(h.samplesPerBucket() >= 5 * SignalHistory::kFirstSamplesPerBucket);
        QCOMPARE(h.memoryBytes(), memory);  // taken once
        QCOMPARE(h.samples(), uint64_t(n));
        QCOMPARE(h.first()->timeNs, int64_t(0));
        QCOMPARE(h.first()->frame, FrameNo(0));
        const SignalRange all = h.range(0, int64_t(n) * 1000, -1);
        QVERIFY(all.valid);
        QCOMPARE(all.min, 0.0);
        QCOMPARE(all.max, 1e6);
        const SignalRange late = h.range(int64_t(n / 2) * 1000, int64_t(n) * 1000, -1);
        QCOMPARE(late.max, 99.0);
        QCOMPARE(h.at(int64_t(n - 1) * 1000 + 5)->frame, FrameNo(n - 1));
    }

    void bufferStaysBoundedAndShowsTheWholeSignal() {
        SignalBuffer buf(2 * SignalBuffer::kChunkSize);
        const size_t n = 40 * SignalBuffer::kChunkSize + 999;
        std::vector<SignalSample> batch;
        for (size_t i = 0; i < n; ++i) {
            // A sawtooth 0..999, a spike of 6144 (bits 11 and 12) at sample 1000, bit 12 set only there.
            const double v = i == 1000 ? 6144.0 : double(i % 1000);
            batch.push_back({int64_t(i) * 1'000'000, v, FrameNo(i)});
            if (batch.size() == 4096 || i + 1 == n) {
                buf.append(batch);
                batch.clear();
            }
        }
        // Bounded: at most the capacity, the chunk filling and the history.
        QVERIFY2(buf.size() <= 3 * SignalBuffer::kChunkSize, qPrintable(QString::number(buf.size())));
        QVERIFY(buf.historyBuckets() <= SignalHistory::kBuckets + 1);
        QCOMPARE(buf.appended(), uint64_t(n));
        QCOMPARE(buf.dropped() + buf.size(), uint64_t(n));
        // Still the whole signal.
        QCOMPARE(buf.first()->timeNs, int64_t(0));
        QCOMPARE(buf.last()->frame, FrameNo(n - 1));
        const int64_t end = int64_t(n) * 1'000'000;
        const SignalRange r = buf.range(0, end, -1);
        QVERIFY(r.valid);
        QCOMPARE(r.max, 6144.0);
        QCOMPARE(r.min, 0.0);
        QCOMPARE(buf.range(0, end, 12).max, 1.0);  // the one sample with bit 12
        QCOMPARE(buf.range(int64_t(n / 2) * 1'000'000, end, 12).max, 0.0);
        std::vector<SignalPoint> drawn;
        buf.envelope(0, end, 800, drawn);
        QVERIFY(!drawn.empty() && drawn.size() <= 4 * 800 + 4);
        QVERIFY(std::any_of(drawn.begin(), drawn.end(), [](const SignalPoint& p) { return p.value == 6144.0; }));
        QVERIFY(std::is_sorted(drawn.begin(), drawn.end(),
                               [](const SignalPoint& a, const SignalPoint& b) { return a.timeNs < b.timeNs; }));
        QCOMPARE(drawn.front().timeNs, int64_t(0));
        const auto decimated = buf.decimate(0, end, 500, -1);
        QVERIFY(
            std::any_of(decimated.begin(), decimated.end(), [](const SignalPoint& p) { return p.value == 6144.0; }));
        // A cursor in the old part reads a value from there, the recent part reads exact samples.
        const auto old = buf.at(int64_t(5 * SignalBuffer::kChunkSize) * 1'000'000);
        QVERIFY(old && old->timeNs <= int64_t(5 * SignalBuffer::kChunkSize) * 1'000'000);
        QVERIFY(old->timeNs > int64_t(4 * SignalBuffer::kChunkSize) * 1'000'000);
        const auto recent = buf.at(end - 1'000'000);
        QCOMPARE(recent->frame, FrameNo(n - 1));
        QVERIFY(!buf.samples(0, int64_t(3 * SignalBuffer::kChunkSize) * 1'000'000).empty());

        // Memory stops growing: as much again leaves the detail and the history within their bounds.
        for (size_t i = n; i < 2 * n; ++i) buf.append({int64_t(i) * 1'000'000, double(i % 1000), FrameNo(i)});
        QVERIFY(buf.size() <= 3 * SignalBuffer::kChunkSize);
        QVERIFY(buf.historyBuckets() <= SignalHistory::kBuckets + 1);
        QCOMPARE(buf.range(0, 2 * end, -1).max, 6144.0);
    }
};

QTEST_GUILESS_MAIN(TestSignalHistory)
#include "test_signal_history.moc"
