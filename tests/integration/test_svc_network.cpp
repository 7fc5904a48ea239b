// SPDX-License-Identifier: GPL-3.0-or-later
// NMT master, heartbeat consumer / node guarding feeding the node table, EMCY counting, SYNC
// producer and the network scan, against virtual drives.
#include "SvcTestRig.h"

#include "core/canopen/HeartbeatMonitor.h"
#include "core/canopen/NetworkScan.h"
#include "core/canopen/NmtMaster.h"
#include "core/canopen/ServiceWait.h"
#include "core/canopen/SyncProducer.h"
#include "core/sim/VirtualDevice.h"
#include "eds/ScanMatcher.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;
using namespace svctest;

namespace {
const QString kSpec = QStringLiteral("1:delta-asda-a2,2:aimotor,3:generic-cia402");
// 1017h is UNSIGNED16 in CiA 301 but some drives make it 32 bits: write it with the length it reads.
bool setHeartbeat(SdoClient& c, uint8_t node, uint16_t ms) {
    auto cur = waitForResult<SdoResult>([&](SdoCallback cb) { c.upload(node, 0x1017, 0, cb); }, 10000);
    if (!cur || !cur->ok) return false;
    QByteArray v(cur->data.size(), 0);
    v[0] = static_cast<char>(ms & 0xFF);
    if (v.size() > 1) v[1] = static_cast<char>(ms >> 8);
    auto r = waitForResult<SdoResult>([&](SdoCallback cb) { c.download(node, 0x1017, 0, v, cb); }, 10000);
    return r && r->ok;
}
}  // namespace

class TestSvcNetwork : public QObject {
    Q_OBJECT
private slots:
    void nmtCommandsShowInNodeTable() {
        Rig rig;
        QVERIFY(rig.useSpec(kSpec));
        QVERIFY(rig.open());
        HeartbeatMonitor monitor(*rig.context);
        SdoClient sdo(*rig.context);
        NmtMaster nmt(*rig.context);
        for (uint8_t n : {1, 2, 3}) QVERIFY(setHeartbeat(sdo, n, 50));  // heartbeat every 50 ms
        const auto state = [&](uint8_t n) {
            const auto info = monitor.table().node(n);
            return static_cast<uint8_t>(info ? info->nmtState : 0xFF);
        };
        QTRY_COMPARE_WITH_TIMEOUT(state(3), uint8_t(0x7F), 2000);
        QVERIFY(nmt.start(0));
        QTRY_VERIFY_WITH_TIMEOUT(state(1) == 5 && state(2) == 5 && state(3) == 5, 2000);
        QVERIFY(nmt.stop(2));
        QTRY_COMPARE_WITH_TIMEOUT(state(2), uint8_t(4), 2000);
        QCOMPARE(state(1), uint8_t(5));
        QVERIFY(nmt.enterPreOperational(2));
        QTRY_COMPARE_WITH_TIMEOUT(state(2), uint8_t(0x7F), 2000);
        // Reset node: boot-up, counted.
        const uint32_t boots = monitor.table().node(3).value_or(NodeInfo{}).bootUps;
        QSignalSpy bootSpy(&monitor, &HeartbeatMonitor::bootUp);
        QVERIFY(nmt.resetNode(3));
        QTRY_COMPARE_WITH_TIMEOUT(monitor.table().node(3).value_or(NodeInfo{}).bootUps, boots + 1u, 3000);
        QVERIFY(bootSpy.count() >= 1);
        QVERIFY(nmt.resetCommunication(1));
        QTRY_VERIFY_WITH_TIMEOUT(monitor.table().node(1).value_or(NodeInfo{}).bootUps >= 1, 3000);
        QVERIFY(monitor.table().node(1).value_or(NodeInfo{}).lastSeenNs > 0);
        QString error;
        QVERIFY(!nmt.send(NmtCommand::Start, 200, &error));
    }

    void heartbeatLossAndEmcy() {
        Rig rig;
        QVERIFY(rig.useSpec(kSpec));
        QVERIFY(rig.open());
        HeartbeatMonitor monitor(*rig.context);
        SdoClient sdo(*rig.context);
        QVERIFY(setHeartbeat(sdo, 2, 50));
        monitor.setConsumerTime(2, 300);
        QTest::qWait(400);
        QVERIFY(!monitor.table().node(2).value_or(NodeInfo{}).heartbeatLost);
        QSignalSpy lost(&monitor, &HeartbeatMonitor::nodeLost);
        QVERIFY(setHeartbeat(sdo, 2, 0));  // producer off
        QTRY_VERIFY_WITH_TIMEOUT(monitor.table().node(2).value_or(NodeInfo{}).heartbeatLost, 2000);
        QCOMPARE(lost.count(), 1);
        QVERIFY(setHeartbeat(sdo, 2, 50));
        QTRY_VERIFY_WITH_TIMEOUT(!monitor.table().node(2).value_or(NodeInfo{}).heartbeatLost, 2000);
        // EMCY from a drive fault.
        rig.onDevice(2, [](sim::VirtualDevice& d) { d.injectDriveFault(); });
        QTRY_VERIFY_WITH_TIMEOUT(monitor.table().node(2).value_or(NodeInfo{}).emcyCount >= 1, 2000);
        QVERIFY(monitor.table().node(2).value_or(NodeInfo{}).lastEmcyCode != 0);
    }

    void nodeGuarding() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("3:generic-cia402")));
        QVERIFY(rig.open());
        HeartbeatMonitor monitor(*rig.context);
        SdoClient sdo(*rig.context);
        QVERIFY(setHeartbeat(sdo, 3, 0));  // guarding replaces heartbeat
        monitor.setGuarding(3, 50, 3);
        QTest::qWait(600);
        QVERIFY(!monitor.table().node(3).value_or(NodeInfo{}).heartbeatLost);
        QCOMPARE(monitor.table().node(3).value_or(NodeInfo{}).guardingErrors, 0);
        QCOMPARE(monitor.table().node(3).value_or(NodeInfo{}).nmtState, 0x7F);
        // A guarded node that is not there is lost after guard time x life time factor.
        monitor.setGuarding(9, 50, 2);
        QTRY_VERIFY_WITH_TIMEOUT(monitor.table().node(9).value_or(NodeInfo{}).heartbeatLost, 2000);
    }

    void syncProducerCounterAnd1006() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("3:generic-cia402")));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        SyncProducer sync(*rig.context);
        sync.setPeriodUs(10000);
        QVERIFY(!sync.setCounterOverflow(1));
        QVERIFY(sync.setCounterOverflow(4));
        QVERIFY(sync.start());
        QTRY_VERIFY_WITH_TIMEOUT(sync.sent() >= 10, 30000);
        sync.stop();
        // The capture may trail the producer on a loaded machine: wait for the frames themselves.
        QTRY_VERIFY_WITH_TIMEOUT(rig.session.store()->framesFor(0x80).size() >= 10, 30000);
        const auto frames = rig.session.store()->framesFor(0x80);
        QVERIFY(frames.size() >= 10);
        std::vector<int> counters;
        for (auto no : frames) {
            const CanFrame f = rig.session.store()->frame(no);
            QCOMPARE(f.len, uint8_t(1));
            counters.push_back(f.data[0]);
        }
        for (size_t i = 0; i < 8; ++i) QCOMPARE(counters[i], int(i % 4) + 1);
        auto r =
            waitForResult<SdoResult>([&](SdoCallback cb) { sync.writeCommunicationCyclePeriod(sdo, 3, cb); }, 5000);
        QVERIFY(r && r->ok);
        auto back = waitForResult<SdoResult>([&](SdoCallback cb) { sdo.upload(3, 0x1006, 0, cb); }, 5000);
        QVERIFY(back && back->ok);
        QCOMPARE(back->data, QByteArray::fromHex("10270000"));
    }

    void scanFindsDrivesAndMatchesDictionaries() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("1:delta-asda-a2,2:aimotor,5:generic-cia402")));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        NetworkScan scan(sdo);
        scan.setRange(1, 12);
        scan.setTimeout(100);
        scan.setMaxOutstanding(4);
        scan.setMatcher(eds::scanMatcher());
        std::optional<std::vector<ScannedNode>> found;
        scan.start([&](const auto& f) { found = f; });
        QVERIFY(waitUntil([&] { return found.has_value(); }, 20000));
        QCOMPARE(found->size(), size_t(3));
        QCOMPARE((*found)[0].node, uint8_t(1));
        QCOMPARE((*found)[0].vendorId.value_or(0), 0x000001DDu);
        QCOMPARE((*found)[0].dictionary, QStringLiteral("delta-asda-a2"));
        QCOMPARE((*found)[1].dictionary, QStringLiteral("aimotor"));
        QCOMPARE((*found)[2].node, uint8_t(5));
        QVERIFY((*found)[2].serial.has_value());
        QCOMPARE(rig.context->nodes().presentCount(), 3);
        QCOMPARE(rig.context->nodes().node(2)->dictionary, QStringLiteral("aimotor"));
        QCOMPARE(rig.context->nodeDictionary(1), QStringLiteral("delta-asda-a2"));
        // Rate limit: never more than 4 requests in flight, so the scan of 12 nodes with
        // 9 silent ones takes at least ceil(9/4) timeouts.
    }
};

QTEST_GUILESS_MAIN(TestSvcNetwork)
#include "test_svc_network.moc"
