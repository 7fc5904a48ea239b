// SPDX-License-Identifier: GPL-3.0-or-later
// The periodic master services on a virtual bus, checked on the frames that reach the bus:
// SYNC per CiA 301 §7.2.5 (counter 1..overflow then 1 again, DLC 0 without a counter, COB-ID of
// 1005h with its 29-bit frame bit), the tool's heartbeat (§7.2.8.3.2: 700h + node-ID, the NMT
// state byte), the PeriodicSender's period, count and remove, the transmit list with several
// periodic rows at once, and listen-only refusing all of them with nothing sent.
#include "SvcTestRig.h"

#include "core/canopen/BusMaster.h"
#include "core/trace/TraceStore.h"

#include <QtTest>

#include <atomic>

using namespace coscope;
using namespace coscope::canopen;
using namespace svctest;

namespace {

constexpr int64_t kMs = 1'000'000;

std::vector<CanFrame> framesOf(Rig& rig, uint32_t id, bool extended = false) {
    std::vector<CanFrame> out;
    for (auto no : rig.session.store()->framesFor(TraceStore::keyOf(id, extended)))
        out.push_back(rig.session.store()->frame(no));
    return out;
}

}  // namespace

class TestSvcMaster : public QObject {
    Q_OBJECT
private slots:
    void syncCounterRunsOneToOverflowThenOne() {
        Rig rig;
        QVERIFY(rig.open());
        SyncProducer sync(*rig.context);
        sync.setPeriodUs(2000);
        QVERIFY(!sync.setCounterOverflow(1));    // reserved (CiA 301 §7.5.2.22)
        QVERIFY(!sync.setCounterOverflow(241));  // reserved
        QVERIFY(sync.setCounterOverflow(3));
        std::atomic<uint64_t> hooked{0};
        sync.setOnEachSync([&](const CanFrame&, uint64_t n) { hooked = n; });
        QString error;
        QVERIFY2(sync.start(&error, 8), qPrintable(error));
        QTRY_VERIFY_WITH_TIMEOUT(!sync.isRunning(), 5000);
        QCOMPARE(sync.sent(), uint64_t(8));
        QCOMPARE(hooked.load(), uint64_t(8));
        QTRY_COMPARE_WITH_TIMEOUT(framesOf(rig, 0x80).size(), size_t(8), 5000);
        std::vector<int> counters;
        for (const CanFrame& f : framesOf(rig, 0x80)) {
            QCOMPARE(f.len, uint8_t(1));
            counters.push_back(f.data[0]);
        }
        QCOMPARE(counters, (std::vector<int>{1, 2, 3, 1, 2, 3, 1, 2}));
        // A new run starts at 1 again.
        QVERIFY(sync.start(&error, 2));
        QTRY_COMPARE_WITH_TIMEOUT(framesOf(rig, 0x80).size(), size_t(10), 5000);
        QCOMPARE(int(framesOf(rig, 0x80)[8].data[0]), 1);
        QCOMPARE(sync.sent(), uint64_t(10));
    }

    void syncWithoutCounterIsEmptyAndCobIdFollows1005h() {
        Rig rig;
        QVERIFY(rig.open());
        SyncProducer sync(*rig.context);
        QCOMPARE(sync.cobId(), 0x80u);
        QCOMPARE(sync.frame(0).len, uint8_t(0));
        QString error;
        QVERIFY(!sync.start(&error));  // period 0
        sync.setPeriodUs(1000);
        QVERIFY(sync.start(&error, 3));
        QTRY_COMPARE_WITH_TIMEOUT(framesOf(rig, 0x80).size(), size_t(3), 5000);
        for (const CanFrame& f : framesOf(rig, 0x80)) QCOMPARE(f.len, uint8_t(0));  // DLC 0 (CiA 301 §7.2.5.2.1)
        // 1005h bit 29 = 29-bit CAN-ID; bits 11..28 without it are refused.
        QVERIFY(!sync.setCobId(0x00001080));
        QCOMPARE(sync.cobId(), 0x80u);
        QVERIFY(sync.setCobId(0x40000081));  // gen bit ignored
        QCOMPARE(sync.frame(0).id, 0x81u);
        QVERIFY(sync.setCobId(0x20000080 | 0x12345000));
        QVERIFY(sync.frame(0).isExtended());
        QVERIFY(sync.start(&error, 2));
        QTRY_COMPARE_WITH_TIMEOUT(framesOf(rig, 0x12345080, true).size(), size_t(2), 5000);
    }

    void heartbeatCarriesNodeIdAndState() {
        Rig rig;
        QVERIFY(rig.open());
        HeartbeatProducer hb(*rig.context);
        QVERIFY(!hb.setNodeId(0));
        QVERIFY(!hb.setNodeId(128));
        QVERIFY(hb.setNodeId(0x7E));
        QVERIFY(!hb.setPeriodMs(0));
        QVERIFY(hb.setPeriodMs(20));
        QString error;
        QVERIFY2(hb.start(&error), qPrintable(error));
        QTRY_VERIFY_WITH_TIMEOUT(framesOf(rig, 0x77E).size() >= 3, 5000);
        for (const CanFrame& f : framesOf(rig, 0x77E)) {
            QCOMPARE(f.len, uint8_t(1));
            QCOMPARE(int(f.data[0]), 0x05);  // operational
        }
        hb.setState(0x7F);
        const size_t before = framesOf(rig, 0x77E).size();
        QTRY_VERIFY_WITH_TIMEOUT(framesOf(rig, 0x77E).size() >= before + 2, 5000);
        QCOMPARE(int(framesOf(rig, 0x77E).back().data[0]), 0x7F);
        hb.stop();
        QVERIFY(!hb.isRunning());
        QVERIFY(hb.sent() >= before + 2);
    }

    void periodicSenderKeepsPeriodCountAndRemove() {
        Rig rig;
        QVERIFY(rig.open());
        PeriodicSender& sender = rig.context->periodic();
        PeriodicSender::Job job;
        job.frame = CanFrame::classic(0x321, {0xAA});
        job.periodNs = 10 * kMs;
        job.count = 20;
        QString error;
        const auto id = sender.add(job, &error);
        QVERIFY2(id, qPrintable(error));
        QTRY_COMPARE_WITH_TIMEOUT(framesOf(rig, 0x321).size(), size_t(20), 5000);
        QTest::qWait(50);
        QCOMPARE(framesOf(rig, 0x321).size(), size_t(20));  // the count ended it
        const auto f = framesOf(rig, 0x321);
        // As the bus saw it (the virtual network stamps frames on its 1 ms tick).
        const double meanMs = double(f.back().timestampNs - f.front().timestampNs) / 19 / 1e6;
        qInfo("mean period on the virtual bus: %.3f ms (skipped %llu)", meanMs,
              static_cast<unsigned long long>(sender.status(id).skipped));
        QVERIFY2(meanMs > 9.5 && meanMs < 10.5 + 10.0 * double(sender.status(id).skipped) / 19,
                 qPrintable(QString::number(meanMs)));

        job.frame = CanFrame::classic(0x322, {});
        job.count = 0;
        job.periodNs = 5 * kMs;
        const auto open = sender.add(job, &error);
        QVERIFY(open);
        QTRY_VERIFY_WITH_TIMEOUT(framesOf(rig, 0x322).size() >= 5, 5000);
        QVERIFY(sender.remove(open));
        QTest::qWait(30);  // frames already handed to the bus arrive
        const size_t after = framesOf(rig, 0x322).size();
        QTest::qWait(100);
        QCOMPARE(framesOf(rig, 0x322).size(), after);
    }

    void transmitListRunsSeveralRowsAtOnce() {
        Rig rig;
        QVERIFY(rig.open());
        BusMaster master(*rig.context);
        TransmitList& list = master.transmit();
        const int a = list.add({CanFrame::classic(0x201, {1, 2}), 5000, {}});
        const int b = list.add({CanFrame::classic(0x202, {3}), 7000, {}});
        const int once = list.add({CanFrame::classic(0x603, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}), 0, {}});
        QString error;
        QVERIFY2(list.start(a, &error), qPrintable(error));
        QVERIFY2(list.start(b, &error), qPrintable(error));
        QVERIFY(list.sendOnce(once, &error));
        QCOMPARE(list.runningCount(), 2);
        QVERIFY(master.anyRunning());
        QTRY_VERIFY_WITH_TIMEOUT(list.sentCount(a) >= 10 && list.sentCount(b) >= 7, 5000);
        master.stopAll();
        QVERIFY(!master.anyRunning());
        QCOMPARE(list.size(), 3);  // rows are kept
        QTRY_COMPARE_WITH_TIMEOUT(framesOf(rig, 0x201).size(), size_t(list.sentCount(a)), 5000);
        QTRY_COMPARE_WITH_TIMEOUT(framesOf(rig, 0x202).size(), size_t(list.sentCount(b)), 5000);
        QTRY_COMPARE_WITH_TIMEOUT(framesOf(rig, 0x603).size(), size_t(1), 5000);
        QCOMPARE(list.sentCount(once), uint64_t(1));
        // A count limit ends a row by itself.
        QVERIFY(list.start(b, &error, 3));
        QTRY_VERIFY_WITH_TIMEOUT(!list.isRunning(b), 5000);
        QTRY_COMPARE_WITH_TIMEOUT(framesOf(rig, 0x202).size(), size_t(list.sentCount(b)), 5000);
        QVERIFY(list.lastError(b).isEmpty());
    }

    void listenOnlyRefusesEveryPeriodicSend() {
        Rig rig;
        QVERIFY(rig.open(QStringLiteral("sim://?listen-only=1")));
        BusMaster master(*rig.context);
        QString error;
        master.sync().setPeriodUs(10000);
        QVERIFY(!master.sync().start(&error));
        QVERIFY2(error.contains(QStringLiteral("listen-only")), qPrintable(error));
        error.clear();
        QVERIFY(!master.heartbeat().start(&error));
        QVERIFY2(error.contains(QStringLiteral("listen-only")), qPrintable(error));
        const int row = master.transmit().add({CanFrame::classic(0x123, {1}), 10000, {}});
        error.clear();
        QVERIFY(!master.transmit().start(row, &error));
        QVERIFY2(error.contains(QStringLiteral("listen-only")), qPrintable(error));
        error.clear();
        QVERIFY(!master.transmit().sendOnce(row, &error));
        QVERIFY2(error.contains(QStringLiteral("listen-only")), qPrintable(error));
        QVERIFY(!master.anyRunning());
        QVERIFY(master.periodic().jobs().empty());
        QTest::qWait(100);
        QCOMPARE(rig.bus->counters().tx, uint64_t(0));
        QVERIFY(framesOf(rig, 0x80).empty() && framesOf(rig, 0x77F).empty() && framesOf(rig, 0x123).empty());
    }
};

QTEST_GUILESS_MAIN(TestSvcMaster)
#include "test_svc_master.moc"
