// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 35 "Safety edges": quitting (Ctrl+Q) or disconnecting (toolbar, Bus menu) while a drive
// is enabled by CoScope asks first, naming the node; Cancel keeps everything as it was; Disable
// sends Disable voltage (6040h = 0000h, an SDO download to 603h) and sees it go out — its Tx copy
// is in the trace and the capture journal — before the bus closes, and the virtual drive is no
// longer in Operation enabled. All through input events on the main window and the CiA 402
// wizard opened from the Commission menu.
#include "app/gui/MainWindow.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/ds402/Ds402Wizard.h"
#include "core/logio/PcapLog.h"
#include "core/sim/Ds402Drive.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"

#include <QComboBox>
#include <QDir>
#include <QMenu>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QSettings>
#include <QToolBar>
#include <QToolButton>
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
constexpr int kNode = 3;  // sim:// node 3: the generic CiA 402 drive

void click(QWidget* w) { QTest::mouseClick(w, Qt::LeftButton, {}, w->rect().center()); }

template <typename W>
W* findTopLevel() {
    for (QWidget* w : QApplication::topLevelWidgets())
        if (auto* t = qobject_cast<W*>(w); t && t->isVisible()) return t;
    return nullptr;
}

// The SDO download of 6040h = `cw` to node 3 (CiA 301 §7.2.4.3.3, expedited, 2 bytes).
bool isControlwordWrite(const CanFrame& f, uint16_t cw) {
    return f.id == 0x600u + kNode && f.len == 8 && f.data[0] == 0x2B && f.data[1] == 0x40 && f.data[2] == 0x60 &&
           f.data[3] == 0x00 && f.data[4] == (cw & 0xFF) && f.data[5] == (cw >> 8);
}
// Frame numbers of our own (Tx) writes of 6040h = `cw` to node 3 in the trace.
std::vector<FrameNo> ownWrites(const TraceStore& store, uint16_t cw) {
    std::vector<FrameNo> out;
    for (size_t n = 0; n < store.size(); ++n)
        if (const CanFrame f = store.frame(FrameNo(n)); f.isTx() && isControlwordWrite(f, cw))
            out.push_back(FrameNo(n));
    return out;
}
}  // namespace

class TestSafeClose : public QObject {
    Q_OBJECT
    std::unique_ptr<MainWindow> w_;
    std::shared_ptr<sim::SimNetwork> net_;  // outlives the bus: the drives are looked at after it closed

    Workspace* ws() const { return w_->workspace(); }
    State driveState() const {
        State s = State::Unknown;
        net_->runOnNetworkThread([&] { s = net_->device(kNode)->drive(0)->state(); });
        return s;
    }

    // The window, connected to the virtual drives by Bus ▸ Connect to virtual drives, the CiA 402
    // wizard opened from the Commission menu, node 3 chosen in it by keys and enabled by clicks.
    void connectAndEnable() {
        w_ = std::make_unique<MainWindow>();  // not quiet: the questions are modal boxes
        w_->show();
        QVERIFY(QTest::qWaitForWindowActive(w_.get()));
        QVERIFY(clickMenuItem(*w_, QStringLiteral("Bus"), QStringLiteral("Connect to virtual drives")));
        QVERIFY(waitFor([&] { return ws()->canTransmit(); }));
        net_ = static_cast<SimBus*>(ws()->bus())->sharedNetwork();
        // The Commission items come on once the window saw the bus open (its refresh).
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
        Ds402Wizard* wiz = nullptr;
        QVERIFY(waitFor([&] { return (wiz = findTopLevel<Ds402Wizard>()) != nullptr; }));
        QVERIFY(QTest::qWaitForWindowExposed(wiz));
        auto* nodes = wiz->findChild<QComboBox*>(QStringLiteral("nodeCombo"));
        QVERIFY(waitFor([&] { return nodes->findText(QStringLiteral("Node %1").arg(kNode), Qt::MatchStartsWith) >= 0; },
                        20000));
        nodes->setFocus();
        QTest::keyClick(nodes, Qt::Key_Home);
        for (int i = 0; i < nodes->count() && !nodes->currentText().startsWith(QStringLiteral("Node %1").arg(kNode));
             ++i)
            QTest::keyClick(nodes, Qt::Key_Down);
        QVERIFY(waitFor([&] { return wiz->node() == kNode && wiz->shownState() == State::SwitchOnDisabled; }, 8000));
        auto stepTo = [&](Command c, State expect) {
            QPushButton* b = wiz->stepButton(c);
            if (!waitFor([&] { return b->isEnabled(); }, 6000)) return false;
            click(b);
            return waitFor([&] { return driveState() == expect && wiz->shownState() == expect; }, 6000);
        };
        QVERIFY(stepTo(Command::Shutdown, State::ReadyToSwitchOn));
        QVERIFY(stepTo(Command::SwitchOn, State::SwitchedOn));
        QString asked;
        auto yes = answerBox(QMessageBox::Yes, &asked);
        QVERIFY(stepTo(Command::EnableOperation, State::OperationEnabled));
        QVERIFY(asked.contains(QStringLiteral("energises")));
        // Back to the main window, as a user clicks it.
        w_->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(w_.get()));
    }

    // After the bus closed: the Disable voltage went out (in the trace as ours, and in the
    // journal), and the drive left Operation enabled.
    void checkDisabledBeforeClose(const QString& journal, bool inTrace = true) {
        if (inTrace) {
            QVERIFY(!ws()->isLive());
            const auto writes = ownWrites(*ws()->store(), 0x0000);
            QVERIFY2(!writes.empty(), "no Disable voltage (6040h = 0000h) to 603h in the trace");
        }
        logio::PcapReader r;
        QVERIFY(r.open(journal));
        const auto read = r.readAll();
        QVERIFY2(r.errorString().isEmpty(), qPrintable(r.errorString()));
        QVERIFY2(std::any_of(read.begin(), read.end(), [](const CanFrame& f) { return isControlwordWrite(f, 0x0000); }),
                 "the journal lacks the Disable voltage frame");
        QVERIFY(waitFor([&] { return driveState() == State::SwitchOnDisabled; }, 3000));
    }

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_safe_close"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
    }
    void cleanup() {
        w_.reset();
        net_.reset();
    }

    // Ctrl+Q: "save first?" (Discard), then the question naming node 3; Disable and quit.
    void quitDisablesTheEnabledDrive() {
        connectAndEnable();
        if (QTest::currentTestFailed()) return;
        const QString journal = ws()->journalPath();
        QString saveAsked, asked;
        auto discard = answerBox(QMessageBox::Discard, &saveAsked);
        auto yes = answerBox(QMessageBox::Yes, &asked);
        QTest::keyClick(w_.get(), Qt::Key_Q, Qt::ControlModifier);
        QVERIFY2(waitFor([&] { return !asked.isEmpty(); }, 5000), "no question about the enabled drive");
        QVERIFY2(asked.contains(QStringLiteral("Node 3 is enabled")) && asked.contains(QStringLiteral("quit")),
                 qPrintable(asked));
        QVERIFY(waitFor([&] { return !w_->isVisible(); }, 5000));
        checkDisabledBeforeClose(journal);
    }

    // Disconnect on the toolbar: Cancel keeps the bus and the drive as they were (nothing sent);
    // Bus ▸ Disconnect, Disable and disconnect: disabled, seen, then closed.
    void disconnectAsksAndDisables() {
        connectAndEnable();
        if (QTest::currentTestFailed()) return;
        const QString journal = ws()->journalPath();
        auto* bar = w_->findChild<QToolBar*>(QStringLiteral("busToolBar"));
        QVERIFY(bar);
        QAction* disconnect = nullptr;
        for (QAction* a : bar->actions())
            if (a->text().remove(u'&').startsWith(QStringLiteral("Disconnect"))) disconnect = a;
        QVERIFY(disconnect);
        {
            QString asked;
            auto cancel = answerBox(QMessageBox::Cancel, &asked);
            click(bar->widgetForAction(disconnect));
            QVERIFY(waitFor([&] { return !asked.isEmpty(); }, 5000));
            QVERIFY2(
                asked.contains(QStringLiteral("Node 3 is enabled")) && asked.contains(QStringLiteral("disconnect")),
                qPrintable(asked));
        }
        QTest::qWait(300);
        QVERIFY(ws()->canTransmit());
        QCOMPARE(driveState(), State::OperationEnabled);
        QVERIFY(ownWrites(*ws()->store(), 0x0000).empty());
        QString asked;
        auto yes = answerBox(QMessageBox::Yes, &asked);
        QVERIFY(clickMenuItem(*w_, QStringLiteral("Bus"), QStringLiteral("Disconnect")));
        QVERIFY(waitFor([&] { return !asked.isEmpty() && !ws()->isLive(); }, 5000));
        QVERIFY2(asked.contains(QStringLiteral("Node 3 is enabled")), qPrintable(asked));
        checkDisabledBeforeClose(journal);
    }

    // Bus ▸ Connect to virtual drives again (after "save first?": Discard): the question says
    // "connect anew"; Cancel keeps the connection and the drive; Yes disables it (in the old
    // capture's journal) before the new connection replaces the old one.
    void connectingAnewAsksAndDisables() {
        connectAndEnable();
        if (QTest::currentTestFailed()) return;
        const QString journal = ws()->journalPath();
        const auto before = ws()->store();
        {
            QString saveAsked, asked;
            auto discard = answerBox(QMessageBox::Discard, &saveAsked);
            auto cancel = answerBox(QMessageBox::Cancel, &asked);
            QVERIFY(clickMenuItem(*w_, QStringLiteral("Bus"), QStringLiteral("Connect to virtual drives")));
            QVERIFY(waitFor([&] { return !asked.isEmpty(); }, 5000));
            QVERIFY2(
                asked.contains(QStringLiteral("Node 3 is enabled")) && asked.contains(QStringLiteral("connect anew")),
                qPrintable(asked));
        }
        QTest::qWait(300);
        QCOMPARE(ws()->store(), before);
        QVERIFY(ws()->canTransmit());
        QCOMPARE(driveState(), State::OperationEnabled);
        QString saveAsked, asked;
        auto discard = answerBox(QMessageBox::Discard, &saveAsked);
        auto yes = answerBox(QMessageBox::Yes, &asked);
        QVERIFY(clickMenuItem(*w_, QStringLiteral("Bus"), QStringLiteral("Connect to virtual drives")));
        QVERIFY(waitFor([&] { return !asked.isEmpty() && ws()->store() != before; }, 5000));
        checkDisabledBeforeClose(journal, false);
    }
};

QTEST_MAIN(TestSafeClose)
#include "test_safe_close.moc"
