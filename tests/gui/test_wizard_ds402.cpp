// SPDX-License-Identifier: GPL-3.0-or-later
// The CiA 402 enable step-through wizard end to end against the virtual drives (sim://) of every
// personality: stepping to Operation enabled, mode, hold-to-run test move, disable; faults
// injected during the enable; disable on close; dry run and listen-only send nothing.
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/ds402/Ds402MotionPlot.h"
#include "app/gui/wizards/ds402/Ds402StateDiagram.h"
#include "app/gui/wizards/ds402/Ds402StatusPanel.h"
#include "app/gui/wizards/ds402/Ds402Wizard.h"
#include "core/sim/Ds402Drive.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"

#include <QComboBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QtTest>

#include "tests/gui/ModalAnswer.h"

using namespace coscope;
using namespace coscope::gui;
using canopen::ds402::Command;
using canopen::ds402::State;

namespace {
const QString kAll = QStringLiteral("sim://?nodes=1:delta-asda-a2,2:aimotor,3:dexmart-dev,4:generic-cia402");

struct Rig {
    Workspace ws;
    bool open(const QString& url) {
        QString error;
        if (!ws.connectBus(url, &error)) return false;
        return QTest::qWaitFor([&] { return ws.bus() && ws.bus()->state() == CanBus::State::Open; }, 5000);
    }
    sim::SimNetwork* net() { return static_cast<SimBus*>(ws.bus())->network(); }
    template <typename F>
    auto onDrive(int node, F f) {
        decltype(f(static_cast<sim::Ds402Drive*>(nullptr))) out{};
        net()->runOnNetworkThread([&] { out = f(net()->device(static_cast<uint8_t>(node))->drive(0)); });
        return out;
    }
    State driveState(int node) {
        return onDrive(node, [](sim::Ds402Drive* d) { return d->state(); });
    }
};

bool waitSignal(QSignalSpy& spy, int ms = 5000) { return spy.count() > 0 || spy.wait(ms); }

// Waits for the wizard's first successful state read of a drive that finished initialising
// (a drive may answer Not ready to switch on just after power-on; the wizard re-reads then).
bool waitReady(Ds402Wizard& w, QSignalSpy& read, int ms = 6000) {
    const bool ok = QTest::qWaitFor([&] {
        for (const auto& args : read)
            if (args.first().toBool() && w.shownState() != State::NotReadyToSwitchOn && w.shownState() != State::Unknown) return true;
        return false;
    }, ms);
    if (!ok) qWarning("no settled state read: shown %s: %s", qPrintable(canopen::ds402::stateName(w.shownState())), qPrintable(w.message()));
    return ok;
}

// Clicks the step button (it must be the enabled next step) and waits for its outcome.
bool step(Ds402Wizard& w, Command c, bool* ok) {
    QPushButton* b = w.stepButton(c);
    if (!b || !b->isEnabled()) {
        qWarning("step %s: button not enabled (busy %d, shown state %s): %s", qPrintable(canopen::ds402::commandName(c)), int(w.isBusy()),
                 qPrintable(canopen::ds402::stateName(w.shownState())), qPrintable(w.message()));
        return false;
    }
    QSignalSpy done(&w, &Ds402Wizard::stepFinished);
    b->click();
    if (!waitSignal(done, 6000)) {
        qWarning("step %s: no outcome within 6 s: %s", qPrintable(canopen::ds402::commandName(c)), qPrintable(w.message()));
        return false;
    }
    *ok = done.first().first().toBool();
    return true;
}
}  // namespace

class TestWizardDs402 : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { eds::installSimulatorDictionaries(); }

    void enableModeTestMoveDisable_data() {
        QTest::addColumn<int>("node");
        QTest::newRow("delta-asda-a2") << 1;
        QTest::newRow("aimotor") << 2;
        QTest::newRow("generic-cia402") << 4;
    }
    void enableModeTestMoveDisable() {
        QFETCH(int, node);
        Rig rig;
        QVERIFY(rig.open(kAll));
        Ds402Wizard w(&rig.ws, node);
        w.setAutoConfirm(true);
        QSignalSpy read(&w, &Ds402Wizard::stateRead);
        QVERIFY(waitReady(w, read));
        QCOMPARE(w.shownState(), State::SwitchOnDisabled);
        QCOMPARE(w.diagram()->state(), State::SwitchOnDisabled);
        QCOMPARE(w.diagram()->nextTransition(), std::optional<int>(2));
        QVERIFY(w.statusPanel()->bitText(6).endsWith(QStringLiteral("on")));
        QVERIFY(w.property("screenshotReady").toBool());
        // Only the next step is offered.
        QVERIFY(!w.stepButton(Command::SwitchOn)->isEnabled());
        QVERIFY(w.quickStopButton()->isEnabled() && w.disableButton()->isEnabled());

        bool ok = false;
        QVERIFY(step(w, Command::Shutdown, &ok) && ok);
        QCOMPARE(w.diagram()->state(), State::ReadyToSwitchOn);
        QVERIFY(step(w, Command::SwitchOn, &ok) && ok);
        QCOMPARE(w.diagram()->state(), State::SwitchedOn);
        QVERIFY(step(w, Command::EnableOperation, &ok) && ok);
        QCOMPARE(w.diagram()->state(), State::OperationEnabled);
        QCOMPARE(rig.driveState(node), State::OperationEnabled);
        const auto visited = w.visitedStates();
        for (State s : {State::SwitchOnDisabled, State::ReadyToSwitchOn, State::SwitchedOn, State::OperationEnabled}) QVERIFY(visited.contains(s));

        // Mode: profile velocity, among those 6502h lists, verified in 6061h.
        QVERIFY(w.supportedModes().has_value());
        QVERIFY(canopen::ds402::modeSupported(*w.supportedModes(), 3));
        QVERIFY(w.modeCombo()->findData(3) >= 0);
        QVERIFY(w.modeCombo()->findData(5) < 0);
        QString why;
        QSignalSpy mode(&w, &Ds402Wizard::modeFinished);
        QVERIFY2(w.chooseMode(3, &why), qPrintable(why));
        QVERIFY(waitSignal(mode));
        QVERIFY(mode.first().first().toBool());
        QCOMPARE(w.modeDisplay(), int8_t(3));
        QCOMPARE(rig.onDrive(node, [](sim::Ds402Drive* d) { return d->modeDisplay(); }), int8_t(3));
        QVERIFY(!w.chooseMode(5, &why));  // not a mode at all

        // Test move on hold-to-run: moves while held, stops on release, stays enabled.
        canopen::Ds402TestMove m;
        m.kind = canopen::Ds402TestMove::Kind::Jog;
        m.velocity = 3000;
        m.maxDurationMs = 5000;
        w.setTestMove(m);
        QVERIFY(!w.holdToRunButton()->isEnabled());  // not armed yet
        QVERIFY2(w.armTestMove(&why), qPrintable(why));
        QVERIFY(w.holdToRunButton()->isEnabled());
        const double before = rig.onDrive(node, [](sim::Ds402Drive* d) { return d->position(); });
        QSignalSpy moved(&w, &Ds402Wizard::testMoveFinished);
        QTest::mousePress(w.holdToRunButton(), Qt::LeftButton);
        QVERIFY(w.testMoveRunning());
        QVERIFY(QTest::qWaitFor([&] { return rig.onDrive(node, [](sim::Ds402Drive* d) { return d->velocity(); }) > 1000; }, 3000));
        QTest::qWait(300);
        QVERIFY(moved.isEmpty());  // still held: still moving
        QTest::mouseRelease(w.holdToRunButton(), Qt::LeftButton);
        QVERIFY(waitSignal(moved));
        QVERIFY2(moved.first().first().toBool(), qPrintable(w.message()));
        QVERIFY(w.message().contains(QStringLiteral("released")));
        QCOMPARE(rig.onDrive(node, [](sim::Ds402Drive* d) { return d->velocity(); }), 0.0);
        QVERIFY(rig.onDrive(node, [](sim::Ds402Drive* d) { return d->position(); }) > before + 100);
        QVERIFY(w.motionPlot()->sampleCount() >= 3);
        QCOMPARE(rig.driveState(node), State::OperationEnabled);

        // Disable.
        w.disableButton()->click();
        QVERIFY(QTest::qWaitFor([&] { return rig.driveState(node) == State::SwitchOnDisabled; }, 3000));
        QVERIFY(QTest::qWaitFor([&] { return w.shownState() == State::SwitchOnDisabled; }, 3000));
    }

    void timeLimitStopsAHeldMove() {
        Rig rig;
        QVERIFY(rig.open(kAll));
        Ds402Wizard w(&rig.ws, 4);
        w.setAutoConfirm(true);
        QSignalSpy read(&w, &Ds402Wizard::stateRead);
        QVERIFY(waitReady(w, read));
        bool ok = false;
        for (Command c : {Command::Shutdown, Command::SwitchOn, Command::EnableOperation}) QVERIFY(step(w, c, &ok) && ok);
        canopen::Ds402TestMove m;
        m.velocity = 2000;
        m.maxDurationMs = 1000;
        w.setTestMove(m);
        QString why;
        QVERIFY2(w.armTestMove(&why), qPrintable(why));
        QSignalSpy moved(&w, &Ds402Wizard::testMoveFinished);
        QVERIFY2(w.pressHoldToRun(&why), qPrintable(why));
        // Held (the feed timer runs) but the time limit stops the move by itself.
        QVERIFY(QTest::qWaitFor([&] { return rig.onDrive(4, [](sim::Ds402Drive* d) { return d->velocity(); }) > 500; }, 3000));
        QVERIFY(waitSignal(moved, 8000));
        QVERIFY2(w.message().contains(QStringLiteral("time limit")), qPrintable(w.message()));
        QCOMPARE(rig.onDrive(4, [](sim::Ds402Drive* d) { return d->velocity(); }), 0.0);
        w.releaseHoldToRun();
        w.close();
        QVERIFY(QTest::qWaitFor([&] { return rig.driveState(4) == State::SwitchOnDisabled; }, 3000));
    }

    void dexmartIsNotACia402Drive() {
        Rig rig;
        QVERIFY(rig.open(kAll));
        Ds402Wizard w(&rig.ws, 3);
        QVERIFY(QTest::qWaitFor([&] { return !w.isCia402(); }, 3000));
        QVERIFY(w.message().contains(QStringLiteral("not a CiA 402"), Qt::CaseInsensitive) || w.message().contains(QStringLiteral("no CiA 402"), Qt::CaseInsensitive));
        QString why;
        QVERIFY(!w.runStep(Command::Shutdown, &why));
        QVERIFY(!why.isEmpty());
        QVERIFY(!w.stepButton(Command::Shutdown)->isEnabled());
    }

    void faultDuringEnableIsReportedAndLeftDisabled_data() {
        QTest::addColumn<int>("node");
        QTest::addColumn<QString>("alarm");
        QTest::addColumn<QString>("expect");
        // The node table is empty (no scan): the wizard must find the dictionary by identity
        // (1018h) to name the vendor alarm.
        QTest::newRow("delta-asda-a2") << 1 << QStringLiteral("AL013") << QStringLiteral("AL013 Emergency stop");
        QTest::newRow("aimotor") << 2 << QStringLiteral("Er.620") << QStringLiteral("Er.620 Motor overload");
        QTest::newRow("generic-cia402") << 4 << QStringLiteral("overcurrent") << QStringLiteral("2310h");
    }
    void faultDuringEnableIsReportedAndLeftDisabled() {
        QFETCH(int, node);
        QFETCH(QString, alarm);
        QFETCH(QString, expect);
        Rig rig;
        QVERIFY(rig.open(kAll));
        rig.onDrive(node, [&](sim::Ds402Drive* d) { d->enableFaults().alarmOnSwitchOn = alarm; return 0; });
        Ds402Wizard w(&rig.ws, node);
        w.setAutoConfirm(true);
        QSignalSpy read(&w, &Ds402Wizard::stateRead);
        QVERIFY(waitReady(w, read));
        bool ok = false;
        QVERIFY(step(w, Command::Shutdown, &ok) && ok);
        QVERIFY(step(w, Command::SwitchOn, &ok));
        QVERIFY(!ok);
        QVERIFY2(w.message().contains(QStringLiteral("Switch on")), qPrintable(w.message()));
        QVERIFY2(w.faultText().contains(QStringLiteral("603Fh")) && w.faultText().contains(expect), qPrintable(w.faultText()));
        QVERIFY2(w.message().contains(expect), qPrintable(w.message()));
        QVERIFY(w.statusPanel()->faultText().contains(expect));
        QCOMPARE(w.diagram()->state(), State::Fault);
        QVERIFY(rig.ws.nodes().snapshot().empty() || !rig.ws.nodes().node(node) || rig.ws.nodes().node(node)->dictionary.isEmpty());
        const State s = rig.driveState(node);
        QVERIFY(s == State::Fault || s == State::SwitchOnDisabled);
        // The statusword read back over the bus says disabled (or fault), never enabled.
        QSignalSpy again(&w, &Ds402Wizard::stateRead);
        w.refresh();
        QVERIFY(waitSignal(again));
        QVERIFY(again.first().first().toBool());
        QVERIFY2(w.shownState() == State::Fault || w.shownState() == State::SwitchOnDisabled, qPrintable(canopen::ds402::stateName(w.shownState())));
        QVERIFY(!(w.statusword() & canopen::ds402::sw::OperationEnabled));
        // The next step offered is the fault reset.
        QVERIFY(w.stepButton(Command::FaultReset)->isEnabled());
    }

    void mainPowerOffIsExplained() {
        Rig rig;
        QVERIFY(rig.open(kAll));
        rig.onDrive(1, [](sim::Ds402Drive* d) { d->enableFaults().mainPowerOff = true; return 0; });
        Ds402Wizard w(&rig.ws, 1);
        w.setAutoConfirm(true);
        QSignalSpy read(&w, &Ds402Wizard::stateRead);
        QVERIFY(waitReady(w, read));
        QVERIFY(w.statusPanel()->bitText(4).endsWith(QStringLiteral("off")));
        bool ok = false;
        QVERIFY(step(w, Command::Shutdown, &ok) && ok);
        QVERIFY(step(w, Command::SwitchOn, &ok));
        QVERIFY(!ok);
        QVERIFY2(w.message().contains(QStringLiteral("Voltage enabled (bit 4) is off: main power is not on")), qPrintable(w.message()));
        QVERIFY(w.message().contains(QStringLiteral("P1-01")));  // Delta: what to check
        QCOMPARE(rig.driveState(1), State::SwitchOnDisabled);  // restored: Disable voltage
    }

    void closingDisablesAnEnabledDrive() {
        Rig rig;
        QVERIFY(rig.open(kAll));
        auto* w = new Ds402Wizard(&rig.ws, 2);
        w->setAutoConfirm(true);
        QSignalSpy read(w, &Ds402Wizard::stateRead);
        QVERIFY(waitReady(*w, read));
        bool ok = false;
        for (Command c : {Command::Shutdown, Command::SwitchOn, Command::EnableOperation}) QVERIFY(step(*w, c, &ok) && ok);
        QCOMPARE(rig.driveState(2), State::OperationEnabled);
        w->close();
        delete w;
        QVERIFY(QTest::qWaitFor([&] { return rig.driveState(2) == State::SwitchOnDisabled; }, 3000));
    }

    // "Losing the connection … disables the drive": the wizard gets its last word in while the
    // workspace closes the bus (Workspace::aboutToDisconnect).
    void disconnectingDisablesAnEnabledDrive() {
        Rig rig;
        QVERIFY(rig.open(kAll));
        Ds402Wizard w(&rig.ws, 4);
        w.setAutoConfirm(true);
        QSignalSpy read(&w, &Ds402Wizard::stateRead);
        QVERIFY(waitReady(w, read));
        bool ok = false;
        for (Command c : {Command::Shutdown, Command::SwitchOn, Command::EnableOperation}) QVERIFY(step(w, c, &ok) && ok);
        QCOMPARE(rig.driveState(4), State::OperationEnabled);
        const std::shared_ptr<sim::SimNetwork> net = static_cast<SimBus*>(rig.ws.bus())->sharedNetwork();  // outlives the bus
        rig.ws.disconnectBus();
        auto state = [&] {
            State st = State::Unknown;
            net->runOnNetworkThread([&] { st = net->device(4)->drive(0)->state(); });
            return st;
        };
        QVERIFY(QTest::qWaitFor([&] { return state() == State::SwitchOnDisabled; }, 3000));
    }

    void refusesEnableWhenNotConfirmed() {
        Rig rig;
        QVERIFY(rig.open(kAll));
        Ds402Wizard w(&rig.ws, 4);
        w.setAutoConfirm(true);
        QSignalSpy read(&w, &Ds402Wizard::stateRead);
        QVERIFY(waitReady(w, read));
        bool ok = false;
        QVERIFY(step(w, Command::Shutdown, &ok) && ok);
        QVERIFY(step(w, Command::SwitchOn, &ok) && ok);
        w.setAutoConfirm(false);
        // A "no" answer: the test answers the dialog with Escape.
        auto no = coscope::testing::answerEscape();
        QString why;
        QVERIFY(!w.runStep(Command::EnableOperation, &why));
        QVERIFY(why.contains(QStringLiteral("not confirmed")));
        QCOMPARE(rig.driveState(4), State::SwitchedOn);
    }

    void dryRunSendsNothing() {
        Rig rig;
        QVERIFY(rig.open(kAll));
        Ds402Wizard w(&rig.ws, 1);
        QSignalSpy read(&w, &Ds402Wizard::stateRead);
        QVERIFY(waitReady(w, read));
        const uint64_t tx = rig.ws.bus()->counters().tx;
        canopen::CommandScript s = w.dryRun();
        // The chosen mode (6060h write + 6061h check) comes first when it differs from the drive's.
        if (!s.steps.empty() && s.steps[0].index == 0x6060) s.steps.erase(s.steps.begin(), s.steps.begin() + 2);
        QCOMPARE(rig.ws.bus()->counters().tx, tx);
        QCOMPARE(rig.driveState(1), State::SwitchOnDisabled);
        // Shutdown, Switch on, Enable operation: each a 6040h write and a 6041h check.
        QCOMPARE(int(s.steps.size()), 6);
        QCOMPARE(s.steps[0].kind, canopen::ScriptStep::Kind::SdoWrite);
        QCOMPARE(s.steps[0].index, uint16_t(0x6040));
        QCOMPARE(s.steps[0].data, QByteArray::fromHex("0600"));
        QCOMPARE(s.steps[1].kind, canopen::ScriptStep::Kind::SdoExpect);
        QCOMPARE(s.steps[1].index, uint16_t(0x6041));
        QCOMPARE(s.steps[1].mask, QByteArray::fromHex("6f00"));
        QCOMPARE(s.steps[1].data, QByteArray::fromHex("2100"));
        QCOMPARE(s.steps[5].data, QByteArray::fromHex("2700"));
        for (const auto& st : s.steps) QVERIFY(!st.why.isEmpty());
    }

    void listenOnlyRefuses() {
        Rig rig;
        QVERIFY(rig.open(QStringLiteral("sim://?listen-only=1&nodes=1:delta-asda-a2")));
        Ds402Wizard w(&rig.ws, 1);
        QTest::qWait(300);
        QString why;
        QVERIFY(!w.sendRefusal().isEmpty());
        QVERIFY(!w.runStep(Command::Shutdown, &why));
        QVERIFY(why.contains(QStringLiteral("isten-only")));
        QVERIFY(!w.quickStopButton()->isEnabled());
        QVERIFY(!w.stepButton(Command::Shutdown)->isEnabled());
        QCOMPARE(rig.ws.bus()->counters().tx, uint64_t(0));
    }

    void nmtResetWarnsAboutAnEnabledDrive() {
        Rig rig;
        QVERIFY(rig.open(kAll));
        NodesDock dock(&rig.ws);
        dock.setAutoConfirm(true);
        // Not enabled: no warning, the plain question only.
        QVERIFY(dock.sendNmt(0x81, 1));  // reset node 1
        QVERIFY2(dock.lastConfirmation().startsWith(QStringLiteral("Send NMT")), qPrintable(dock.lastConfirmation()));
        QVERIFY(!dock.lastConfirmation().contains(QStringLiteral("enabled")));
        Ds402Wizard w(&rig.ws, 1);
        w.setAutoConfirm(true);
        QSignalSpy read(&w, &Ds402Wizard::stateRead);
        QVERIFY(waitReady(w, read));
        bool ok = false;
        for (Command c : {Command::Shutdown, Command::SwitchOn, Command::EnableOperation}) QVERIFY(step(w, c, &ok) && ok);
        QCOMPARE(rig.driveState(1), State::OperationEnabled);
        // Reset communication of node 1, then of all nodes: both name the enabled drive.
        for (int target : {1, 0}) {
            dock.setAutoConfirm(false);
            // Answer "no" (Escape) once the question shows (the statusword is read first).
            auto no = coscope::testing::answerEscape();
            QVERIFY(!dock.sendNmt(0x82, target));  // answered "no": nothing sent
            const QString text = dock.lastConfirmation();
            QVERIFY2(text.contains(QStringLiteral("Drive 1 is enabled (Operation enabled")), qPrintable(text));
            QVERIFY2(text.contains(QStringLiteral("a reset stops it abruptly")), qPrintable(text));
            QVERIFY2(text.contains(QStringLiteral("AL401")), qPrintable(text));
            QVERIFY(!text.contains(QStringLiteral("Drive 2")));  // node 2 is not enabled
            QCOMPARE(rig.driveState(1), State::OperationEnabled);
        }
        // Start (01h) does not stop anything: no warning.
        dock.setAutoConfirm(true);
        QVERIFY(dock.sendNmt(0x01, 1));
        QVERIFY(!dock.lastConfirmation().contains(QStringLiteral("is enabled")));
        w.disableDrive();
        QVERIFY(QTest::qWaitFor([&] { return rig.driveState(1) == State::SwitchOnDisabled; }, 3000));
    }

    void firstCia402DriveIsPreselected() {
        Rig rig;
        QVERIFY(rig.open(QStringLiteral("sim://?nodes=3:dexmart-dev,5:aimotor")));
        startAll(rig);
        Ds402Wizard w(&rig.ws, -1);
        QVERIFY(QTest::qWaitFor([&] { return w.node() == 5 && w.property("screenshotReady").toBool(); }, 10000));
        QCOMPARE(w.shownState(), State::SwitchOnDisabled);
    }

private:
    // The node table learns the nodes from their boot-ups; make sure there is traffic.
    static void startAll(Rig& rig) {
        QString error;
        rig.ws.master()->send(CanFrame::classic(0x000, {0x81, 0x00}), &error);  // reset communication: boot-ups
        (void)QTest::qWaitFor([&] { return rig.ws.nodes().snapshot().size() >= 2; }, 5000);
    }
};

QTEST_MAIN(TestWizardDs402)
#include "test_wizard_ds402.moc"
