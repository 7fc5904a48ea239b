// SPDX-License-Identifier: GPL-3.0-or-later
// The virtual drives' heartbeat consumer (CiA 301 §7.2.8.3.2.2, 1016h) and their reaction when
// the master's heartbeat stops, frame by frame: a heartbeat producer on node 127 every 100 ms,
// 1016h:01 = 007F012Ch (node 127, 300 ms); the heartbeat stops while the drive turns in
// Operation enabled; about 300 ms later the drive sends EMCY 8130h (CiA 301 Table 21) and reacts
// as 6007h says (CiA 402-2: 0 no action, 1 fault, 2 disable voltage, 3 quick stop), or, without
// 6007h, as its manual says (Delta AL170/AL180, AIMOTOR Er.D03).
#include "SimTestHarness.h"

#include "core/canopen/SdoAbort.h"
#include "core/sim/Ds402Drive.h"
#include "core/sim/HeartbeatConsumer.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::testing;
using canopen::ds402::State;

namespace {
constexpr uint32_t kWatch127 = 0x007F012C;  // node 127, 300 ms

struct DriveView {
    State state = State::Unknown;
    double velocity = 0;
    canopen::NmtState nmt = canopen::NmtState::BootUp;
};
DriveView view(SimHarness& h, uint8_t node) {
    DriveView v;
    h.withDevice(node, [&](sim::VirtualDevice& d) {
        v.nmt = d.nmtState();
        if (auto* drive = d.drive(0)) {
            v.state = drive->state();
            v.velocity = drive->velocity();
        }
    });
    return v;
}

// Profile velocity at `velocity`, enabled through 6040h 06h 07h 0Fh (CiA 402-2 §6.2).
void enableAndTurn(SimHarness& h, uint8_t node, int32_t velocity) {
    QVERIFY(h.download(node, 0x6060, 0, SimHarness::u8(3)).ok());
    QVERIFY(h.download(node, 0x60FF, 0, SimHarness::u32(uint32_t(velocity))).ok());
    for (uint16_t cw : {0x06, 0x07, 0x0F}) QVERIFY(h.download(node, 0x6040, 0, SimHarness::u16(cw)).ok());
    QCOMPARE(view(h, node).state, State::OperationEnabled);
}

// Node 127's heartbeat (05h operational) every 100 ms for `ms`; returns the frames seen
// meanwhile. *sinceLast restarts at the last heartbeat sent.
std::vector<CanFrame> heartbeats(SimHarness& h, int ms, QElapsedTimer* sinceLast) {
    std::vector<CanFrame> seen;
    for (int t = 0; t < ms; t += 100) {
        h.send(CanFrame::classic(0x77F, {0x05}));
        sinceLast->start();
        for (const CanFrame& f : h.collect(100)) seen.push_back(f);
    }
    return seen;
}

bool isEmcy(const CanFrame& f, uint8_t node) { return f.id == 0x80u + node && f.len == 8; }
uint16_t emcyCode(const CanFrame& f) { return uint16_t(f.data[0] | (f.data[1] << 8)); }
}  // namespace

class TestSimHeartbeatConsumer : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { eds::installSimulatorDictionaries(); }

    // The brief's case on the generic CiA 402 drive with 6007h = 3 (quick stop).
    void lostHeartbeatQuickStopsTheDrive() {
        SimHarness h;
        QString err;
        QVERIFY2(h.open(QStringLiteral("3:generic-cia402"), &err), qPrintable(err));
        h.send(CanFrame::classic(0x000, {0x01, 0x03}));  // NMT start
        QVERIFY(h.download(3, 0x1016, 1, SimHarness::u32(kWatch127)).ok());
        QVERIFY(h.download(3, 0x6007, 0, SimHarness::u16(3)).ok());
        enableAndTurn(h, 3, 5000);
        QElapsedTimer sinceLast;
        const auto seen = heartbeats(h, 600, &sinceLast);
        for (const CanFrame& f : seen) QVERIFY2(!isEmcy(f, 3), "EMCY while the heartbeat came in time");
        DriveView turning = view(h, 3);
        QCOMPARE(turning.state, State::OperationEnabled);
        QVERIFY2(turning.velocity > 1000, qPrintable(QString::number(turning.velocity)));
        QCOMPARE(turning.nmt, canopen::NmtState::Operational);

        // The heartbeat stops: EMCY 8130h after the consumer time (300 ms), not before.
        auto emcy = h.waitFor([](const CanFrame& f) { return isEmcy(f, 3); }, 1500);
        const qint64 after = sinceLast.elapsed();
        QVERIFY(emcy);
        QCOMPARE(emcyCode(*emcy), 0x8130);
        QVERIFY2(emcy->data[2] & 0x10, "1001h communication error bit");  // CiA 301 §7.5.2.2
        QVERIFY2(after >= 280 && after < 700, qPrintable(QString::number(after)));
        // Quick stop: out of Operation enabled at once, brakes on 6085h, then Switch on disabled
        // (605Ah = 2).
        QVERIFY(view(h, 3).state != State::OperationEnabled);
        QTRY_COMPARE_WITH_TIMEOUT(view(h, 3).state, State::SwitchOnDisabled, 1000);
        QCOMPARE(view(h, 3).velocity, 0.0);
        const auto sw = h.read(3, 0x6041, 0);
        QVERIFY(sw);
        QCOMPARE(*sw & 0x4F, 0x40u);  // switch on disabled (CiA 402-2 Table 30)
        // 1029h:01 = 0: an operational node goes pre-operational (CiA 301 §7.5.2.32).
        QCOMPARE(view(h, 3).nmt, canopen::NmtState::PreOperational);
        // One event, one EMCY.
        for (const CanFrame& f : h.collect(400)) QVERIFY2(!isEmcy(f, 3), "a second EMCY");
    }

    void eachAbortConnectionOption_data() {
        QTest::addColumn<int>("option");
        QTest::addColumn<int>("state");
        QTest::newRow("0 no action") << 0 << int(State::OperationEnabled);
        QTest::newRow("1 fault signal") << 1 << int(State::Fault);
        QTest::newRow("2 disable voltage") << 2 << int(State::SwitchOnDisabled);
    }
    void eachAbortConnectionOption() {
        QFETCH(int, option);
        QFETCH(int, state);
        SimHarness h;
        QString err;
        QVERIFY2(h.open(QStringLiteral("3:generic-cia402"), &err), qPrintable(err));
        QVERIFY(h.download(3, 0x1016, 1, SimHarness::u32(kWatch127)).ok());
        QVERIFY(h.download(3, 0x6007, 0, SimHarness::u16(uint16_t(option))).ok());
        enableAndTurn(h, 3, 2000);
        QElapsedTimer sinceLast;
        heartbeats(h, 300, &sinceLast);
        auto emcy = h.waitFor([](const CanFrame& f) { return isEmcy(f, 3); }, 1500);
        QVERIFY(emcy);
        QCOMPARE(emcyCode(*emcy), 0x8130);
        QTRY_COMPARE_WITH_TIMEOUT(int(view(h, 3).state), state, 500);
        if (option == 1) QCOMPARE(h.read(3, 0x603F, 0).value_or(0), 0x8130u);  // error code of the fault
        if (option == 0) QVERIFY(view(h, 3).velocity > 1000);                  // no action: still turning
    }

    // Monitoring starts with the first heartbeat of the watched node (CiA 301 §7.2.8.3.2.2), and
    // starts again with the next one after an event.
    void watchStartsWithTheFirstHeartbeat() {
        SimHarness h;
        QString err;
        QVERIFY2(h.open(QStringLiteral("3:generic-cia402"), &err), qPrintable(err));
        QVERIFY(h.download(3, 0x1016, 1, SimHarness::u32(kWatch127)).ok());
        QVERIFY(h.download(3, 0x6007, 0, SimHarness::u16(0)).ok());
        // Another node's heartbeat is not the watched one.
        for (int i = 0; i < 6; ++i) {
            h.send(CanFrame::classic(0x77E, {0x05}));
            for (const CanFrame& f : h.collect(100)) QVERIFY2(!isEmcy(f, 3), "EMCY before node 127 was ever heard");
        }
        QElapsedTimer sinceLast;
        for (int round = 0; round < 2; ++round) {
            heartbeats(h, 200, &sinceLast);
            auto emcy = h.waitFor([](const CanFrame& f) { return isEmcy(f, 3); }, 1000);
            QVERIFY2(emcy, qPrintable(QStringLiteral("round %1").arg(round)));
            QCOMPARE(emcyCode(*emcy), 0x8130);
        }
        uint64_t events = 0;
        h.withDevice(3, [&](sim::VirtualDevice& d) { events = d.heartbeatConsumer().events(); });
        QCOMPARE(events, uint64_t(2));
        // 1016h:01 = 0 stops the watch.
        h.send(CanFrame::classic(0x77F, {0x05}));
        QVERIFY(h.download(3, 0x1016, 1, SimHarness::u32(0)).ok());
        for (const CanFrame& f : h.collect(500)) QVERIFY2(!isEmcy(f, 3), "EMCY after the entry was cleared");
    }

    // Two entries with a time for one node-ID: abort 06040043h (CiA 301 §7.5.2.18).
    void oneEntryPerProducer() {
        SimHarness h;
        QString err;
        QVERIFY2(h.open(QStringLiteral("3:generic-cia402"), &err), qPrintable(err));
        QCOMPARE(h.read(3, 0x1016, 0).value_or(0), 4u);
        QVERIFY(h.download(3, 0x1016, 1, SimHarness::u32(kWatch127)).ok());
        QCOMPARE(h.download(3, 0x1016, 2, SimHarness::u32(0x007F0200)).abort, canopen::sdoabort::ParameterIncompatible);
        QVERIFY(h.download(3, 0x1016, 2, SimHarness::u32(0x007E0200)).ok());
        QVERIFY(h.download(3, 0x1016, 2, SimHarness::u32(0x007F0000)).ok());  // time 0: unused, allowed
        QVERIFY(h.download(3, 0x1016, 1, SimHarness::u32(0x007F03E8)).ok());  // the same entry, a new time
        QCOMPARE(h.read(3, 0x6007, 0).value_or(0xFFFF), 1u);                  // generic default: fault signal
    }

    // Delta ASDA-A2: no 6007h; AL170 with the servo on, AL180 with it off (extract-delta §6.3).
    void deltaRaisesAl170OrAl180() {
        for (bool servoOn : {true, false}) {
            SimHarness h;
            QString err;
            QVERIFY2(h.open(QStringLiteral("1:delta-asda-a2"), &err), qPrintable(err));
            QCOMPARE(h.upload(1, 0x6007, 0).abort, canopen::sdoabort::NoObject);
            QCOMPARE(h.read(1, 0x1016, 0).value_or(0), 1u);
            QVERIFY(h.download(1, 0x1016, 1, SimHarness::u32(kWatch127)).ok());
            if (servoOn) enableAndTurn(h, 1, 100);
            QElapsedTimer sinceLast;
            heartbeats(h, 300, &sinceLast);
            auto emcy = h.waitFor([](const CanFrame& f) { return isEmcy(f, 1); }, 1500);
            QVERIFY(emcy);
            QCOMPARE(emcyCode(*emcy), 0x8130);
            QCOMPARE(int(emcy->data[3] | (emcy->data[4] << 8)), servoOn ? 0x0170 : 0x0180);
            QTRY_COMPARE_WITH_TIMEOUT(view(h, 1).state, State::Fault, 500);
            QCOMPARE(view(h, 1).velocity, 0.0);
        }
    }

    // AIMOTOR: no 6007h; Er.D03 "CAN communication interrupted" (resources/alarms/aimotor.json).
    void aimotorRaisesErD03() {
        SimHarness h;
        QString err;
        QVERIFY2(h.open(QStringLiteral("2:aimotor"), &err), qPrintable(err));
        QCOMPARE(h.upload(2, 0x6007, 0).abort, canopen::sdoabort::NoObject);
        QVERIFY(h.download(2, 0x1016, 1, SimHarness::u32(kWatch127)).ok());
        enableAndTurn(h, 2, 1000);
        QElapsedTimer sinceLast;
        heartbeats(h, 300, &sinceLast);
        auto emcy = h.waitFor([](const CanFrame& f) { return isEmcy(f, 2); }, 1500);
        QVERIFY(emcy);
        QCOMPARE(emcyCode(*emcy), 0x8130);
        QCOMPARE(int(emcy->data[3] | (emcy->data[4] << 8)), 0x0D03);
        QTRY_COMPARE_WITH_TIMEOUT(view(h, 2).state, State::Fault, 500);
    }

    // DEXMART DEV has no 1016h (extract-dexmart §2.5).
    void dexmartHasNoConsumer() {
        SimHarness h;
        QString err;
        QVERIFY2(h.open(QStringLiteral("4:dexmart-dev"), &err), qPrintable(err));
        QCOMPARE(h.upload(4, 0x1016, 1).abort, canopen::sdoabort::NoObject);
    }
};

QTEST_GUILESS_MAIN(TestSimHeartbeatConsumer)
#include "test_sim_heartbeat_consumer.moc"
