// SPDX-License-Identifier: GPL-3.0-or-later
// Homing (6098h as each drive's manual defines it) and the profile-position set-point handshake
// of the virtual drives, frame by frame: the AIMOTOR manual's HM frames (extract-aimotor §5.1
// §4.4), its refusals (Er.668, "change 6098 only while disabled"), hard-stop homing 37, the
// H05-35 time limit (Er.601) and 1F -> 0F; Delta's and the generic drive's SDO aborts for a
// method they lack; a switch method moving to the modelled switch and back; CiA 402-2 §12's
// set-point acknowledge with the one-deep buffer, relative and immediate set-points.
#include "SimTestHarness.h"

#include "core/canopen/HomingMethods.h"
#include "core/canopen/SdoAbort.h"
#include "core/sim/Ds402Drive.h"

#include <QtTest>

#include <tuple>

using namespace coscope;
using namespace coscope::testing;

namespace {
constexpr uint16_t kAck = 1u << 12, kError = 1u << 13, kReached = 1u << 10;
}  // namespace

class TestSimHoming : public QObject {
    Q_OBJECT
    static uint32_t sw(SimHarness& h, uint8_t node) { return h.read(node, 0x6041, 0).value_or(0xFFFF); }
    static bool cw(SimHarness& h, uint8_t node, uint16_t v) {
        return h.download(node, 0x6040, 0, SimHarness::u16(v)).ok();
    }
    static int32_t pos(SimHarness& h, uint8_t node) { return int32_t(h.read(node, 0x6064, 0).value_or(0x7FFFFFFF)); }
    static double machine(SimHarness& h, uint8_t node) {
        double m = 0;
        h.withDevice(node, [&](sim::VirtualDevice& d) { m = d.drive(0)->machinePosition(); });
        return m;
    }
    static bool enable(SimHarness& h, uint8_t node) {
        return cw(h, node, 0x06) && cw(h, node, 0x07) && cw(h, node, 0x0F) && (sw(h, node) & 0x6F) == 0x27;
    }
    // Sends `req` and compares the whole answer with `resp` (hex, 8 bytes).
    static bool frame(SimHarness& h, const char* req, const char* resp) {
        const QByteArray q = QByteArray::fromHex(req);
        CanFrame f = CanFrame::classic(0x601, {});
        f.len = 8;
        for (int i = 0; i < 8; ++i) f.data[size_t(i)] = uint8_t(q[i]);
        auto a = h.sdoRequest(1, f);
        if (!a) return false;
        const QByteArray got(reinterpret_cast<const char*>(a->data.data()), 8);
        if (got.toHex() != QByteArray(resp).replace(' ', "").toLower()) {
            qWarning("%s -> %s, expected %s", req, got.toHex(' ').constData(), resp);
            return false;
        }
        return true;
    }

private slots:
    void initTestCase() { eds::installSimulatorDictionaries(); }

    void aimotorManualFramesHomeOnCurrentPosition() {
        SimHarness h;
        QString err;
        QVERIFY2(h.open(QStringLiteral("1:aimotor"), &err), qPrintable(err));
        QCOMPARE(h.read(1, 0x6098, 0).value_or(0), 35u);  // default 35 (extract-aimotor §2.5)
        // Away from zero first (profile position, extract-aimotor §4.6 A), so that "cleared to
        // zero" shows.
        QVERIFY(h.download(1, 0x6060, 0, SimHarness::u8(1)).ok());
        QVERIFY(h.download(1, 0x6081, 0, SimHarness::u32(5000)).ok());
        QVERIFY(h.download(1, 0x607A, 0, SimHarness::u32(500)).ok());
        QVERIFY(enable(h, 1));
        QVERIFY(cw(h, 1, 0x1F));
        QTRY_COMPARE_WITH_TIMEOUT(pos(h, 1), 500, 10000);
        QVERIFY(cw(h, 1, 0x00));
        // extract-aimotor §5.1 "§4.4 HM via SDO", node 1, with the default method and speeds.
        QVERIFY(frame(h, "2F60600006000000", "60 60 60 00 00 00 00 00"));  // HM1/HM2
        QVERIFY(frame(h, "2F98600023000000", "60 98 60 00 00 00 00 00"));  // HM3/HM4: 6098h = 35
        QVERIFY(frame(h, "2399600110270000", "60 99 60 01 00 00 00 00"));  // HM5/HM6: 10000 pulse/s
        QVERIFY(frame(h, "23996002E8030000", "60 99 60 02 00 00 00 00"));  // HM7/HM8: 1000 pulse/s
        QVERIFY(frame(h, "239A600010270000", "60 9A 60 00 00 00 00 00"));  // HM9/HM10
        QVERIFY(frame(h, "2B40600006000000", "60 40 60 00 00 00 00 00"));  // HM11-HM18: 06 07 0F 1F
        QVERIFY(frame(h, "2B40600007000000", "60 40 60 00 00 00 00 00"));
        QVERIFY(frame(h, "2B4060000F000000", "60 40 60 00 00 00 00 00"));
        QVERIFY(frame(h, "2B4060001F000000", "60 40 60 00 00 00 00 00"));
        // HM19/HM20: operation enabled (0237h) + target reached + homing attained + home found
        // (bit 15); HM21/HM22: the position cleared to zero.
        QVERIFY(frame(h, "4041600000000000", "4B 41 60 00 37 96 00 00"));
        QVERIFY(frame(h, "4064600000000000", "43 64 60 00 00 00 00 00"));
        // Bit 15 "home found" is cleared by disabling (extract-aimotor §4.2).
        QVERIFY(cw(h, 1, 0x06));
        QVERIFY(!(sw(h, 1) & 0x8000));
    }

    void aimotorRefusals() {
        SimHarness h;
        QString err;
        QVERIFY2(h.open(QStringLiteral("1:aimotor"), &err), qPrintable(err));
        QVERIFY(h.download(1, 0x6060, 0, SimHarness::u8(6)).ok());
        QVERIFY(enable(h, 1));
        // "Change 6098 only while disabled": another method is refused in Operation enabled.
        QCOMPARE(h.download(1, 0x6098, 0, SimHarness::u8(17)).abort, canopen::sdoabort::DeviceState);
        QVERIFY(h.download(1, 0x6098, 0, SimHarness::u8(35)).ok());  // the same one is fine
        QCOMPARE(h.download(1, 0x6098, 0, SimHarness::u8(39)).abort, canopen::sdoabort::ValueTooHigh);  // 0-38
        QVERIFY(cw(h, 1, 0x06));
        // Method 3 is in range but not the drive's: taken, and Er.668 when homing starts.
        QVERIFY(h.download(1, 0x6098, 0, SimHarness::u8(3)).ok());
        QVERIFY(enable(h, 1));
        h.clear();
        QVERIFY(cw(h, 1, 0x1F));
        auto e = h.waitFor([](const CanFrame& f) { return f.id == 0x81; }, 1000);
        QVERIFY(e);
        QCOMPARE(QByteArray(reinterpret_cast<const char*>(e->data.data()), 2).toHex(),
                 QByteArray("00ff"));  // EMCY FF00h
        QCOMPARE(QByteArray(reinterpret_cast<const char*>(e->data.data() + 3), 2).toHex(),
                 QByteArray("6806"));                             // vendor 0668h
        QTRY_COMPARE_WITH_TIMEOUT(sw(h, 1) & 0x4F, 0x08u, 2000);  // fault
        QCOMPARE(h.read(1, 0x603F, 0).value_or(0), 0xFF00u);
    }

    void aimotorSwitchMethodAbortAndTimeLimit() {
        SimHarness h;
        QString err;
        QVERIFY2(h.open(QStringLiteral("1:aimotor"), &err), qPrintable(err));
        QVERIFY(h.download(1, 0x6060, 0, SimHarness::u8(6)).ok());
        QVERIFY(h.download(1, 0x6098, 0, SimHarness::u8(17)).ok());  // negative overtravel switch
        QVERIFY(h.download(1, 0x6099, 1, SimHarness::u32(2000)).ok());
        QVERIFY(enable(h, 1));
        QVERIFY(cw(h, 1, 0x1F));
        QCOMPARE(sw(h, 1) & (kAck | kError | kReached), 0u);  // 000: in progress (CiA 402-2 §13.1)
        QTRY_VERIFY_WITH_TIMEOUT(pos(h, 1) < -100, 5000);
        // 1F -> 0F aborts (extract-aimotor §4.6 C): stops short of the switch, not homed.
        QVERIFY(cw(h, 1, 0x0F));
        QTRY_COMPARE_WITH_TIMEOUT(sw(h, 1) & (kAck | kError | kReached), uint32_t(kReached), 5000);  // 001: interrupted
        const int32_t stopped = pos(h, 1);
        QVERIFY2(stopped > -1000 && stopped < -100, qPrintable(QString::number(stopped)));
        QTest::qWait(100);
        QCOMPARE(pos(h, 1), stopped);

        // H05-35 (2005h:24h) = 100 ms: not home in time -> ER.601 (EMCY 8610h, vendor 0601h).
        QVERIFY(h.download(1, 0x2005, 0x24, SimHarness::u16(100)).ok());
        QVERIFY(h.download(1, 0x6099, 1, SimHarness::u32(500)).ok());
        h.clear();
        QVERIFY(cw(h, 1, 0x1F));
        auto e = h.waitFor([](const CanFrame& f) { return f.id == 0x81 && f.data[0] == 0x10; }, 3000);
        QVERIFY(e);
        QCOMPARE(QByteArray(reinterpret_cast<const char*>(e->data.data()), 5).toHex(),
                 QByteArray("1086") + QByteArray::number(e->data[2], 16).rightJustified(2, '0') + "0106");
        QTRY_COMPARE_WITH_TIMEOUT(sw(h, 1) & 0x4F, 0x08u, 2000);
    }

    void aimotorHardStop37() {
        SimHarness h;
        QString err;
        QVERIFY2(h.open(QStringLiteral("1:aimotor"), &err), qPrintable(err));
        QVERIFY(h.download(1, 0x6060, 0, SimHarness::u8(6)).ok());
        QVERIFY(h.download(1, 0x6098, 0, SimHarness::u8(37)).ok());
        QVERIFY(h.download(1, 0x6099, 2, SimHarness::u32(3000)).ok());    // hard stop runs at the slow speed
        QVERIFY(h.download(1, 0x2005, 0x3B, SimHarness::u16(300)).ok());  // H05-58 torque limit, 30 %
        QVERIFY(enable(h, 1));
        QVERIFY(cw(h, 1, 0x1F));
        bool sawLimit = false;
        QTRY_VERIFY_WITH_TIMEOUT((sawLimit |= int16_t(h.read(1, 0x6077, 0).value_or(0)) == 300, sw(h, 1) & kAck),
                                 10000);
        QVERIFY2(sawLimit, "6077h never showed the homing torque limit against the end stop");
        QVERIFY(sw(h, 1) & 0x8000);
        QCOMPARE(pos(h, 1), 0);
        QVERIFY2(std::abs(machine(h, 1) - 1200.0) < 1.0,
                 qPrintable(QString::number(machine(h, 1))));  // end stop at +1.2 rev
    }

    void deltaAndGenericRefuseOnWrite_data() {
        QTest::addColumn<QString>("dictionary");
        QTest::addColumn<int>("method");
        QTest::addColumn<uint32_t>("abort");
        QTest::newRow("delta reserved 15") << "delta-asda-a2" << 15 << canopen::sdoabort::InvalidValue;
        QTest::newRow("delta reserved 32") << "delta-asda-a2" << 32 << canopen::sdoabort::InvalidValue;
        QTest::newRow("delta 36 above range") << "delta-asda-a2" << 36 << canopen::sdoabort::ValueTooHigh;
        QTest::newRow("delta 35") << "delta-asda-a2" << 35 << 0u;
        QTest::newRow("generic reserved 36") << "generic-cia402" << 36 << canopen::sdoabort::InvalidValue;
        QTest::newRow("generic manufacturer -1") << "generic-cia402" << -1 << canopen::sdoabort::InvalidValue;
        QTest::newRow("generic 37") << "generic-cia402" << 37 << 0u;
    }
    void deltaAndGenericRefuseOnWrite() {
        QFETCH(QString, dictionary);
        QFETCH(int, method);
        QFETCH(uint32_t, abort);
        SimHarness h;
        QString err;
        QVERIFY2(h.open(QStringLiteral("1:") + dictionary, &err), qPrintable(err));
        QCOMPARE(h.download(1, 0x6098, 0, SimHarness::u8(uint8_t(method))).abort, abort);
    }

    void currentPositionDoesNotMove_data() {
        QTest::addColumn<QString>("dictionary");
        QTest::addColumn<int>("method");
        QTest::newRow("delta 35") << "delta-asda-a2" << 35;
        QTest::newRow("generic 35") << "generic-cia402" << 35;
        QTest::newRow("generic 37") << "generic-cia402" << 37;  // CiA 402-2: 37 = current position
    }
    void currentPositionDoesNotMove() {
        QFETCH(QString, dictionary);
        QFETCH(int, method);
        SimHarness h;
        QString err;
        QVERIFY2(h.open(QStringLiteral("1:") + dictionary, &err), qPrintable(err));
        QVERIFY(h.download(1, 0x6060, 0, SimHarness::u8(6)).ok());
        QVERIFY(h.download(1, 0x6098, 0, SimHarness::u8(uint8_t(method))).ok());
        QVERIFY(h.download(1, 0x607C, 0, SimHarness::u32(1234)).ok());
        QVERIFY(enable(h, 1));
        const double before = machine(h, 1);
        QVERIFY(cw(h, 1, 0x1F));
        QCOMPARE(sw(h, 1) & (kAck | kError | kReached), uint32_t(kAck | kReached));  // 011: attained at once
        QCOMPARE(pos(h, 1), 1234);                                                   // 6064h = home offset
        QCOMPARE(machine(h, 1), before);
        QVERIFY(!(sw(h, 1) & 0x8000));  // no "home found" bit outside AIMOTOR
    }

    void switchMethodTravelsAndBacksOff_data() {
        QTest::addColumn<QString>("dictionary");
        QTest::addColumn<int>("method");
        QTest::addColumn<double>("home");      // machine position of home (HomingMachine conventions)
        QTest::addColumn<double>("farthest");  // a machine position passed on the way
        // Generic, 10000 inc/rev: 1 = negative limit switch (-1 rev), back to the index at -0.9 rev.
        QTest::newRow("generic 1") << "generic-cia402" << 1 << -9000.0 << -9500.0;
        // 9: home cam (+0.20..+0.35 rev) upper edge, index below it (+0.10 rev), via +0.35 rev.
        QTest::newRow("generic 9") << "generic-cia402" << 9 << 1000.0 << 3400.0;
        // 11: negative start, the negative limit switch reverses, index above the upper edge (+1.1 rev).
        QTest::newRow("generic 11") << "generic-cia402" << 11 << 11000.0 << -9500.0;
        // Delta, 1280000 PUU/rev: 19 = positive home switch edge (+0.2 rev) reached from below.
        QTest::newRow("delta 19") << "delta-asda-a2" << 19 << 256000.0 << 256000.0;
        // AIMOTOR, 1000 pulses/rev: 24 = through the home switch, back onto its far edge (+0.35 rev).
        QTest::newRow("aimotor 24") << "aimotor" << 24 << 350.0 << 360.0;
    }
    void switchMethodTravelsAndBacksOff() {
        QFETCH(QString, dictionary);
        QFETCH(int, method);
        QFETCH(double, home);
        QFETCH(double, farthest);
        SimHarness h;
        QString err;
        QVERIFY2(h.open(QStringLiteral("1:") + dictionary, &err), qPrintable(err));
        const bool delta = dictionary == u"delta-asda-a2";
        // Fast enough for a test: Delta 200/50 rpm (0.1 rpm units, its highest), ramp 20 ms to 3000 rpm.
        QVERIFY(h.download(1, 0x6099, 1, SimHarness::u32(delta ? 2000 : dictionary == u"aimotor" ? 2000 : 50000)).ok());
        QVERIFY(h.download(1, 0x6099, 2, SimHarness::u32(delta ? 500 : dictionary == u"aimotor" ? 500 : 10000)).ok());
        QVERIFY(h.download(1, 0x609A, 0, SimHarness::u32(delta ? 20 : dictionary == u"aimotor" ? 20000 : 500000)).ok());
        QVERIFY(h.download(1, 0x607C, 0, SimHarness::u32(250)).ok());
        QVERIFY(h.download(1, 0x6060, 0, SimHarness::u8(6)).ok());
        QVERIFY(h.download(1, 0x6098, 0, SimHarness::u8(uint8_t(method))).ok());
        QVERIFY(enable(h, 1));
        QVERIFY(cw(h, 1, 0x1F));
        QTRY_VERIFY_WITH_TIMEOUT(sw(h, 1) & kAck, 20000);
        // How far it went, as the drive's model recorded it (sampling from here misses the
        // turning point on a loaded machine).
        double lo = 0, hi = 0;
        h.withDevice(1, [&](sim::VirtualDevice& d) { std::tie(lo, hi) = d.drive(0)->homingTravel(); });
        QCOMPARE(sw(h, 1) & (kAck | kError | kReached), uint32_t(kAck | kReached));
        QCOMPARE(pos(h, 1), 250);
        QVERIFY2(std::abs(machine(h, 1) - home) < 1.0, qPrintable(QString::number(machine(h, 1))));
        QVERIFY2(farthest < 0 ? lo <= farthest : hi >= farthest,
                 qPrintable(QStringLiteral("%1 .. %2").arg(lo).arg(hi)));
        // Homing again from there finds the same place: the switches are the machine's.
        QVERIFY(cw(h, 1, 0x0F));
        QVERIFY(cw(h, 1, 0x1F));
        QTRY_VERIFY_WITH_TIMEOUT(sw(h, 1) & kAck, 20000);
        QVERIFY2(std::abs(machine(h, 1) - home) < 1.0, qPrintable(QString::number(machine(h, 1))));
    }

    void deltaPairsBehaveTheSame() {
        // Delta §4.6: 19 = 20, ..., 29 = 30 (unlike CiA 402-2, where the pairs differ).
        const auto& delta = canopen::homing::drive(QStringLiteral("delta-asda-a2"));
        const auto& cia = canopen::homing::cia402();
        for (int n : {20, 22, 24, 26, 28, 30}) {
            QCOMPARE(int(delta.method(n)->sameAs), n - 1);
            QCOMPARE(delta.method(n)->homeSide, delta.method(n - 1)->homeSide);
            QVERIFY(cia.method(n)->homeSide != cia.method(n - 1)->homeSide ||
                    cia.method(n)->edge != cia.method(n - 1)->edge ||
                    cia.method(n)->switchSide != cia.method(n - 1)->switchSide);
        }
        QCOMPARE(delta.numbers(), QStringLiteral("1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 17, 18, 19, 20, 21, "
                                                 "22, 23, 24, 25, 26, 27, 28, 29, 30, 33, 34, 35"));
        QCOMPARE(canopen::homing::drive(QStringLiteral("aimotor")).numbers(),
                 QStringLiteral("1, 2, 4, 6, 17, 18, 24, 28, 33, 34, 35, 37, 38"));
    }

    void profilePositionSetPointHandshake() {
        SimHarness h;
        QString err;
        QVERIFY2(h.open(QStringLiteral("1:generic-cia402"), &err), qPrintable(err));
        QVERIFY(h.download(1, 0x6060, 0, SimHarness::u8(1)).ok());
        QVERIFY(h.download(1, 0x6081, 0, SimHarness::u32(2000)).ok());
        QVERIFY(h.download(1, 0x607A, 0, SimHarness::u32(1000)).ok());
        QVERIFY(enable(h, 1));
        QCOMPARE(sw(h, 1) & (kAck | kReached), uint32_t(kReached));
        // Bit 4 rising: the set-point is taken (bit 12), the move starts (bit 10 off).
        QVERIFY(cw(h, 1, 0x1F));
        QCOMPARE(sw(h, 1) & (kAck | kReached), uint32_t(kAck));
        QVERIFY(cw(h, 1, 0x0F));
        QCOMPARE(sw(h, 1) & kAck, 0u);  // bit 4 low: acknowledge falls
        // A second set-point while moving (single set-point): buffered, acknowledged, and the
        // acknowledge stays while it waits, even with bit 4 low (CiA 402-2 §12.2).
        QVERIFY(h.download(1, 0x607A, 0, SimHarness::u32(3000)).ok());
        QVERIFY(cw(h, 1, 0x1F));
        QVERIFY(sw(h, 1) & kAck);
        QVERIFY(cw(h, 1, 0x0F));
        QVERIFY(sw(h, 1) & kAck);
        // A third one is not taken while the buffer is full.
        QVERIFY(h.download(1, 0x607A, 0, SimHarness::u32(uint32_t(-5000))).ok());
        QVERIFY(cw(h, 1, 0x1F));
        QVERIFY(cw(h, 1, 0x0F));
        QVERIFY(pos(h, 1) < 1000);
        QTRY_VERIFY_WITH_TIMEOUT((sw(h, 1) & (kAck | kReached)) == kReached && pos(h, 1) == 3000, 10000);
        // Relative (bit 6) to the last target, then change set immediately (bit 5).
        QVERIFY(h.download(1, 0x607A, 0, SimHarness::u32(uint32_t(-500))).ok());
        QVERIFY(cw(h, 1, 0x4F));
        QVERIFY(cw(h, 1, 0x5F));
        QVERIFY(cw(h, 1, 0x4F));
        QTRY_VERIFY_WITH_TIMEOUT((sw(h, 1) & kReached) && pos(h, 1) == 2500, 10000);
        QVERIFY(h.download(1, 0x607A, 0, SimHarness::u32(0)).ok());
        QVERIFY(cw(h, 1, 0x1F));
        QVERIFY(cw(h, 1, 0x0F));
        QTRY_VERIFY_WITH_TIMEOUT(pos(h, 1) < 2300, 5000);
        QVERIFY(h.download(1, 0x607A, 0, SimHarness::u32(2400)).ok());
        QVERIFY(cw(h, 1, 0x3F));  // immediately: turns back at once
        QVERIFY(cw(h, 1, 0x2F));
        QTRY_VERIFY_WITH_TIMEOUT((sw(h, 1) & kReached) && pos(h, 1) == 2400, 10000);
        // Halt (bit 8) stops on the ramp with target reached = standing still.
        QVERIFY(h.download(1, 0x607A, 0, SimHarness::u32(0)).ok());
        QVERIFY(cw(h, 1, 0x1F));
        QVERIFY(cw(h, 1, 0x10F));
        QTRY_VERIFY_WITH_TIMEOUT(sw(h, 1) & kReached, 5000);
        QVERIFY(pos(h, 1) > 0);
    }
};

QTEST_GUILESS_MAIN(TestSimHoming)
#include "test_sim_homing.moc"
