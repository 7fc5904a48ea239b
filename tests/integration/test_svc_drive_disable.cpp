// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 35 "Safety edges", core side: the bus's record of the drives CoScope enabled (fed by the
// controlwords Ds402Controller writes) and the last word before a bus closes
// (canopen::disableEnabledDrives): Disable voltage — Quick stop first to a drive that may be
// moving — sent, its own Tx copy seen, the drive's answer awaited, all within a bounded wait;
// a silent or refusing drive and a listen-only bus are reported, never waited on for ever.
#include "SvcTestRig.h"

#include "core/canopen/DriveDisable.h"
#include "core/canopen/Ds402Controller.h"
#include "core/canopen/SdoClient.h"
#include "core/canopen/ServiceWait.h"
#include "core/sim/Ds402Drive.h"
#include "core/sim/VirtualDevice.h"

#include <QElapsedTimer>
#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;
using namespace svctest;
using ds402::State;

namespace {
Ds402Result wait(const std::function<void(Ds402Callback)>& start) {
    auto r = waitForResult<Ds402Result>(start, 30000);
    return r ? *r : Ds402Result{};
}
State driveState(Rig& rig, uint8_t node) {
    State s = State::Unknown;
    rig.onDevice(node, [&](sim::VirtualDevice& d) { s = d.drive(0)->state(); });
    return s;
}
uint16_t controlwordOf(const CanFrame& f) { return uint16_t(f.data[4] | (f.data[5] << 8)); }
}  // namespace

class TestSvcDriveDisable : public QObject {
    Q_OBJECT
private slots:
    // Enabled by the controller: recorded (may move); closing sends Quick stop then Disable
    // voltage, both seen and confirmed; the drive is in Switch on disabled; the record is empty.
    void enabledDriveIsDisabledBeforeTheBusCloses() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("3:generic-cia402")));
        QVERIFY(rig.open());
        {
            SdoClient sdo(*rig.context);
            Ds402Controller ctl(sdo, 3);
            const Ds402Result r = wait([&](auto cb) { ctl.enable(cb); });
            QVERIFY2(r.ok, qPrintable(r.error));
        }  // the SDO client is gone, as when a workspace closes
        const auto drives = rig.context->enabledDrives().drives();
        QCOMPARE(drives.size(), size_t(1));
        QCOMPARE(drives[0].node, uint8_t(3));
        QVERIFY(drives[0].mayMove());
        QCOMPARE(driveState(rig, 3), State::OperationEnabled);
        QElapsedTimer t;
        t.start();
        const DriveDisableOutcome out = disableEnabledDrives(*rig.context, 500);
        QVERIFY(t.elapsed() < 500);
        QCOMPARE(out.drives.size(), size_t(1));
        QVERIFY2(out.allSeen() && out.drives[0].answered, qPrintable(out.summary()));
        QVERIFY(out.drives[0].quickStopSent);
        QVERIFY(rig.context->enabledDrives().isEmpty());
        QCOMPARE(driveState(rig, 3), State::SwitchOnDisabled);
    }

    // The controller's own Disable takes the drive off the record.
    void disableByTheControllerForgetsTheDrive() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("3:generic-cia402")));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        Ds402Controller ctl(sdo, 3);
        QVERIFY(wait([&](auto cb) { ctl.transition(ds402::Command::Shutdown, cb); }).ok);
        QVERIFY(!rig.context->enabledDrives().isEmpty());
        QVERIFY(!rig.context->enabledDrives().drives()[0].mayMove());
        QVERIFY(wait([&](auto cb) { ctl.disable(cb); }).ok);
        QVERIFY(rig.context->enabledDrives().isEmpty());
        QVERIFY(disableEnabledDrives(*rig.context).drives.empty());  // nothing to send
    }

    // A drive that acknowledges frames on the bus but never answers: the request is seen going
    // out (so it is in the trace), the missing answer reported, the wait bounded. No Quick stop:
    // it was only switched on.
    void silentDriveIsReportedWithinTheBound() {
        Rig rig;
        ScriptedNode* n = rig.addNode(5);
        QVERIFY(rig.open());
        rig.context->enabledDrives().noteControlword(5, 0, 0x0007);
        QElapsedTimer t;
        t.start();
        const DriveDisableOutcome out = disableEnabledDrives(*rig.context, 300);
        QVERIFY(t.elapsed() < 1000);
        QVERIFY2(out.allSeen() && !out.drives[0].answered, qPrintable(out.summary()));
        QVERIFY2(out.drives[0].error.contains(QStringLiteral("did not confirm")), qPrintable(out.drives[0].error));
        const auto seen = n->seen();
        QCOMPARE(seen.size(), size_t(1));
        QCOMPARE(controlwordOf(seen[0]), uint16_t(0x0000));
        QCOMPARE(bytesOf(seen[0]), hex("2B40600000000000"));
        QVERIFY(rig.context->enabledDrives().isEmpty());  // seen: it went out
    }

    // A refusal (SDO abort) is named; axis 1 uses 6840h (CiA 402-2 §5.2).
    void refusalIsNamed() {
        Rig rig;
        ScriptedNode* n = rig.addNode(6);
        n->setScript([](const CanFrame& in, ScriptedNode& node) {
            node.reply({0x80, in.data[1], in.data[2], in.data[3], 0x00, 0x00, 0x02, 0x08});
        });
        QVERIFY(rig.open());
        rig.context->enabledDrives().noteControlword(6, 1, 0x000F);
        const DriveDisableOutcome out = disableEnabledDrives(*rig.context, 400);
        QVERIFY2(out.allSeen() && !out.drives[0].answered && out.drives[0].error.contains(QStringLiteral("refused")),
                 qPrintable(out.summary()));
        const auto seen = n->seen();
        QCOMPARE(seen.size(), size_t(2));  // Quick stop, then Disable voltage
        QCOMPARE(bytesOf(seen[0]), hex("2B40680002000000"));
        QCOMPARE(bytesOf(seen[1]), hex("2B40680000000000"));
    }

    // Listen-only: nothing is sent, it says so at once.
    void listenOnlySendsNothing() {
        Rig rig;
        ScriptedNode* n = rig.addNode(5);
        QVERIFY(rig.open(QStringLiteral("sim://?listen-only=1")));
        rig.context->enabledDrives().noteControlword(5, 0, 0x000F);
        const DriveDisableOutcome out = disableEnabledDrives(*rig.context, 500);
        QVERIFY(!out.allSeen());
        QVERIFY2(out.drives[0].error.contains(QStringLiteral("listen-only")), qPrintable(out.drives[0].error));
        QTest::qWait(50);
        QVERIFY(n->seen().empty());
        QVERIFY(!rig.context->enabledDrives().isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestSvcDriveDisable)
#include "test_svc_drive_disable.moc"
