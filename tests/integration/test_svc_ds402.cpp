// SPDX-License-Identifier: GPL-3.0-or-later
// CiA 402 controller: enable and disable sequence on each virtual drive personality, a fault
// reset cycle, mode of operation set and verified, a failed enable leaving the drive disabled
// with the missing bit named, and the multi-axis offset.
#include "SvcTestRig.h"

#include "core/canopen/Ds402Controller.h"
#include "core/canopen/ServiceWait.h"
#include "core/sim/Ds402Drive.h"
#include "core/sim/VirtualDevice.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;
using namespace svctest;
using ds402::State;

namespace {
Ds402Result wait(const std::function<void(Ds402Callback)>& start) {
    auto r = waitForResult<Ds402Result>(start, 30000);
    if (!r) {
        Ds402Result none;
        none.error = QStringLiteral("no result");
        return none;
    }
    return *r;
}
State driveState(Rig& rig, uint8_t node) {
    State s = State::Unknown;
    rig.onDevice(node, [&](sim::VirtualDevice& d) {
        if (d.drive(0)) s = d.drive(0)->state();
    });
    return s;
}

// A scripted drive whose statusword never leaves Switch on disabled; it records 6040h writes.
struct StuckDrive {
    std::shared_ptr<std::vector<uint16_t>> controlwords = std::make_shared<std::vector<uint16_t>>();
    std::shared_ptr<uint16_t> readIndex = std::make_shared<uint16_t>(0);
    ScriptedNode::Script script() {
        auto cws = controlwords;
        auto idx = readIndex;
        return [cws, idx](const CanFrame& in, ScriptedNode& n) {
            const uint16_t index = uint16_t(in.data[1] | (in.data[2] << 8));
            if (in.data[0] == 0x40) {
                *idx = index;
                n.reply({0x4B, in.data[1], in.data[2], in.data[3], 0x40, 0x02, 0, 0});  // 0240h: switch on disabled
            } else if ((in.data[0] & 0xE0) == 0x20) {
                if ((index & 0x07FF) == 0x0040 && (index & 0xF000) == 0x6000)
                    cws->push_back(uint16_t(in.data[4] | (in.data[5] << 8)));
                n.reply({0x60, in.data[1], in.data[2], in.data[3], 0, 0, 0, 0});
            }
        };
    }
};
}  // namespace

class TestSvcDs402 : public QObject {
    Q_OBJECT
private slots:
    void enableDisableEachPersonality_data() {
        QTest::addColumn<QString>("dictionary");
        QTest::newRow("delta") << QStringLiteral("delta-asda-a2");
        QTest::newRow("aimotor") << QStringLiteral("aimotor");
        QTest::newRow("generic") << QStringLiteral("generic-cia402");
    }
    void enableDisableEachPersonality() {
        QFETCH(QString, dictionary);
        Rig rig;
        QString error;
        QVERIFY2(rig.useSpec(QStringLiteral("1:") + dictionary, &error), qPrintable(error));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        Ds402Controller ctl(sdo, 1);
        QStringList sent;
        ctl.setSendObserver([&](const QString& s) { sent << s; });

        Ds402Result r = wait([&](auto cb) { ctl.setMode(1, cb); });  // profile position
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.mode, int8_t(1));

        r = wait([&](auto cb) { ctl.enable(cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.state, State::OperationEnabled);
        QCOMPARE(driveState(rig, 1), State::OperationEnabled);
        // What was sent, in order (mode first, then shutdown, switch on, enable operation).
        QVERIFY2(sent.size() >= 4, qPrintable(sent.join(u'|')));
        QVERIFY(sent[sent.size() - 3].contains(QStringLiteral("6040h = 0x0006")));
        QVERIFY(sent[sent.size() - 2].contains(QStringLiteral("6040h = 0x0007")));
        QVERIFY(sent.back().contains(QStringLiteral("6040h = 0x000F")));

        r = wait([&](auto cb) { ctl.disable(cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.state, State::SwitchOnDisabled);
        QCOMPARE(driveState(rig, 1), State::SwitchOnDisabled);
    }

    void faultResetCycle() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("2:aimotor")));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        Ds402Controller ctl(sdo, 2);
        QVERIFY(wait([&](auto cb) { ctl.enable(cb); }).ok);
        rig.onDevice(2, [](sim::VirtualDevice& d) { d.injectDriveFault(); });
        QTRY_COMPARE_WITH_TIMEOUT(driveState(rig, 2), State::Fault, 3000);
        Ds402Result r = wait([&](auto cb) { ctl.readState(cb); });
        QCOMPARE(r.state, State::Fault);
        QStringList sent;
        ctl.setSendObserver([&](const QString& s) { sent << s; });
        r = wait([&](auto cb) { ctl.transition(ds402::Command::FaultReset, cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.state, State::SwitchOnDisabled);
        // A rising edge of bit 7: 0000h then 0080h.
        QCOMPARE(sent.size(), 2);
        QVERIFY(sent[0].contains(QStringLiteral("= 0x0000")));
        QVERIFY(sent[1].contains(QStringLiteral("= 0x0080")));
        // Fault again; enable goes through fault reset by itself.
        rig.onDevice(2, [](sim::VirtualDevice& d) { d.injectDriveFault(); });
        QTRY_COMPARE_WITH_TIMEOUT(driveState(rig, 2), State::Fault, 3000);
        r = wait([&](auto cb) { ctl.enable(cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(driveState(rig, 2), State::OperationEnabled);
        r = wait([&](auto cb) { ctl.transition(ds402::Command::QuickStop, cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        QVERIFY(r.state == State::QuickStopActive || r.state == State::SwitchOnDisabled);
        QCOMPARE(driveState(rig, 2), r.state);
        QVERIFY(wait([&](auto cb) { ctl.disable(cb); }).ok);
    }

    void failedEnableLeavesDriveDisabled() {
        Rig rig;
        auto* n = rig.addNode(4);
        StuckDrive stuck;
        n->setScript(stuck.script());
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        Ds402Controller ctl(sdo, 4);
        ctl.setTimeout(150);
        const Ds402Result r = wait([&](auto cb) { ctl.enable(cb); });
        QVERIFY(!r.ok);
        QVERIFY2(r.error.contains(QStringLiteral("did not reach Ready to switch on")) ||
                     r.error.contains(QStringLiteral("did not reach")),
                 qPrintable(r.error));
        QVERIFY2(r.error.contains(QStringLiteral("missing bit 0")), qPrintable(r.error));
        QVERIFY2(r.error.contains(QStringLiteral("drive disabled")), qPrintable(r.error));
        QCOMPARE(*stuck.controlwords, (std::vector<uint16_t>{0x0006, 0x0000}));
    }

    void axisOffsetAndModeVerify() {
        Rig rig;
        auto* n = rig.addNode(4);
        StuckDrive stuck;
        n->setScript(stuck.script());
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        Ds402Controller ctl(sdo, 4, 1);
        QCOMPARE(ctl.objectIndex(0x6041), uint16_t(0x6841));
        Ds402Result r = wait([&](auto cb) { ctl.readState(cb); });
        QVERIFY(r.ok);
        QCOMPARE(*stuck.readIndex, uint16_t(0x6841));
        QCOMPARE(r.state, State::SwitchOnDisabled);
        // 6861h reads back 40h (the scripted drive), not 3: verification fails and says so.
        ctl.setTimeout(100);
        r = wait([&](auto cb) { ctl.setMode(3, cb); });
        QVERIFY(!r.ok);
        QVERIFY2(r.error.contains(QStringLiteral("6861h")), qPrintable(r.error));
    }

    void mismatchNamesBits() {
        QCOMPARE(Ds402Controller::describeMismatch(State::OperationEnabled, 0x0233),
                 QStringLiteral("missing bit 2 (%1)").arg(ds402::statuswordBitName(2)));
    }
};

QTEST_GUILESS_MAIN(TestSvcDs402)
#include "test_svc_ds402.moc"
