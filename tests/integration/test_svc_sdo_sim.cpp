// SPDX-License-Identifier: GPL-3.0-or-later
// SDO client against the virtual drives (sim://): every transfer type, server aborts with CiA and
// vendor texts, timeouts (dropped responses), toggle and CRC errors and declined block transfer
// from the SDO server's fault injection.
#include "SvcTestRig.h"

#include "core/canopen/SdoAbort.h"
#include "core/canopen/SdoClient.h"
#include "core/canopen/ServiceWait.h"
#include "core/sim/VirtualDevice.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;
using namespace svctest;

namespace {
const QString kSpec = QStringLiteral("1:delta-asda-a2,2:aimotor,3:generic-cia402");

SdoResult read(SdoClient& c, uint8_t node, uint16_t index, uint8_t sub, SdoOptions o = {}) {
    auto r = waitForResult<SdoResult>([&](SdoCallback cb) { c.upload(node, index, sub, cb, o); }, 30000);
    return r ? *r : SdoResult{};
}
SdoResult write(SdoClient& c, uint8_t node, uint16_t index, uint8_t sub, const QByteArray& d, SdoOptions o = {}) {
    auto r = waitForResult<SdoResult>([&](SdoCallback cb) { c.download(node, index, sub, d, cb, o); }, 30000);
    return r ? *r : SdoResult{};
}
uint32_t u32(const QByteArray& b) {
    uint32_t v = 0;
    for (int i = 0; i < std::min<int>(4, int(b.size())); ++i) v |= uint32_t(uint8_t(b[i])) << (8 * i);
    return v;
}
SdoOptions block() {
    SdoOptions o;
    o.protocol = SdoOptions::Protocol::Block;
    return o;
}
QByteArray domainPattern(int n, int salt) {
    QByteArray b(n, 0);
    for (int i = 0; i < n; ++i) b[i] = char((i * 13 + salt) & 0xFF);
    return b;
}
}  // namespace

class TestSvcSdoSim : public QObject {
    Q_OBJECT
private slots:
    void expeditedReadOfEveryDrive() {
        Rig rig;
        QString error;
        QVERIFY2(rig.useSpec(kSpec, &error), qPrintable(error));
        QVERIFY(rig.open());
        SdoClient client(*rig.context);
        for (uint8_t node : {1, 2, 3}) {
            const SdoResult r = read(client, node, 0x1000, 0);
            QVERIFY2(r.ok, qPrintable(r.error));
            QCOMPARE(r.data.size(), 4);
            QCOMPARE(u32(r.data) & 0xFFFF, 0x0192u);  // CiA 402 device profile number
            const SdoResult v = read(client, node, 0x1018, 1);
            QVERIFY2(v.ok, qPrintable(v.error));
        }
        QCOMPARE(u32(read(client, 1, 0x1018, 1).data), 0x000001DDu);  // Delta's vendor-ID
    }

    void expeditedWriteReadsBack() {
        Rig rig;
        QVERIFY(rig.useSpec(kSpec));
        QVERIFY(rig.open());
        SdoClient client(*rig.context);
        QVERIFY(write(client, 3, 0x1017, 0, QByteArray::fromHex("f401")).ok);  // heartbeat 500 ms
        QCOMPARE(read(client, 3, 0x1017, 0).data, QByteArray::fromHex("f401"));
    }

    void segmentedAndBlockDomain() {
        Rig rig;
        QVERIFY(rig.useSpec(kSpec));
        QVERIFY(rig.open());
        SdoClient client(*rig.context);
        const uint16_t dom = sim::VirtualDevice::kTestDomainIndex;
        // Initial content: byte i = i & FFh.
        const SdoResult seg = read(client, 2, dom, 0);
        QVERIFY2(seg.ok, qPrintable(seg.error));
        QCOMPARE(seg.data.size(), sim::VirtualDevice::kTestDomainSize);
        QCOMPARE(uint8_t(seg.data[300]), uint8_t(300 & 0xFF));
        const SdoResult blk = read(client, 2, dom, 0, block());
        QVERIFY2(blk.ok, qPrintable(blk.error));
        QCOMPARE(blk.data, seg.data);
        QVERIFY(!blk.fellBackToSegmented);
        QVERIFY(blk.framesSent + blk.framesReceived < seg.framesSent + seg.framesReceived);
        // Writes both ways, read back.
        const QByteArray a = domainPattern(5000, 1);
        QVERIFY(write(client, 2, dom, 0, a).ok);
        QCOMPARE(read(client, 2, dom, 0, block()).data, a);
        const QByteArray b = domainPattern(9001, 7);
        const SdoResult wb = write(client, 2, dom, 0, b, block());
        QVERIFY2(wb.ok, qPrintable(wb.error));
        QVERIFY(!wb.fellBackToSegmented);
        QCOMPARE(read(client, 2, dom, 0).data, b);
    }

    void serverAbortsCarryTexts() {
        Rig rig;
        QVERIFY(rig.useSpec(kSpec));
        QVERIFY(rig.open());
        SdoClient client(*rig.context);
        SdoResult r = read(client, 3, 0x2FF0, 1);
        QVERIFY(!r.ok);
        QVERIFY(r.serverAborted);
        QCOMPARE(r.abortCode, sdoabort::NoObject);
        QCOMPARE(r.error,
                 QStringLiteral("node 3 aborted 2FF0:01: Object does not exist in the object dictionary (0x06020000)"));
        r = write(client, 3, 0x1000, 0, QByteArray::fromHex("00000000"));  // read-only
        QCOMPARE(r.abortCode, sdoabort::ReadOnly);
        QVERIFY2(r.error.contains(QStringLiteral("read-only")) || r.error.contains(QStringLiteral("read only")),
                 qPrintable(r.error));
        r = write(client, 3, 0x1017, 0, QByteArray::fromHex("010203"));  // wrong length
        QVERIFY(!r.ok);
        QVERIFY(r.serverAborted);
        // A vendor code via injection, with the Delta table.
        rig.context->setNodeDictionary(1, QStringLiteral("delta-asda-a2"));  // its bundled alarm table (:/alarms)
        rig.onDevice(1, [](sim::VirtualDevice& d) {
            d.sdoFaults().abortOn = std::make_tuple(uint16_t(0x1010), uint8_t(1), uint32_t(0x080000A2));
        });
        r = write(client, 1, 0x1010, 1, QByteArray("save"));
        QCOMPARE(r.error, QStringLiteral("node 1 aborted 1010:01: Object error when writing to EEPROM (0x080000A2)"));
    }

    void droppedResponseTimesOutWithoutRetry() {
        Rig rig;
        QVERIFY(rig.useSpec(kSpec));
        QVERIFY(rig.open());
        SdoClient client(*rig.context);
        client.setDefaultTimeout(200);
        uint64_t before = 0;
        rig.onDevice(3, [&](sim::VirtualDevice& d) {
            d.sdoFaults().dropResponses = 1;
            before = d.sdoRequests();
        });
        SdoResult r = write(client, 3, 0x1017, 0, QByteArray::fromHex("e803"));
        QVERIFY(r.timedOut);
        QCOMPARE(r.abortCode, sdoabort::Timeout);
        QTest::qWait(300);
        uint64_t after = 0;
        rig.onDevice(3, [&](sim::VirtualDevice& d) { after = d.sdoRequests(); });
        QVERIFY2(after - before <= 2, "the write went out once (plus our abort)");
        // A read is not retried silently either: it fails and the next one works.
        rig.onDevice(3, [](sim::VirtualDevice& d) { d.sdoFaults().dropResponses = 1; });
        QVERIFY(read(client, 3, 0x1000, 0).timedOut);
        QVERIFY(read(client, 3, 0x1000, 0).ok);
        // A late answer (delay) beyond the timeout is a timeout too.
        rig.onDevice(3, [](sim::VirtualDevice& d) { d.sdoFaults().delayMs = 400; });
        QVERIFY(read(client, 3, 0x1000, 0).timedOut);
        rig.onDevice(3, [](sim::VirtualDevice& d) { d.sdoFaults().delayMs = 0; });
        QTest::qWait(500);
    }

    void wrongToggleAndCrcAreAborted() {
        Rig rig;
        QVERIFY(rig.useSpec(kSpec));
        QVERIFY(rig.open());
        SdoClient client(*rig.context);
        const uint16_t dom = sim::VirtualDevice::kTestDomainIndex;
        rig.onDevice(2, [](sim::VirtualDevice& d) { d.sdoFaults().wrongToggle = true; });
        SdoResult r = read(client, 2, dom, 0);
        QVERIFY(!r.ok);
        QCOMPARE(r.abortCode, sdoabort::ToggleBit);
        rig.onDevice(2, [](sim::VirtualDevice& d) { d.sdoFaults().wrongToggle = true; });
        r = write(client, 2, dom, 0, domainPattern(100, 3));
        QVERIFY(!r.ok);
        QCOMPARE(r.abortCode, sdoabort::ToggleBit);
        rig.onDevice(2, [](sim::VirtualDevice& d) { d.sdoFaults().blockCrcError = true; });
        r = read(client, 2, dom, 0, block());
        QVERIFY(!r.ok);
        QCOMPARE(r.abortCode, sdoabort::CrcError);
        QVERIFY(r.error.contains(QStringLiteral("CRC")));
        rig.onDevice(2, [](sim::VirtualDevice& d) { d.sdoFaults().blockCrcError = true; });
        r = write(client, 2, dom, 0, domainPattern(100, 3), block());
        QVERIFY(!r.ok);
        QVERIFY(r.serverAborted);
        QCOMPARE(r.abortCode, sdoabort::CrcError);
        // The client recovers: the next transfer works.
        QVERIFY(read(client, 2, dom, 0, block()).ok);
    }

    void declinedBlockFallsBack() {
        Rig rig;
        QVERIFY(rig.useSpec(kSpec));
        QVERIFY(rig.open());
        SdoClient client(*rig.context);
        const uint16_t dom = sim::VirtualDevice::kTestDomainIndex;
        rig.onDevice(1, [](sim::VirtualDevice& d) { d.sdoFaults().declineBlock = true; });
        const SdoResult r = read(client, 1, dom, 0, block());
        QVERIFY2(r.ok, qPrintable(r.error));
        QVERIFY(r.fellBackToSegmented);
        QCOMPARE(r.data.size(), sim::VirtualDevice::kTestDomainSize);
        const QByteArray d = domainPattern(777, 9);
        const SdoResult w = write(client, 1, dom, 0, d, block());
        QVERIFY2(w.ok, qPrintable(w.error));
        QVERIFY(w.fellBackToSegmented);
        QCOMPARE(read(client, 1, dom, 0).data, d);
    }

    void queueServesNodesIndependently() {
        Rig rig;
        QVERIFY(rig.useSpec(kSpec));
        QVERIFY(rig.open());
        SdoClient client(*rig.context);
        int done = 0, good = 0;
        for (int i = 0; i < 10; ++i)
            for (uint8_t node : {1, 2, 3})
                client.upload(node, 0x1018, 1, [&](const SdoResult& r) {
                    ++done;
                    good += r.ok;
                });
        QVERIFY(waitUntil([&] { return done == 30; }, 20000));
        QCOMPARE(good, 30);
    }
};

QTEST_GUILESS_MAIN(TestSvcSdoSim)
#include "test_svc_sdo_sim.moc"
