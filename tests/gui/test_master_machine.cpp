// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 35 "Done when", in one session as a technician runs a machine without a PLC, by mouse and
// keys in the main window on the virtual network (node 1 Delta ASDA-A2, node 2 AIMOTOR, node 3
// generic CiA 402 drive): SYNC at 10 ms from Bus ▸ Master settings… and the toolbar; the
// AIMOTOR's default TPDOs (transmission type 1, on SYNC: extract-aimotor §3.6) plotted without
// remapping; a raw frame sent every 20 ms, seen in the trace at its period; the AIMOTOR enabled
// and turned through the Process data panel (RPDO1 6040h/6060h, RPDO2 60FFh: extract-aimotor §2)
// while "Hold to run" is held; node 3 homed and moved 1000 units in the CiA 402 wizard; Ctrl+Q
// with node 3 enabled asks, and the Disable voltage frame is in the capture journal.
#include "app/gui/MainWindow.h"
#include "app/gui/master/MasterActions.h"
#include "app/gui/master/ProcessDataDock.h"
#include "app/gui/master/TransmitDock.h"
#include "app/gui/master/TransmitModel.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/od/IntegerSpinBox.h"
#include "app/gui/plot/PlotDock.h"
#include "app/gui/plot/PlotView.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/ds402/Ds402HomingBox.h"
#include "app/gui/wizards/ds402/Ds402PositionMoveBox.h"
#include "app/gui/wizards/ds402/Ds402Wizard.h"
#include "core/logio/PcapLog.h"
#include "core/sim/Ds402Drive.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStyleOptionButton>
#include <QTabBar>
#include <QTabWidget>
#include <QToolBar>
#include <QtTest>

#include <algorithm>
#include <vector>

#include "tests/gui/ContextMenuClick.h"
#include "tests/gui/ItemClick.h"
#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/TxFrames.h"
#include "tests/gui/TypeText.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using canopen::ds402::Command;
using canopen::ds402::State;
using coscope::testing::answerBox;
using coscope::testing::answerBoxSaying;
using coscope::testing::clickCheckBox;
using coscope::testing::clickDockTab;
using coscope::testing::clickMenuItem;
using coscope::testing::median;
using coscope::testing::signalItem;
using coscope::testing::txIntervalsMs;
using coscope::testing::typeAndEnter;
using coscope::testing::waitFor;

namespace {
constexpr int kPatienceMs = 30000;

void click(QWidget* w) { QTest::mouseClick(w, Qt::LeftButton, {}, w->rect().center()); }

// Clicks the tab titled `title` of `tabs`; false when there is none.
bool clickTab(QTabWidget* tabs, const QString& title) {
    QTabBar* bar = tabs->tabBar();
    for (int i = 0; i < bar->count(); ++i)
        if (bar->tabText(i) == title) {
            QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(i).center());
            return true;
        }
    return false;
}
QLineEdit* editOf(QWidget* field) { return field->findChild<QLineEdit*>(); }

// The SDO download of 6040h = 0000h (Disable voltage) to node 3 (CiA 301 §7.2.4.3.3, expedited).
bool isDisableVoltage(const CanFrame& f) {
    return f.id == 0x603u && f.len == 8 && f.data[0] == 0x2B && f.data[1] == 0x40 && f.data[2] == 0x60 &&
           f.data[3] == 0x00 && f.data[4] == 0 && f.data[5] == 0;
}

template <typename W>
W* findTopLevel() {
    for (QWidget* w : QApplication::topLevelWidgets())
        if (auto* t = qobject_cast<W*>(w); t && t->isVisible()) return t;
    return nullptr;
}
}  // namespace

class TestMasterMachine : public QObject {
    Q_OBJECT
    std::unique_ptr<MainWindow> w_;
    std::shared_ptr<sim::SimNetwork> net_;  // outlives the bus: the drives are looked at after it closed

    Workspace* ws() const { return w_->workspace(); }
    template <typename F>
    auto onDrive(int node, F f) const {
        decltype(f(static_cast<sim::Ds402Drive*>(nullptr))) out{};
        net_->runOnNetworkThread([&] { out = f(net_->device(node)->drive(0)); });
        return out;
    }
    State driveState(int node) const {
        return onDrive(node, [](sim::Ds402Drive* d) { return d->state(); });
    }

    // Connect, identify the drives, NMT Start all from the Nodes dock.
    void connectAndStart() {
        QVERIFY(clickMenuItem(*w_, QStringLiteral("Bus"), QStringLiteral("Connect to virtual drives")));
        QVERIFY(waitFor(
            [&] {
                int known = 0;
                for (const canopen::NodeInfo& n : ws()->nodes().snapshot()) known += !n.dictionary.isEmpty();
                return ws()->canTransmit() && known >= 3;
            },
            kPatienceMs));
        net_ = static_cast<SimBus*>(ws()->bus())->sharedNetwork();
        QTableView* nodes = w_->nodesDock()->view();
        auto yes = answerBox(QMessageBox::Yes);
        QVERIFY(coscope::testing::contextMenuClick(nodes, QPoint(4, nodes->viewport()->height() - 4),
                                                   QStringLiteral("Start (Operational)")));
        QVERIFY(waitFor([&] { return yes->answered(); }, kPatienceMs));
    }

    // Bus ▸ Master settings…: SYNC every 10 ms; the toolbar's SYNC starts it.
    void startSync() {
        {
            coscope::testing::ModalAnswerer settings([](QWidget* dlg) {
                auto* period = dlg->findChild<QDoubleSpinBox*>(QStringLiteral("syncPeriod"));
                auto* buttons = dlg->findChild<QDialogButtonBox*>();
                if (!period || !buttons) return false;
                QTest::mouseClick(period, Qt::LeftButton);
                QTest::keyClick(period, Qt::Key_A, Qt::ControlModifier);
                QTest::keyClicks(period, QStringLiteral("10"));
                QTest::mouseClick(buttons->button(QDialogButtonBox::Ok), Qt::LeftButton);
                return true;
            });
            QVERIFY(clickMenuItem(*w_, QStringLiteral("Bus"), QStringLiteral("Master settings")));
            QVERIFY(waitFor([&] { return settings.answered() && !QApplication::activeModalWidget(); }, kPatienceMs));
        }
        auto* bar = w_->findChild<QToolBar*>(QStringLiteral("busToolBar"));
        QVERIFY(bar);
        QWidget* syncButton = bar->widgetForAction(w_->masterActions()->syncAction());
        QVERIFY(syncButton && syncButton->isEnabled());
        const size_t before = ws()->store()->size();
        click(syncButton);
        QVERIFY(waitFor([&] { return txIntervalsMs(*ws()->store(), 0x80, before).size() >= 100; }, kPatienceMs));
        const double syncMs = median(txIntervalsMs(*ws()->store(), 0x80, before));
        QVERIFY2(syncMs > 9.5 && syncMs < 10.5, qPrintable(QString::number(syncMs)));
    }

    // The AIMOTOR's position actual value (TPDO1, on SYNC) ticked in the plot: samples arrive.
    void plotAimotor() {
        QVERIFY(clickDockTab(*w_, QStringLiteral("Plot")));
        auto* tree = w_->plotDock()->findChild<QTreeWidget*>(QStringLiteral("signalTree"));
        QVERIFY(tree);
        QTreeWidgetItem* item = nullptr;
        QVERIFY(waitFor(
            [&] {
                return (item = signalItem(tree, 2, QStringLiteral("Position actual value"))) &&
                       tree->visualItemRect(item).isValid();
            },
            kPatienceMs));
        tree->scrollToItem(item);
        QVERIFY(clickCheckBox(tree, item));
        QCOMPARE(w_->plotDock()->view()->plotted().size(), size_t(1));
        QVERIFY(waitFor([&] { return w_->plotDock()->view()->drawnPoints(0).size() >= 10; }, kPatienceMs));
    }

    // Transmit: 123#1122 every 20 ms, typed in candump syntax, Enter; then stopped by its box.
    void periodicFrame() {
        QVERIFY(clickDockTab(*w_, QStringLiteral("Transmit")));
        TransmitDock* tx = w_->transmitDock();
        QVERIFY(waitFor([&] { return tx->frameEdit()->isVisible(); }, kPatienceMs));
        QTest::mouseClick(tx->frameEdit(), Qt::LeftButton);
        QTest::keyClicks(tx->frameEdit(), QStringLiteral("123#1122"));
        QTest::mouseClick(tx->everyEdit(), Qt::LeftButton);
        QTest::keyClicks(tx->everyEdit(), QStringLiteral("20"));
        const size_t from = ws()->store()->size();
        QTest::keyClick(tx->everyEdit(), Qt::Key_Return);
        QVERIFY(waitFor([&] { return txIntervalsMs(*ws()->store(), 0x123, from).size() >= 30; }, kPatienceMs));
        const double everyMs = median(txIntervalsMs(*ws()->store(), 0x123, from));
        QVERIFY2(everyMs > 19.5 && everyMs < 20.5, qPrintable(QString::number(everyMs)));
        clickCheckBox(tx->view(), tx->model()->index(0, TransmitModel::Run));
        QVERIFY(waitFor([&] { return !tx->model()->isRunning(0); }, kPatienceMs));
    }

    // Process data, node 2: mode 3 (profile velocity) and the controlword by its named bits,
    // sent with each SYNC; each step of the enable sequence (06h, 07h, 0Fh: CiA 402-2 §6.3.1)
    // goes out only while Hold to run is held; the target velocity turns the motor while held.
    void turnAimotorByProcessData() {
        QVERIFY(clickDockTab(*w_, QStringLiteral("Process data")));
        ProcessDataDock* dock = w_->processDataDock();
        // Node 2 chosen by keys in the node box (the dock may have started on another node).
        QComboBox* nodeBox = dock->nodeBox();
        QVERIFY(waitFor([&] { return nodeBox->findText(QStringLiteral("Node 2")) >= 0; }, kPatienceMs));
        nodeBox->setFocus();
        QTest::keyClick(nodeBox, Qt::Key_Home);
        for (int i = 0; i < nodeBox->count() && nodeBox->currentText() != QStringLiteral("Node 2"); ++i)
            QTest::keyClick(nodeBox, Qt::Key_Down);
        QVERIFY(waitFor(
            [&] {
                return nodeBox->currentText() == QStringLiteral("Node 2") && dock->editor(0x6060, 0) &&
                       dock->controlwordBit(3);
            },
            kPatienceMs));
        QTest::qWait(300);  // the values read from the drive
        typeAndEnter(dock->editor(0x6060, 0), QStringLiteral("3"));
        typeAndEnter(dock->editor(0x60FF, 0), QStringLiteral("20000"));
        auto* modeBox = dock->findChild<QComboBox*>(QStringLiteral("processDataMode"));
        modeBox->setFocus();
        QTest::keyClick(modeBox, Qt::Key_End);  // "With each SYNC"
        click(dock->findChild<QPushButton*>(QStringLiteral("processDataStart")));
        QString asked;
        {
            auto yes = answerBox(QMessageBox::Yes, &asked);
            click(dock->armButton());
        }
        QVERIFY2(asked.contains(QStringLiteral("Hold to run")), qPrintable(asked));
        auto holdUntil = [&](auto reached) {
            QTest::mousePress(dock->holdButton(), Qt::LeftButton);
            const bool ok = waitFor(reached, 3000);
            QTest::mouseRelease(dock->holdButton(), Qt::LeftButton);
            return ok;
        };
        auto setBits = [&](std::initializer_list<int> bits) {
            for (int b : bits) {
                QCheckBox* box = dock->controlwordBit(b);
                QVERIFY(box);
                // On its indicator: a check box stretched by the layout takes clicks on its
                // indicator and text only.
                QStyleOptionButton option;
                option.initFrom(box);
                if (!box->isChecked())
                    QTest::mouseClick(
                        box, Qt::LeftButton, {},
                        box->style()->subElementRect(QStyle::SE_CheckBoxIndicator, &option, box).center());
                QVERIFY(box->isChecked());
            }
        };
        setBits({1, 2});  // Shutdown
        QVERIFY(holdUntil([&] { return driveState(2) == State::ReadyToSwitchOn; }));
        setBits({0});  // Switch on
        QVERIFY(holdUntil([&] { return driveState(2) == State::SwitchedOn; }));
        setBits({3});  // Enable operation: turns at the target velocity while held
        QVERIFY(holdUntil([&] {
            return driveState(2) == State::OperationEnabled &&
                   onDrive(2, [](sim::Ds402Drive* d) { return d->velocity(); }) > 1000;
        }));
        // Released: Halt, the motor stops; the drive stays enabled.
        QVERIFY(
            waitFor([&] { return std::abs(onDrive(2, [](sim::Ds402Drive* d) { return d->velocity(); })) < 1; }, 3000));
        QCOMPARE(driveState(2), State::OperationEnabled);
        click(dock->findChild<QPushButton*>(QStringLiteral("processDataStart")));  // stop sending
    }

    // Commission ▸ CiA 402 enable step-through…, node 3 chosen by keys, enabled step by step.
    Ds402Wizard* enableNode3InWizard() {
        Ds402Wizard* wiz = nullptr;
        const bool opened = waitFor([&] {
            QMenu* menu = coscope::testing::openMenu(*w_, QStringLiteral("Commission"));
            QAction* item = menu ? coscope::testing::menuItem(menu, QStringLiteral("CiA 402 enable")) : nullptr;
            if (item && item->isEnabled()) {
                QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(item).center());
                return true;
            }
            if (menu) QTest::keyClick(menu, Qt::Key_Escape);
            return false;
        });
        if (!opened || !waitFor([&] { return (wiz = findTopLevel<Ds402Wizard>()) != nullptr; }) ||
            !QTest::qWaitForWindowExposed(wiz))
            return nullptr;
        auto* nodes = wiz->findChild<QComboBox*>(QStringLiteral("nodeCombo"));
        if (!waitFor([&] { return nodes->findText(QStringLiteral("Node 3"), Qt::MatchStartsWith) >= 0; }, 20000))
            return nullptr;
        nodes->setFocus();
        QTest::keyClick(nodes, Qt::Key_Home);
        for (int i = 0; i < nodes->count() && !nodes->currentText().startsWith(QStringLiteral("Node 3")); ++i)
            QTest::keyClick(nodes, Qt::Key_Down);
        if (!waitFor([&] { return wiz->node() == 3 && wiz->shownState() == State::SwitchOnDisabled; }, 8000))
            return nullptr;
        auto stepTo = [&](Command c, State expect) {
            QPushButton* b = wiz->stepButton(c);
            if (!waitFor([&] { return b->isEnabled(); }, 6000)) return false;
            click(b);
            return waitFor([&] { return driveState(3) == expect && wiz->shownState() == expect; }, 6000);
        };
        if (!stepTo(Command::Shutdown, State::ReadyToSwitchOn) || !stepTo(Command::SwitchOn, State::SwitchedOn))
            return nullptr;
        auto yes = answerBox(QMessageBox::Yes);
        return stepTo(Command::EnableOperation, State::OperationEnabled) ? wiz : nullptr;
    }

    // The wizard's Homing page: method 35 (the current position is home, CiA 402-2 §13) with
    // home offset 0; Start asks to switch to Homing and to start; "homing attained".
    void homeNode3(Ds402Wizard* wiz) {
        QVERIFY(clickTab(wiz->pages(), QStringLiteral("Homing")));
        Ds402HomingBox* page = wiz->homingBox();
        QVERIFY(waitFor([&] { return page->isVisible(); }, 3000));
        typeAndEnter(page->methodCombo()->lineEdit(), QStringLiteral("35"));
        typeAndEnter(editOf(page->offsetField()), QStringLiteral("0"));
        auto yesMode = answerBoxSaying(QStringLiteral("homing needs"), QMessageBox::Yes);
        auto yesStart = answerBoxSaying(QStringLiteral("Start homing?"), QMessageBox::Yes);
        QSignalSpy finished(wiz, &Ds402Wizard::homingFinished);
        click(page->startButton());
        QVERIFY2(waitFor([&] { return !finished.isEmpty(); }, 10000), qPrintable(wiz->message()));
        QVERIFY2(finished.first().first().toBool(), qPrintable(page->resultText()));
        QVERIFY2(page->resultText().contains(QStringLiteral("Homing attained")), qPrintable(page->resultText()));
        QVERIFY(std::abs(onDrive(3, [](sim::Ds402Drive* d) { return d->position(); })) < 1.0);
    }

    // The wizard's Position move page: relative 1000, armed (two questions), held to the end.
    void moveNode3(Ds402Wizard* wiz) {
        QVERIFY(clickTab(wiz->pages(), QStringLiteral("Position move")));
        Ds402PositionMoveBox* page = wiz->positionBox();
        QVERIFY(waitFor([&] { return page->isVisible(); }, 3000));
        QVERIFY(page->relativeBox()->isChecked());
        typeAndEnter(editOf(page->targetField()), QStringLiteral("1000"));
        typeAndEnter(editOf(page->velocityField()), QStringLiteral("1000"));
        QVERIFY(waitFor([&] { return wiz->shownState() == State::OperationEnabled && !wiz->isBusy(); }, 5000));
        {
            auto yesMode = answerBoxSaying(QStringLiteral("position move needs"), QMessageBox::Yes);
            auto yesArm = answerBoxSaying(QStringLiteral("Arm the position move?"), QMessageBox::Yes);
            click(page->armButton());
            QVERIFY2(waitFor([&] { return page->holdButton()->isEnabled(); }, 5000), qPrintable(wiz->message()));
        }
        const double start = onDrive(3, [](sim::Ds402Drive* d) { return d->position(); });
        QSignalSpy finished(wiz, &Ds402Wizard::positionMoveFinished);
        QTest::mousePress(page->holdButton(), Qt::LeftButton);
        const bool done = waitFor([&] { return !finished.isEmpty(); }, 8000);
        QTest::mouseRelease(page->holdButton(), Qt::LeftButton);
        QVERIFY2(done, qPrintable(wiz->message()));
        QVERIFY2(finished.first().first().toBool(), qPrintable(page->resultText()));
        const double end = onDrive(3, [](sim::Ds402Drive* d) { return d->position(); });
        QVERIFY2(std::abs(end - (start + 1000)) <= 2, qPrintable(QString::number(end)));
        QCOMPARE(driveState(3), State::OperationEnabled);
    }

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_master_machine"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
    }

    void runTheMachine() {
        w_ = std::make_unique<MainWindow>();  // not quiet: the questions are modal boxes
        w_->resize(1400, 900);
        w_->show();
        QVERIFY(QTest::qWaitForWindowActive(w_.get()));
        connectAndStart();
        if (QTest::currentTestFailed()) return;
        startSync();
        if (QTest::currentTestFailed()) return;
        plotAimotor();
        if (QTest::currentTestFailed()) return;
        periodicFrame();
        if (QTest::currentTestFailed()) return;
        turnAimotorByProcessData();
        if (QTest::currentTestFailed()) return;
        Ds402Wizard* wiz = enableNode3InWizard();
        QVERIFY(wiz);
        homeNode3(wiz);
        if (QTest::currentTestFailed()) return;
        moveNode3(wiz);
        if (QTest::currentTestFailed()) return;

        // Ctrl+Q with drives enabled: "save first?" (Discard), then the question naming node 3;
        // Disable and quit: the Disable voltage frame is in the journal, the drive disabled.
        const QString journal = ws()->journalPath();
        QString saveAsked, asked;
        auto discard = answerBox(QMessageBox::Discard, &saveAsked);
        auto yes = answerBox(QMessageBox::Yes, &asked);
        w_->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(w_.get()));
        QTest::keyClick(w_.get(), Qt::Key_Q, Qt::ControlModifier);
        QVERIFY2(waitFor([&] { return !asked.isEmpty(); }, 5000), "no question about the enabled drives");
        QVERIFY2(asked.contains(QStringLiteral("Nodes 2, 3 are enabled")) && asked.contains(QStringLiteral("quit")),
                 qPrintable(asked));
        QVERIFY(waitFor([&] { return !w_->isVisible(); }, 5000));
        logio::PcapReader r;
        QVERIFY(r.open(journal));
        const auto read = r.readAll();
        QVERIFY2(std::any_of(read.begin(), read.end(), isDisableVoltage),
                 "the journal lacks node 3's Disable voltage frame");
        waitFor([&] { return driveState(3) == State::SwitchOnDisabled && driveState(2) != State::OperationEnabled; },
                3000);
        QCOMPARE(driveState(3), State::SwitchOnDisabled);
        QVERIFY(driveState(2) != State::OperationEnabled);
    }

    void cleanup() {
        w_.reset();
        net_.reset();
    }
};

QTEST_MAIN(TestMasterMachine)
#include "test_master_machine.moc"
