// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 35 "Safety edges", CoScope's heartbeat guard from the GUI: node 3 (the generic CiA 402
// drive of sim://) enabled through the CiA 402 wizard by clicks; the question "should it stop by
// itself if CoScope dies?" appears once, naming the node, the heartbeat period and the time;
// answered by a click, CoScope's heartbeat (77Fh) runs every 100 ms and the drive's heartbeat
// consumer 1016h watches it (007F012Ch: node 127, 300 ms) with 6007h = 3 (quick stop), written
// as SDO downloads seen in the trace; the status bar says so. Disable puts the old values back and
// the heartbeat stops; disconnecting with the drive enabled disables it, then puts the old values
// back, then the heartbeat stops, then the bus closes (in that order in the trace); a heartbeat
// that stops while the drive is guarded makes the drive stop by itself (CiA 402-2 6007h = 3).
#include "app/gui/MainWindow.h"
#include "app/gui/master/HeartbeatGuardQuestion.h"
#include "app/gui/master/MasterActions.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/ds402/Ds402Wizard.h"
#include "core/canopen/HeartbeatProducer.h"
#include "core/sim/Ds402Drive.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QtTest>

#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using canopen::ds402::Command;
using canopen::ds402::State;
using coscope::testing::answerBox;
using coscope::testing::clickMenuItem;
using coscope::testing::waitFor;

namespace {
constexpr int kNode = 3;
constexpr int16_t kOldAbortOption = 2;        // set before the test: disable voltage (the EDS default is 1)
constexpr uint32_t kArmedEntry = 0x007F012C;  // CoScope's node 127, 3 x 100 ms (CiA 301 §7.5.2.18)

void click(QWidget* w) { QTest::mouseClick(w, Qt::LeftButton, {}, w->rect().center()); }

template <typename W>
W* findTopLevel(const QString& name = {}) {
    for (QWidget* w : QApplication::topLevelWidgets())
        if (auto* t = qobject_cast<W*>(w); t && t->isVisible() && (name.isEmpty() || t->objectName() == name)) return t;
    return nullptr;
}

// Our own SDO download (CiA 301 §7.2.4.3.3) of `index`:`sub` to node 3 with the value `v`.
bool isWrite(const CanFrame& f, uint16_t index, uint8_t sub, uint32_t v, int bytes) {
    if (!f.isTx() || f.id != 0x600u + kNode || f.len != 8 || f.data[1] != (index & 0xFF) || f.data[2] != (index >> 8) ||
        f.data[3] != sub)
        return false;
    for (int i = 0; i < bytes; ++i)
        if (f.data[4 + i] != ((v >> (8 * i)) & 0xFF)) return false;
    return true;
}
std::vector<FrameNo> framesWhere(const TraceStore& store, const std::function<bool(const CanFrame&)>& pred) {
    std::vector<FrameNo> out;
    for (size_t n = 0; n < store.size(); ++n)
        if (pred(store.frame(FrameNo(n)))) out.push_back(FrameNo(n));
    return out;
}
}  // namespace

class TestHeartbeatGuard : public QObject {
    Q_OBJECT
    std::unique_ptr<MainWindow> w_;
    std::shared_ptr<sim::SimNetwork> net_;
    Ds402Wizard* wiz_ = nullptr;

    Workspace* ws() const { return w_->workspace(); }
    State driveState() const {
        State s = State::Unknown;
        net_->runOnNetworkThread([&] { s = net_->device(kNode)->drive(0)->state(); });
        return s;
    }
    uint64_t driveValue(uint16_t index, uint8_t sub) const {
        uint64_t v = 0;
        net_->runOnNetworkThread(
            [&] { v = net_->device(kNode)->value(index, sub).value_or(od::Value{}).toUInt64().value_or(0); });
        return v;
    }
    int16_t abortOption() const {
        int64_t v = 0;
        net_->runOnNetworkThread(
            [&] { v = net_->device(kNode)->value(0x6007, 0).value_or(od::Value{}).toInt64().value_or(-99); });
        return static_cast<int16_t>(v);
    }
    QString masterStatus() const {
        auto* label = w_->findChild<QLabel*>(QStringLiteral("statusMaster"));
        return label ? label->text() : QString();
    }

    // Connected to sim:// by the Bus menu, 6007h of node 3 set to 2, the CiA 402 wizard opened
    // from the Commission menu on node 3.
    void connectAndOpenWizard() {
        w_ = std::make_unique<MainWindow>();
        w_->show();
        QVERIFY(QTest::qWaitForWindowActive(w_.get()));
        QVERIFY(clickMenuItem(*w_, QStringLiteral("Bus"), QStringLiteral("Connect to virtual drives")));
        QVERIFY(waitFor([&] { return ws()->canTransmit(); }));
        net_ = static_cast<SimBus*>(ws()->bus())->sharedNetwork();
        net_->runOnNetworkThread(
            [&] { net_->device(kNode)->setValue(0x6007, 0, od::Value::signedInt(kOldAbortOption)); });
        QCOMPARE(abortOption(), kOldAbortOption);
        QVERIFY(waitFor([&] {
            QMenu* menu = coscope::testing::openMenu(*w_, QStringLiteral("Commission"));
            QAction* item = menu ? coscope::testing::menuItem(menu, QStringLiteral("CiA 402 enable")) : nullptr;
            if (item && item->isEnabled()) {
                QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(item).center());
                return true;
            }
            if (menu) QTest::keyClick(menu, Qt::Key_Escape);
            return false;
        }));
        QVERIFY(waitFor([&] { return (wiz_ = findTopLevel<Ds402Wizard>()) != nullptr; }));
        QVERIFY(QTest::qWaitForWindowExposed(wiz_));
        auto* nodes = wiz_->findChild<QComboBox*>(QStringLiteral("nodeCombo"));
        QVERIFY(waitFor([&] { return nodes->findText(QStringLiteral("Node %1").arg(kNode), Qt::MatchStartsWith) >= 0; },
                        20000));
        nodes->setFocus();
        QTest::keyClick(nodes, Qt::Key_Home);
        for (int i = 0; i < nodes->count() && !nodes->currentText().startsWith(QStringLiteral("Node %1").arg(kNode));
             ++i)
            QTest::keyClick(nodes, Qt::Key_Down);
        QVERIFY(waitFor([&] { return wiz_->node() == kNode && wiz_->shownState() == State::SwitchOnDisabled; }, 8000));
    }

    bool step(Command c, State expect) {
        QPushButton* b = wiz_->stepButton(c);
        if (!b) return false;
        if (!waitFor([&] { return b->isEnabled(); }, 6000)) return false;
        click(b);
        return waitFor([&] { return driveState() == expect && wiz_->shownState() == expect; }, 6000);
    }

    // Shutdown in the wizard: the question shows (not modal); its text is checked and `answer`
    // clicked, with "Remember my answer" ticked when `remember`.
    void enableAndAnswer(bool guard, bool remember) {
        QVERIFY(step(Command::Shutdown, State::ReadyToSwitchOn));
        QMessageBox* box = nullptr;
        QVERIFY2(
            waitFor(
                [&] { return (box = findTopLevel<QMessageBox>(QStringLiteral("heartbeatGuardQuestion"))) != nullptr; },
                5000),
            "no heartbeat guard question");
        QVERIFY2(box->text().contains(QStringLiteral("Node 3 is enabled by CoScope")), qPrintable(box->text()));
        const QString info = box->informativeText();
        QVERIFY2(info.contains(QStringLiteral("every 100 ms")) && info.contains(QStringLiteral("1016h")) &&
                     info.contains(QStringLiteral("6007h")) && info.contains(QStringLiteral("within 300 ms")) &&
                     info.contains(QStringLiteral("put back")),
                 qPrintable(info));
        QVERIFY(box->windowModality() == Qt::NonModal);  // the wizard stays usable meanwhile
        if (remember) click(box->findChild<QCheckBox*>(QStringLiteral("rememberAnswer")));
        click(box->button(guard ? QMessageBox::Yes : QMessageBox::No));
        QVERIFY(waitFor([&] { return !findTopLevel<QMessageBox>(QStringLiteral("heartbeatGuardQuestion")); }, 3000));
    }

    void checkArmed() {
        QVERIFY2(waitFor([&] { return driveValue(0x1016, 1) == kArmedEntry && abortOption() == 3; }, 5000),
                 qPrintable(
                     QStringLiteral("1016h:01 = %1, 6007h = %2").arg(driveValue(0x1016, 1), 0, 16).arg(abortOption())));
        const TraceStore& store = *ws()->store();
        QVERIFY(!framesWhere(store, [](const CanFrame& f) { return isWrite(f, 0x1016, 1, kArmedEntry, 4); }).empty());
        QVERIFY(!framesWhere(store, [](const CanFrame& f) { return isWrite(f, 0x6007, 0, 3, 2); }).empty());
        QVERIFY(waitFor(
            [&] {
                return framesWhere(*ws()->store(), [](const CanFrame& f) {
                           return f.isTx() && f.id == 0x77F;
                       }).size() >= 2;
            },
            3000));
        QVERIFY2(waitFor(
                     [&] {
                         return masterStatus().contains(QStringLiteral("Heartbeat 100 ms")) &&
                                masterStatus().contains(QStringLiteral("guarding node 3"));
                     },
                     3000),
                 qPrintable(masterStatus()));
    }

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_heartbeat_guard"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
    }
    void cleanup() {
        if (wiz_) wiz_->close();
        wiz_ = nullptr;
        if (w_) w_->setQuiet(true);  // no questions when the window goes
        w_.reset();
        net_.reset();
    }

    // Guard the drive; Disable in the wizard puts 1016h:01 and 6007h back and the heartbeat stops.
    void guardWhileEnabledThenPutBack() {
        connectAndOpenWizard();
        if (QTest::currentTestFailed()) return;
        QCOMPARE(driveValue(0x1016, 1), uint64_t(0));
        enableAndAnswer(true, false);
        if (QTest::currentTestFailed()) return;
        checkArmed();
        if (QTest::currentTestFailed()) return;
        QVERIFY(step(Command::SwitchOn, State::SwitchedOn));
        // Disable (the wizard's always-visible button): the drive leaves the record; the old values come back.
        QVERIFY(waitFor([&] { return wiz_->disableButton()->isEnabled(); }, 3000));
        click(wiz_->disableButton());
        QVERIFY(waitFor(
            [&] { return driveState() == State::SwitchOnDisabled && wiz_->shownState() == State::SwitchOnDisabled; },
            6000));
        QVERIFY2(waitFor([&] { return driveValue(0x1016, 1) == 0 && abortOption() == kOldAbortOption; }, 5000),
                 qPrintable(
                     QStringLiteral("1016h:01 = %1, 6007h = %2").arg(driveValue(0x1016, 1), 0, 16).arg(abortOption())));
        QVERIFY(waitFor(
            [&] {
                return !ws()->heartbeatProducer()->isRunning() && !masterStatus().contains(QStringLiteral("guarding"));
            },
            3000));
        // Enabled again in the same connection: not asked again, guarded again.
        QVERIFY(step(Command::Shutdown, State::ReadyToSwitchOn));
        QTest::qWait(300);
        QVERIFY(!findTopLevel<QMessageBox>(QStringLiteral("heartbeatGuardQuestion")));
        checkArmed();
    }

    // "Not now": nothing is written, no heartbeat.
    void declinedChangesNothing() {
        connectAndOpenWizard();
        if (QTest::currentTestFailed()) return;
        enableAndAnswer(false, false);
        if (QTest::currentTestFailed()) return;
        QTest::qWait(500);
        QCOMPARE(driveValue(0x1016, 1), uint64_t(0));
        QCOMPARE(abortOption(), kOldAbortOption);
        QVERIFY(!ws()->heartbeatProducer()->isRunning());
        QVERIFY(framesWhere(*ws()->store(), [](const CanFrame& f) {
                    return f.isTx() && (f.id == 0x77F || isWrite(f, 0x1016, 1, kArmedEntry, 4));
                }).empty());
    }

    // Remembered "yes", then Bus ▸ Disconnect with the drive in Operation enabled: Disable voltage,
    // then 1016h and 6007h put back, then the last heartbeat, all before the bus closed.
    void disconnectDisablesThenPutsBackThenStopsHeartbeat() {
        connectAndOpenWizard();
        if (QTest::currentTestFailed()) return;
        enableAndAnswer(true, true);
        if (QTest::currentTestFailed()) return;
        QCOMPARE(QSettings().value(HeartbeatGuardQuestion::kSettingsKey).toString(), QStringLiteral("always"));
        checkArmed();
        if (QTest::currentTestFailed()) return;
        QVERIFY(step(Command::SwitchOn, State::SwitchedOn));
        QString energise;
        {
            auto yes = answerBox(QMessageBox::Yes, &energise);
            QVERIFY(step(Command::EnableOperation, State::OperationEnabled));
        }
        w_->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(w_.get()));
        QString asked;
        auto yes = answerBox(QMessageBox::Yes, &asked);
        QVERIFY(clickMenuItem(*w_, QStringLiteral("Bus"), QStringLiteral("Disconnect")));
        QVERIFY(waitFor([&] { return !asked.isEmpty() && !ws()->isLive(); }, 5000));
        const TraceStore& store = *ws()->store();
        const auto disable = framesWhere(store, [](const CanFrame& f) { return isWrite(f, 0x6040, 0, 0x0000, 2); });
        const auto entryBack = framesWhere(store, [](const CanFrame& f) { return isWrite(f, 0x1016, 1, 0, 4); });
        const auto optionBack =
            framesWhere(store, [](const CanFrame& f) { return isWrite(f, 0x6007, 0, uint32_t(kOldAbortOption), 2); });
        const auto heartbeats = framesWhere(store, [](const CanFrame& f) { return f.isTx() && f.id == 0x77F; });
        QVERIFY(!disable.empty() && !entryBack.empty() && !optionBack.empty() && !heartbeats.empty());
        QVERIFY2(disable.back() < entryBack.back() && entryBack.back() < optionBack.back(),
                 "Disable voltage, then 1016h, then 6007h");
        // The heartbeat went on until the drive stopped watching it: one went out within its
        // period before 1016h was put back.
        FrameNo lastBefore = 0;
        for (FrameNo n : heartbeats)
            if (n < entryBack.back()) lastBefore = n;
        const int64_t gapNs = store.record(entryBack.back()).timestampNs - store.record(lastBefore).timestampNs;
        QVERIFY2(lastBefore > 0 && gapNs < 250'000'000,
                 qPrintable(QStringLiteral("%1 ms without heartbeat before 1016h was put back").arg(gapNs / 1e6)));
        QCOMPARE(driveValue(0x1016, 1), uint64_t(0));
        QCOMPARE(abortOption(), kOldAbortOption);
        QVERIFY(waitFor([&] { return driveState() == State::SwitchOnDisabled; }, 3000));
    }

    // Remembered "yes" (previous test): no question; the heartbeat stops as if CoScope died while
    // the drive is in Operation enabled: it quick-stops by itself within the consumer time.
    void drivesStopsByItselfWhenTheHeartbeatStops() {
        QCOMPARE(QSettings().value(HeartbeatGuardQuestion::kSettingsKey).toString(), QStringLiteral("always"));
        connectAndOpenWizard();
        if (QTest::currentTestFailed()) return;
        QVERIFY(step(Command::Shutdown, State::ReadyToSwitchOn));
        checkArmed();
        if (QTest::currentTestFailed()) return;
        QVERIFY(!findTopLevel<QMessageBox>(QStringLiteral("heartbeatGuardQuestion")));
        QVERIFY(step(Command::SwitchOn, State::SwitchedOn));
        {
            QString energise;
            auto yes = answerBox(QMessageBox::Yes, &energise);
            QVERIFY(step(Command::EnableOperation, State::OperationEnabled));
        }
        // What a crash or a pulled cable does: no more heartbeat from CoScope.
        ws()->heartbeatProducer()->stop();
        QVERIFY2(waitFor([&] { return driveState() != State::OperationEnabled; }, 1500),
                 "the drive did not react to the lost heartbeat");
        const State s = driveState();
        QVERIFY2(s == State::QuickStopActive || s == State::SwitchOnDisabled, qPrintable(QString::number(int(s))));
    }
};

QTEST_MAIN(TestHeartbeatGuard)
#include "test_heartbeat_guard.moc"
