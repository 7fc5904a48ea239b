// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 38 (a day-long capture in bounded memory): the health analysis of hours of heartbeats
// and SDO transfers holds a bounded number of entries (histograms, and only the heartbeat gaps
// that can be late or lost one by one), and its figures stay right: the late and lost beats
// counted with their frames, the period's extremes and mean, the SDO response times.
#include "core/can/CanFrame.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/NetworkHealth.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::dissect;

class HealthBoundTest : public QObject {
    Q_OBJECT
private slots:
    void hoursOfHeartbeatsAndSdo() {
        NetworkContext ctx;
        ctx.setGenericNames(false);
        Dissection d;
        NetworkHealth h;
        int64_t frame = 0;
        auto at = [&](int64_t us, uint32_t id, std::initializer_list<uint8_t> bytes) {
            CanFrame f = CanFrame::classic(id, bytes);
            f.timestampNs = us * 1000;
            ctx.dissect(f, d, Dissection::Level::Stats);
            h.add(f, d, ctx, frame++);
        };
        // Node 5: a heartbeat every 100 ms (±0.3 ms) for 300,000 beats (over 8 hours), one 170 ms
        // late at beat 100,000 and a 400 ms gap (lost) at 200,000; an SDO read answered after
        // 2 ms between beats, one after 80 ms.
        int64_t t = 0;
        const int beats = 300'000;
        int64_t lateFrame = -1, lostFrame = -1;
        for (int i = 0; i < beats; ++i) {
            if (i == 100'000) t += 70'000, lateFrame = frame;
            if (i == 200'000) t += 300'000, lostFrame = frame;
            at(t, 0x705, {0x05});
            const int64_t rt = i == 150'000 ? 80'000 : 2000;
            at(t + 10'000, 0x605, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
            at(t + 10'000 + rt, 0x585, {0x43, 0x00, 0x10, 0x00, 0x92, 0x01, 0x02, 0x00});
            t += 100'000 + (i % 3 == 0 ? 300 : i % 3 == 1 ? -300 : 0);
        }
        // Two histograms (their buckets up to the longest value's) and a few gaps, where one entry
        // per beat and per response was 600,000.
        QVERIFY2(h.samplesHeld() < 4000, qPrintable(QString::number(h.samplesHeld())));
        const HealthReport r = h.report(&ctx);
        const NodeHealth* n = nullptr;
        for (const NodeHealth& x : r.nodes)
            if (x.node == 5) n = &x;
        QVERIFY(n);
        QCOMPARE(n->beats, uint64_t(beats));
        QCOMPARE(n->late, 1u);
        QCOMPARE(n->timeouts, 1u);
        QVERIFY(qAbs(n->periodMaxMs - 400.0) < 0.5);
        QVERIFY(qAbs(n->periodMinMs - 99.7) < 0.01);
        QVERIFY(qAbs(n->expectedPeriodMs - 100.0) < 2.5);  // the observed median, within its bucket
        QVERIFY(qAbs(n->periodAvgMs - (double(t) / 1e3 - 100.0) / (beats - 1)) < 0.1);
        QCOMPARE(n->lateAt.frames.size(), size_t(1));
        QCOMPARE(n->lateAt.frames[0], uint64_t(lateFrame));
        QCOMPARE(n->lostAt.frames.size(), size_t(1));
        QCOMPARE(n->lostAt.frames[0], uint64_t(lostFrame));
        QCOMPARE(n->sdoResponses, uint64_t(beats));
        QCOMPARE(n->sdoRtMinMs, 2.0);
        QCOMPARE(n->sdoRtMaxMs, 80.0);
        QVERIFY(qAbs(n->sdoRtP99Ms - 2.0) < 0.05);
        QVERIFY(qAbs(n->sdoRtAvgMs - (2.0 * (beats - 1) + 80.0) / beats) < 1e-6);
    }
};

QTEST_GUILESS_MAIN(HealthBoundTest)
#include "test_health_bound.moc"
