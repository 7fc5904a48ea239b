// SPDX-License-Identifier: GPL-3.0-or-later
// The CiA 402 drive model and the vendor personalities of the virtual drives.
#include "SimTestHarness.h"

#include "core/canopen/SdoAbort.h"
#include "core/sim/Ds402Drive.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::testing;

class TestSimDs402 : public QObject {
    Q_OBJECT
    static uint32_t sw(SimHarness& h, uint8_t node) { return h.read(node, 0x6041, 0).value_or(0xFFFF); }
    static bool cw(SimHarness& h, uint8_t node, uint16_t v) {
        return h.download(node, 0x6040, 0, SimHarness::u16(v)).ok();
    }

private slots:
    void initTestCase() { eds::installSimulatorDictionaries(); }

    void stateMachineWalk_data() {
        QTest::addColumn<QString>("dictionary");
        QTest::addColumn<QString>("fault");    // alarm name injected
        QTest::addColumn<QByteArray>("emcy");  // expected EMCY bytes 0-1 and 3-7
        QTest::newRow("delta") << "delta-asda-a2"
                               << "AL011"
                               << QByteArray::fromHex(
                                      "0573"
                                      "1100000000");
        QTest::newRow("aimotor") << "aimotor"
                                 << "Er.B00"
                                 << QByteArray::fromHex(
                                        "1186"
                                        "000B000000");
        QTest::newRow("generic") << "generic-cia402"
                                 << "overcurrent"
                                 << QByteArray::fromHex(
                                        "1023"
                                        "0000000000");
    }
    void stateMachineWalk() {
        QFETCH(QString, dictionary);
        QFETCH(QString, fault);
        QFETCH(QByteArray, emcy);
        SimHarness h;
        QString err;
        QVERIFY2(h.open(QStringLiteral("7:") + dictionary, &err), qPrintable(err));
        const uint8_t n = 7;
        // Statusword per state (CiA 402-2 Table 30, bits 0-3, 5, 6 under mask 6Fh).
        QCOMPARE(sw(h, n) & 0x6F, 0x40u);  // switch on disabled
        QVERIFY(cw(h, n, 0x06));
        QCOMPARE(sw(h, n) & 0x6F, 0x21u);  // ready to switch on
        QVERIFY(cw(h, n, 0x07));
        QCOMPARE(sw(h, n) & 0x6F, 0x23u);  // switched on
        QVERIFY(cw(h, n, 0x0F));
        QCOMPARE(sw(h, n) & 0x6F, 0x27u);  // operation enabled
        QVERIFY(sw(h, n) & 0x10);          // voltage enabled
        QVERIFY(sw(h, n) & 0x200);         // remote

        // Profile velocity: the motor speeds up and the position moves.
        QVERIFY(h.download(n, 0x6060, 0, SimHarness::u8(3)).ok());
        QCOMPARE(h.read(n, 0x6061, 0).value_or(0), 3u);
        QVERIFY(h.download(n, 0x60FF, 0, SimHarness::u32(5000)).ok());
        // However late the simulator's clock runs (a loaded machine skips its stalls): wait for
        // the motion itself, not for a time.
        int32_t v = 0, p = 0;
        QTRY_VERIFY_WITH_TIMEOUT((v = int32_t(h.read(n, 0x606C, 0).value_or(0))) > 1000 &&
                                     (p = int32_t(h.read(n, 0x6064, 0).value_or(0))) > 100,
                                 30000);
        QVERIFY2(v <= 5000, qPrintable(QString::number(v)));
        QVERIFY2(p > 100, qPrintable(QString::number(p)));

        // Quick stop (0002h) from operation enabled: quick stop active, then switch on disabled.
        QVERIFY(cw(h, n, 0x02));
        QTRY_COMPARE_WITH_TIMEOUT(sw(h, n) & 0x6F, 0x40u, 2000);
        QVERIFY(cw(h, n, 0x06));
        QVERIFY(cw(h, n, 0x0F));
        QCOMPARE(sw(h, n) & 0x6F, 0x27u);

        // Fault injection: EMCY with the vendor layout, 603Fh, statusword fault.
        h.clear();
        bool injected = false;
        h.withDevice(n, [&](sim::VirtualDevice& d) { injected = d.injectDriveFault(fault); });
        QVERIFY(injected);
        auto e = h.waitFor([](const CanFrame& f) { return f.id == 0x87; }, 500);
        QVERIFY(e);
        QCOMPARE(int(e->len), 8);
        const QByteArray got = QByteArray(reinterpret_cast<const char*>(e->data.data()), 2) +
                               QByteArray(reinterpret_cast<const char*>(e->data.data() + 3), 5);
        QCOMPARE(got.toHex(), emcy.toHex());
        QVERIFY(e->data[2] & 0x01);                               // error register: generic error
        QTRY_COMPARE_WITH_TIMEOUT(sw(h, n) & 0x4F, 0x08u, 1000);  // fault
        QCOMPARE(h.read(n, 0x603F, 0).value_or(0), uint32_t(uint8_t(emcy[0]) | uint8_t(emcy[1]) << 8));
        QVERIFY(!cw(h, n, 0x0F) || (sw(h, n) & 0x4F) == 0x08);  // enable does nothing in fault
        // Fault reset on the rising edge of bit 7: switch on disabled and the error-reset EMCY.
        QVERIFY(cw(h, n, 0x00));
        h.clear();
        QVERIFY(cw(h, n, 0x80));
        QCOMPARE(sw(h, n) & 0x4F, 0x40u);
        auto reset = h.waitFor([](const CanFrame& f) { return f.id == 0x87; }, 500);
        QVERIFY(reset);
        QCOMPARE(int(reset->data[0] | reset->data[1]), 0);
        QCOMPARE(h.read(n, 0x603F, 0).value_or(1), 0u);
    }

    void profilePositionReachesTarget() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("3:generic-cia402"), &err));
        QVERIFY(h.download(3, 0x6060, 0, SimHarness::u8(1)).ok());
        QVERIFY(h.download(3, 0x6081, 0, SimHarness::u32(20000)).ok());
        QVERIFY(h.download(3, 0x607A, 0, SimHarness::u32(4000)).ok());
        for (uint16_t v : {0x06, 0x07, 0x0F, 0x1F}) QVERIFY(cw(h, 3, v));  // bit 4: new set-point
        QVERIFY(sw(h, 3) & 0x1000);                                        // set-point acknowledge
        QVERIFY(!(sw(h, 3) & 0x400));                                      // moving
        QTRY_VERIFY_WITH_TIMEOUT(sw(h, 3) & 0x400, 2000);                  // target reached
        QCOMPARE(int32_t(h.read(3, 0x6064, 0).value_or(0)), 4000);
    }

    void deltaAl401OnResetWhileEnabled() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("1:delta-asda-a2"), &err));
        for (uint16_t v : {0x06, 0x07, 0x0F}) QVERIFY(cw(h, 1, v));
        h.clear();
        h.send(CanFrame::classic(0x000, {0x81, 0x01}));
        // extract-delta §10: AL401 -> 081: 00 81 ER 01 04 00 00 00.
        auto e = h.waitFor([](const CanFrame& f) { return f.id == 0x81; }, 500);
        QVERIFY(e);
        QCOMPARE(e->data[0], uint8_t(0x00));
        QCOMPARE(e->data[1], uint8_t(0x81));
        QCOMPARE(e->data[3], uint8_t(0x01));
        QCOMPARE(e->data[4], uint8_t(0x04));
        QTRY_COMPARE_WITH_TIMEOUT(sw(h, 1) & 0x4F, 0x08u, 1000);
        // A reset while disabled is a plain reset: boot-up.
        QVERIFY(cw(h, 1, 0x00));
        QVERIFY(cw(h, 1, 0x80));
        h.clear();
        h.send(CanFrame::classic(0x000, {0x81, 0x01}));
        QVERIFY(h.waitFor([](const CanFrame& f) { return f.id == 0x701 && f.data[0] == 0; }, 500));
    }

    void deltaNodeIdAndBitRateParameters() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("1:delta-asda-a2"), &err));
        // P3-00 = 9 takes effect at the next power cycle / reset node ("●" parameter).
        QVERIFY(h.download(1, 0x2300, 0, SimHarness::u16(9)).ok());
        QVERIFY(h.upload(1, 0x1000, 0).ok());  // still node 1
        // P3-01 = 0403h: only digit Z (CAN bit rate) changes over CAN; 4 = 1 Mbit/s.
        QVERIFY(h.download(1, 0x2301, 0, SimHarness::u16(0x0403)).ok());
        QCOMPARE(h.read(1, 0x2301, 0).value_or(0), 0x0403u);  // factory 0203h: X stays 3
        h.send(CanFrame::classic(0x000, {0x81, 0x01}));
        QVERIFY(h.waitFor([](const CanFrame& f) { return f.id == 0x709 && f.data[0] == 0; }, 500));
        QVERIFY(h.upload(9, 0x1000, 0).ok());
        uint32_t rate = 0;
        h.withDevice(9, [&](sim::VirtualDevice& d) { rate = d.bitRate(); });
        QCOMPARE(rate, 1000000u);
        QCOMPARE(h.download(9, 0x2300, 0, SimHarness::u16(0)).abort != 0, true);  // range 1..127
    }

    void aimotorNeedsCanopenControlMode() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("2:aimotor"), &err));
        QCOMPARE(h.read(2, 0x2002, 1).value_or(0), 8u);  // H02-00 = 8 (commissioned)
        QVERIFY(h.download(2, 0x2002, 1, SimHarness::u16(0)).ok());
        QCOMPARE(h.download(2, 0x6040, 0, SimHarness::u16(6)).abort, canopen::sdoabort::LocalControl);
        QVERIFY(!(sw(h, 2) & 0x200));  // not remote
    }

    void dexmartMultiDrive() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("4:dexmart-dev"), &err));
        // M2 continuous run at 3000 rpm: Multi-Drive 3052h Data2 then CMD 0Ah (extract-dexmart §7).
        QVERIFY(h.download(4, 0x3052, 3, SimHarness::u16(3000)).ok());
        QVERIFY(h.download(4, 0x3052, 1, SimHarness::u16(0x0A)).ok());
        int16_t speed = 0;  // the motor speeds up, however late the simulator's clock runs
        QTRY_VERIFY_WITH_TIMEOUT((speed = int16_t(h.read(4, 0x304A, 5).value_or(0))) > 300, 30000);
        QVERIFY2(speed <= 3000, qPrintable(QString::number(speed)));
        QCOMPARE(h.read(4, 0x3046, 5).value_or(1), 0u);  // M1 untouched
        // A fault on M2: EMCY byte 7 carries the M2 alarm code.
        h.clear();
        h.withDevice(4, [](sim::VirtualDevice& d) { d.injectDriveFault(sim::DriveFault{0x2300, 0x05, 1}); });
        auto e = h.waitFor([](const CanFrame& f) { return f.id == 0x84; }, 500);
        QVERIFY(e);
        QCOMPARE(e->data[7], uint8_t(0x05));
        QCOMPARE(e->data[6], uint8_t(0x00));
    }
};

QTEST_GUILESS_MAIN(TestSimDs402)
#include "test_sim_ds402.moc"
