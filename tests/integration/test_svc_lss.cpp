// SPDX-License-Identifier: GPL-3.0-or-later
// LSS master (CiA 305) against virtual devices: switch state, inquire identity and node-ID,
// configure node-ID and bit timing, store, selective switch, and Fastscan of an unconfigured node.
#include "SvcTestRig.h"

#include "core/canopen/LssMaster.h"
#include "core/canopen/NmtMaster.h"
#include "core/canopen/ServiceWait.h"
#include "core/sim/VirtualDevice.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;
using namespace svctest;

namespace {
LssResult wait(const std::function<void(LssCallback)>& start) {
    auto r = waitForResult<LssResult>(start, 30000);
    return r ? *r : LssResult{};
}
}  // namespace

class TestSvcLss : public QObject {
    Q_OBJECT
private slots:
    void inquireAndConfigure() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("1:delta-asda-a2")));
        QVERIFY(rig.open());
        LssMaster lss(*rig.context);
        lss.setTimeout(300);
        // Nobody in configuration state: no answer.
        LssResult r = wait([&](auto cb) { lss.inquireNodeId(cb); });
        QVERIFY(!r.ok);
        QVERIFY(r.error.contains(QStringLiteral("no answer")));
        QVERIFY(lss.switchStateGlobal(true));
        r = wait([&](auto cb) { lss.inquireIdentity(cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.identity.vendorId, 0x000001DDu);
        uint32_t serial = 0;
        rig.onDevice(1, [&](sim::VirtualDevice& d) {
            serial = uint32_t(d.value(0x1018, 4).value_or(od::Value{}).toUInt64().value_or(0));
        });
        QCOMPARE(r.identity.serial, serial);  // the LSS address is 1018h:01..04 (CiA 305 §4.2)
        r = wait([&](auto cb) { lss.inquireNodeId(cb); });
        QCOMPARE(r.value, 1u);
        r = wait([&](auto cb) { lss.configureBitRate(250000, cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        r = wait([&](auto cb) { lss.configureBitRate(300000, cb); });  // not in the table: refused locally
        QVERIFY(!r.ok);
        r = wait([&](auto cb) { lss.configureNodeId(12, cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        r = wait([&](auto cb) { lss.storeConfiguration(cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        uint32_t pendingRate = 0;
        uint8_t pendingId = 0;
        rig.onDevice(1, [&](sim::VirtualDevice& d) {
            pendingRate = d.pendingBitRate();
            pendingId = d.pendingNodeId();
        });
        QCOMPARE(pendingRate, 250000u);
        QCOMPARE(pendingId, uint8_t(12));
        // Activate bit timing (unconfirmed) switches the device to the configured rate.
        QVERIFY(lss.activateBitTiming(5));
        uint32_t rate = 0;
        QTRY_VERIFY_WITH_TIMEOUT((rig.onDevice(1, [&](sim::VirtualDevice& d) { rate = d.bitRate(); }), rate == 250000u),
                                 3000);
        QVERIFY(lss.switchStateGlobal(false));
        NmtMaster nmt(*rig.context);
        QVERIFY(nmt.resetCommunication(0));
        bool moved = false;
        QTRY_VERIFY_WITH_TIMEOUT(
            (rig.network->runOnNetworkThread([&] { moved = rig.network->device(12) != nullptr; }), moved), 3000);
    }

    void selectiveSwitch() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("1:delta-asda-a2,2:aimotor")));
        QVERIFY(rig.open());
        LssMaster lss(*rig.context);
        lss.setTimeout(300);
        LssIdentity id;
        rig.onDevice(2, [&](sim::VirtualDevice& d) {
            id.vendorId = d.value(0x1018, 1)->toUInt64().value_or(0);
            id.productCode = d.value(0x1018, 2)->toUInt64().value_or(0);
            id.revision = d.value(0x1018, 3)->toUInt64().value_or(0);
            id.serial = d.serialNumber();
        });
        LssResult r = wait([&](auto cb) { lss.switchStateSelective(id, cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        r = wait([&](auto cb) { lss.inquireNodeId(cb); });
        QCOMPARE(r.value, 2u);  // only node 2 is in configuration state
        QVERIFY(lss.switchStateGlobal(false));
        id.serial ^= 0xFFFF;
        r = wait([&](auto cb) { lss.switchStateSelective(id, cb); });
        QVERIFY(!r.ok);
    }

    void fastscanFindsUnconfiguredNode() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("1:delta-asda-a2,4:generic-cia402")));
        QVERIFY(rig.open());
        LssMaster lss(*rig.context);
        lss.setTimeout(300);
        lss.setFastscanTimeout(20);
        // Nothing unconfigured yet.
        LssResult r = wait([&](auto cb) { lss.fastscan(cb); });
        QVERIFY(!r.ok);
        QVERIFY(r.noSlave);
        uint32_t serial = 0;
        rig.onDevice(4, [&](sim::VirtualDevice& d) {
            serial = d.serialNumber();
            d.makeUnconfigured();
        });
        r = wait([&](auto cb) { lss.fastscan(cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.identity.serial, serial);
        // The found slave is in configuration state: give it node-ID 20.
        r = wait([&](auto cb) { lss.configureNodeId(20, cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        QVERIFY(lss.switchStateGlobal(false));
        NmtMaster nmt(*rig.context);
        QVERIFY(nmt.resetCommunication(0));  // CiA 305: the new node-ID applies from here at the latest
        bool present = false;
        QTRY_VERIFY_WITH_TIMEOUT(
            (rig.network->runOnNetworkThread([&] { present = rig.network->device(20) != nullptr; }), present), 3000);
    }

    // A slave (or a gateway) that answers later than the master's first guess: fastscan must
    // still find the right identity, not read silence as 1-bits (CiA 305 §6.7.4 leaves the
    // timeout to the master). Two unconfigured slaves answer the reset together.
    void fastscanToleratesSlowAnswers() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("1:delta-asda-a2,4:generic-cia402,5:aimotor")));
        QVERIFY(rig.open());
        LssMaster lss(*rig.context);
        lss.setTimeout(400);
        lss.setFastscanTimeout(4);
        uint32_t serial4 = 0, serial5 = 0;
        rig.onDevice(4, [&](sim::VirtualDevice& d) {
            serial4 = d.serialNumber();
            d.lssFaults().replyDelayMs = 15;
            d.makeUnconfigured();
        });
        rig.onDevice(5, [&](sim::VirtualDevice& d) {
            serial5 = d.serialNumber();
            d.lssFaults().replyDelayMs = 18;
            d.makeUnconfigured();
        });
        LssResult r = wait([&](auto cb) { lss.fastscan(cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        QVERIFY2(r.identity.serial == serial4 || r.identity.serial == serial5,
                 qPrintable(QString::number(r.identity.serial, 16)));
        r = wait([&](auto cb) { lss.inquireIdentity(cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        QVERIFY(r.identity.serial == serial4 || r.identity.serial == serial5);
    }
};

QTEST_GUILESS_MAIN(TestSvcLss)
#include "test_svc_lss.moc"
