// SPDX-License-Identifier: GPL-3.0-or-later
// Ds402Controller::home() and moveTo() against the virtual drives: homing on the current
// position (35) on each drive, a switch method moving and ending at the home offset, a method
// the drive lacks refused as its manual says (Delta: SDO abort; AIMOTOR: Er.668), AIMOTOR hard
// stop 37, profile position moves absolute and relative with the set-point handshake, and a
// stop (halt, quick stop) at any time.
#include "SvcTestRig.h"

#include "core/canopen/Ds402Controller.h"
#include "core/canopen/HomingMethods.h"
#include "core/canopen/ServiceWait.h"
#include "core/sim/Ds402Drive.h"
#include "core/sim/VirtualDevice.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;
using namespace svctest;
using ds402::State;

namespace {
struct Run {
    Ds402Result result;
    std::vector<Ds402MotionSample> samples;
    QStringList sent;
};
State driveState(Rig& rig, uint8_t node) {
    State s = State::Unknown;
    rig.onDevice(node, [&](sim::VirtualDevice& d) { s = d.drive(0)->state(); });
    return s;
}
double machine(Rig& rig, uint8_t node) {
    double m = 0;
    rig.onDevice(node, [&](sim::VirtualDevice& d) { m = d.drive(0)->machinePosition(); });
    return m;
}
int32_t position(Rig& rig, uint8_t node) {
    int32_t p = 0;
    rig.onDevice(node, [&](sim::VirtualDevice& d) { p = int32_t(std::llround(d.drive(0)->position())); });
    return p;
}
const char* dictionaryOf(uint8_t node) {
    return node == 1 ? "delta-asda-a2" : node == 2 ? "aimotor" : "generic-cia402";
}
}  // namespace

class TestSvcDs402Motion : public QObject {
    Q_OBJECT
    std::unique_ptr<Rig> rig_;
    std::unique_ptr<SdoClient> sdo_;

    Run home(uint8_t node, const Ds402HomingRequest& req) {
        Ds402Controller ctl(*sdo_, node);
        Run run;
        ctl.setSendObserver([&](const QString& s) { run.sent << s; });
        auto r = waitForResult<Ds402Result>(
            [&](Ds402Callback cb) {
                ctl.home(
                    req, [&](const Ds402MotionSample& s) { run.samples.push_back(s); }, cb);
            },
            60000);
        if (r) run.result = *r;
        else run.result.error = QStringLiteral("no result");
        return run;
    }
    Run moveTo(uint8_t node, const Ds402PositionMove& move) {
        Ds402Controller ctl(*sdo_, node);
        Run run;
        ctl.setSendObserver([&](const QString& s) { run.sent << s; });
        auto r = waitForResult<Ds402Result>(
            [&](Ds402Callback cb) {
                ctl.moveTo(
                    move, [&](const Ds402MotionSample& s) { run.samples.push_back(s); }, cb);
            },
            60000);
        if (r) run.result = *r;
        else run.result.error = QStringLiteral("no result");
        return run;
    }
    static Ds402HomingRequest request(uint8_t node, int8_t method) {
        Ds402HomingRequest req;
        req.method = method;
        req.methodOnlyWhileDisabled = homing::drive(QString::fromLatin1(dictionaryOf(node))).changeOnlyWhileDisabled;
        req.timeoutMs = 20000;
        return req;
    }

private slots:
    void init() {
        rig_ = std::make_unique<Rig>();
        QVERIFY(rig_->useSpec(QStringLiteral("1:delta-asda-a2,2:aimotor,3:generic-cia402")));
        QVERIFY(rig_->open());
        sdo_ = std::make_unique<SdoClient>(*rig_->context);
    }
    void cleanup() {
        sdo_.reset();
        rig_.reset();
    }

    void homeOnCurrentPositionEachDrive_data() {
        QTest::addColumn<int>("node");
        QTest::newRow("delta") << 1;
        QTest::newRow("aimotor") << 2;
        QTest::newRow("generic") << 3;
    }
    void homeOnCurrentPositionEachDrive() {
        QFETCH(int, node);
        const double before = machine(*rig_, uint8_t(node));
        Ds402HomingRequest req = request(uint8_t(node), 35);
        req.offset = 500;
        const Run run = home(uint8_t(node), req);
        QVERIFY2(run.result.ok, qPrintable(run.result.error));
        QVERIFY(run.result.statusword & (1u << 12));  // homing attained
        QVERIFY(run.result.statusword & (1u << 10));
        QCOMPARE(machine(*rig_, uint8_t(node)), before);  // no movement
        QCOMPARE(position(*rig_, uint8_t(node)), 500);    // 6064h = home offset
        // 6060h = 6, the parameters, 06 07 0F, then 0F -> 1F and bit 4 low again at the end.
        const QString all = run.sent.join(u'\n');
        QVERIFY2(all.contains(QStringLiteral("6060h = 6")) && all.contains(QStringLiteral("6098h = 35")) &&
                     all.contains(QStringLiteral("607Ch = 500")),
                 qPrintable(all));
        QVERIFY2(run.sent.size() >= 3 && run.sent[run.sent.size() - 2].contains(QStringLiteral("6040h = 0x001F")),
                 qPrintable(all));
        QVERIFY2(run.sent.back().contains(QStringLiteral("6040h = 0x000F")), qPrintable(all));
        QCOMPARE(driveState(*rig_, uint8_t(node)), State::OperationEnabled);  // stays enabled, homed
    }

    void homeWithSwitchMethodMovesThenOffset_data() {
        QTest::addColumn<int>("node");
        QTest::addColumn<int>("method");
        QTest::addColumn<double>("homeAt");  // machine position (HomingMachine conventions)
        QTest::newRow("delta 17: negative limit switch") << 1 << 17 << -1280000.0;
        QTest::newRow("aimotor 1: negative overtravel, Z") << 2 << 1 << -900.0;
        QTest::newRow("generic 4: positive home switch, index above") << 3 << 4 << 11000.0;
    }
    void homeWithSwitchMethodMovesThenOffset() {
        QFETCH(int, node);
        QFETCH(int, method);
        QFETCH(double, homeAt);
        Ds402HomingRequest req = request(uint8_t(node), int8_t(method));
        req.offset = -250;
        // Delta: 0.1 rpm and ms to 3000 rpm; AIMOTOR pulse/s; generic inc/s.
        req.fastSpeed = node == 1 ? 2000 : node == 2 ? 3000 : 50000;
        req.slowSpeed = node == 1 ? 500 : node == 2 ? 500 : 10000;
        req.acceleration = node == 1 ? 20 : node == 2 ? 30000 : 500000;
        const Run run = home(uint8_t(node), req);
        QVERIFY2(run.result.ok, qPrintable(run.result.error));
        QVERIFY(run.result.statusword & (1u << 12));
        QCOMPARE(position(*rig_, uint8_t(node)), -250);
        QVERIFY2(std::abs(machine(*rig_, uint8_t(node)) - homeAt) < 1.0,
                 qPrintable(QString::number(machine(*rig_, uint8_t(node)))));
        // The progress showed the motor on its way (in progress: bits 12/13 off, moving).
        bool moving = false;
        for (const auto& s : run.samples) moving |= s.velocity != 0 && !(s.statusword & (3u << 12));
        QVERIFY2(moving && run.samples.size() >= 3, qPrintable(QString::number(run.samples.size())));
    }

    void unsupportedMethodRefused_data() {
        QTest::addColumn<int>("node");
        QTest::addColumn<int>("method");
        QTest::addColumn<QString>("why");
        // Delta: a reserved method's write is aborted (invalid value, 0609 0030h).
        QTest::newRow("delta 15") << 1 << 15 << QStringLiteral("6098h = 15 (homing method) refused");
        // AIMOTOR: taken, then Er.668 homing method mismatch when homing starts (EMCY FF00h).
        QTest::newRow("aimotor 3") << 2 << 3 << QStringLiteral("603Fh = FF00h");
        // Generic: CiA 402-2 has no method 36.
        QTest::newRow("generic 36") << 3 << 36 << QStringLiteral("6098h = 36 (homing method) refused");
    }
    void unsupportedMethodRefused() {
        QFETCH(int, node);
        QFETCH(int, method);
        QFETCH(QString, why);
        const Run run = home(uint8_t(node), request(uint8_t(node), int8_t(method)));
        QVERIFY(!run.result.ok);
        QVERIFY2(run.result.error.contains(why), qPrintable(run.result.error));
        QVERIFY2(run.result.error.contains(QStringLiteral("drive disabled")), qPrintable(run.result.error));
        QVERIFY2(run.sent.back().contains(QStringLiteral("6040h = 0x0000")), qPrintable(run.sent.join(u'\n')));
        // Disabled, or in Fault after the vendor alarm (past its fault reaction).
        QTRY_VERIFY_WITH_TIMEOUT(driveState(*rig_, uint8_t(node)) == State::SwitchOnDisabled ||
                                     driveState(*rig_, uint8_t(node)) == State::Fault,
                                 2000);
    }

    void aimotorHardStopAndMethodChangeWhileEnabled() {
        // Enabled with method 35 first; 37 needs a disabled drive: home() shuts down first.
        QVERIFY2(home(2, request(2, 35)).result.ok, "home 35");
        QCOMPARE(driveState(*rig_, 2), State::OperationEnabled);
        Ds402HomingRequest req = request(2, 37);
        req.slowSpeed = 3000;
        const Run run = home(2, req);
        QVERIFY2(run.result.ok, qPrintable(run.result.error));
        QVERIFY2(run.sent.join(u'\n').contains(QStringLiteral("6040h = 0x0006 (Shutdown)")),
                 qPrintable(run.sent.join(u'\n')));
        QVERIFY(run.result.statusword & 0x8000);  // home found
        QCOMPARE(position(*rig_, 2), 0);
        QVERIFY2(std::abs(machine(*rig_, 2) - 1200.0) < 1.0, qPrintable(QString::number(machine(*rig_, 2))));
    }

    void profilePositionMoves_data() {
        QTest::addColumn<int>("node");
        QTest::newRow("delta") << 1;
        QTest::newRow("aimotor") << 2;
        QTest::newRow("generic") << 3;
    }
    void profilePositionMoves() {
        QFETCH(int, node);
        Ds402PositionMove move;
        move.target = 1000;
        move.velocity = 5000;
        Run run = moveTo(uint8_t(node), move);
        QVERIFY2(run.result.ok, qPrintable(run.result.error));
        QVERIFY(run.result.statusword & (1u << 10));  // target reached
        QCOMPARE(position(*rig_, uint8_t(node)), 1000);
        const QString all = run.sent.join(u'\n');
        QVERIFY2(all.contains(QStringLiteral("6040h = 0x001F (New set-point")) &&
                     run.sent.back().contains(QStringLiteral("6040h = 0x000F")),
                 qPrintable(all));
        // Relative: from the last target.
        move.relative = true;
        run = moveTo(uint8_t(node), move);
        QVERIFY2(run.result.ok, qPrintable(run.result.error));
        QCOMPARE(position(*rig_, uint8_t(node)), 2000);
        QVERIFY2(run.sent.join(u'\n').contains(QStringLiteral("6040h = 0x005F")), qPrintable(run.sent.join(u'\n')));
    }

    void stopAtAnyTime_data() {
        QTest::addColumn<bool>("quick");
        QTest::addColumn<bool>("homing");
        QTest::newRow("halt homing") << false << true;
        QTest::newRow("quick stop homing") << true << true;
        QTest::newRow("halt move") << false << false;
    }
    void stopAtAnyTime() {
        QFETCH(bool, quick);
        QFETCH(bool, homing);
        Ds402Controller ctl(*sdo_, 3);
        Ds402Result result;
        bool done = false;
        int samples = 0;
        auto progress = [&](const Ds402MotionSample&) {
            if (++samples == 3) ctl.stopMotion(quick, QStringLiteral("operator"));
        };
        auto finished = [&](const Ds402Result& r) { result = r, done = true; };
        if (homing) {
            Ds402HomingRequest req = request(3, 1);  // negative limit switch: a long way
            req.fastSpeed = 2000;
            ctl.home(req, progress, finished);
        } else {
            Ds402PositionMove move;
            move.target = 100000;
            move.velocity = 2000;
            ctl.moveTo(move, progress, finished);
        }
        QVERIFY(waitUntil([&] { return done; }, 20000));
        QVERIFY(!result.ok);
        QCOMPARE(result.stopReason, QStringLiteral("operator"));
        QVERIFY2(result.error.contains(QStringLiteral("stopped (operator)")), qPrintable(result.error));
        QVERIFY(!ctl.motionActive());
        const double still = machine(*rig_, 3);
        QTest::qWait(100);
        QCOMPARE(machine(*rig_, 3), still);
        QVERIFY(std::abs(still) > 10 && std::abs(still) < 9000);  // moved, stopped short
        QCOMPARE(driveState(*rig_, 3), quick ? State::SwitchOnDisabled : State::OperationEnabled);
    }

    void statuswordBitNamesFollowTheMode() {
        QCOMPARE(ds402::statuswordBitName(12, int8_t(6)), QStringLiteral("homing attained"));
        QCOMPARE(ds402::statuswordBitName(13, int8_t(6)), QStringLiteral("homing error"));
        QCOMPARE(ds402::statuswordBitName(10, int8_t(6)), QStringLiteral("target reached"));
        QCOMPARE(ds402::statuswordBitName(12, int8_t(1)), QStringLiteral("set-point acknowledge"));
        QCOMPARE(ds402::statuswordBitName(13, int8_t(1)), QStringLiteral("following error"));
        QCOMPARE(ds402::statuswordBitName(12, std::nullopt), QStringLiteral("operation mode specific (bit 12)"));
        QCOMPARE(ds402::statuswordBits(0x1637, int8_t(6)).last(), QStringLiteral("homing attained"));
    }
};

QTEST_GUILESS_MAIN(TestSvcDs402Motion)
#include "test_svc_ds402_motion.moc"
