// SPDX-License-Identifier: GPL-3.0-or-later
// The technician's walk (issue 12): the main window on the virtual drives as `coscope --simulate`
// starts it, driven only by input events, as a hand on the mouse and keyboard does. Each wizard
// is opened from the Commission menu (a click on the menu bar, or Alt+C and the arrow keys) and
// run to its end: a PDO remapped and applied; node 3 changed to node 7, then found in the Nodes
// dock with its dictionary; node 1 enabled and disabled with the CiA 402 wizard, which closes
// with Close and with Esc and leaves the drive disabled; last, a listen-only connection made in
// the Connect dialog, where the Commission items are disabled. The steps run in order on one
// window, as one walk.
#include "app/gui/MainWindow.h"
#include "app/gui/connect/ConnectDialog.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/od/ObjectDictionaryDock.h"
#include "app/gui/od/OdTreeModel.h"
#include "app/gui/session/SimulationDemo.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/common/WizardFramesPane.h"
#include "app/gui/wizards/ds402/Ds402Wizard.h"
#include "app/gui/wizards/nodeid/NodeIdPages.h"
#include "app/gui/wizards/nodeid/NodeIdWizard.h"
#include "app/gui/wizards/pdo/PdoWizard.h"
#include "core/canopen/PdoConfigurator.h"
#include "core/sim/Ds402Drive.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"

#include <QAbstractButton>
#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QMenuBar>
#include <QPointer>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTableView>
#include <QTableWidget>
#include <QTreeView>
#include <QtTest>

#include "tests/gui/WaitFor.h"

#include <memory>

#include "tests/gui/ModalAnswer.h"

using namespace coscope;
using namespace coscope::gui;
using canopen::ds402::State;
using coscope::testing::answerBox;
using coscope::testing::ModalAnswerer;

namespace {
using coscope::testing::waitFor;
QString plain(QString text) { return text.remove(u'&'); }

void click(QWidget* w) { QTest::mouseClick(w, Qt::LeftButton, {}, w->rect().center()); }
// What the mouse sends for a double click: press, release, double-click, release.
void doubleClick(QWidget* w, QPoint at) {
    QTest::mouseClick(w, Qt::LeftButton, {}, at);
    QTest::mouseDClick(w, Qt::LeftButton, {}, at);
    QTest::mouseRelease(w, Qt::LeftButton, {}, at);
}

// The Commission menu as the user opens it: a click on its title in the menu bar, or Alt+C.
QMenu* openCommission(QMainWindow& w, bool byKeys) {
    QAction* title = nullptr;
    for (QAction* a : w.menuBar()->actions())
        if (plain(a->text()) == u"Commission") title = a;
    if (!title || !title->menu()) return nullptr;
    if (byKeys) {
        // The keys go to the active window: a window manager gives the focus back to the main
        // window when a wizard closes; offscreen there is none, so do its part.
        w.activateWindow();
        if (!QTest::qWaitForWindowActive(&w)) return nullptr;
        QTest::keyClick(&w, Qt::Key_C, Qt::AltModifier);
    } else QTest::mouseClick(w.menuBar(), Qt::LeftButton, {}, w.menuBar()->actionGeometry(title).center());
    QMenu* menu = title->menu();
    return waitFor([&] { return menu->isVisible(); }, 3000) ? menu : nullptr;
}
// Opens Commission and picks the item that starts with `item`: by a click, or by the arrow
// keys and Enter.
bool pickCommission(QMainWindow& w, const QString& item, bool byKeys) {
    QMenu* menu = openCommission(w, byKeys);
    if (!menu) return false;
    QAction* wanted = nullptr;
    for (QAction* a : menu->actions())
        if (plain(a->text()).startsWith(item)) wanted = a;
    if (!wanted || !wanted->isEnabled()) {
        QTest::keyClick(menu, Qt::Key_Escape);
        return false;
    }
    if (!byKeys) {
        QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(wanted).center());
        return true;
    }
    for (int i = 0; i <= menu->actions().size() && menu->activeAction() != wanted; ++i)
        QTest::keyClick(menu, Qt::Key_Down);
    if (menu->activeAction() != wanted) return false;
    QTest::keyClick(menu, Qt::Key_Return);
    return true;
}
// Bus ▸ Connect… by a click on the menu bar and on the item.
bool clickBusConnect(QMainWindow& w) {
    for (QAction* top : w.menuBar()->actions()) {
        if (plain(top->text()) != u"Bus" || !top->menu()) continue;
        QTest::mouseClick(w.menuBar(), Qt::LeftButton, {}, w.menuBar()->actionGeometry(top).center());
        QMenu* menu = top->menu();
        if (!waitFor([&] { return menu->isVisible(); }, 3000)) return false;
        for (QAction* a : menu->actions())
            if (plain(a->text()).startsWith(QStringLiteral("Connect…"))) {
                QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(a).center());
                return true;
            }
    }
    return false;
}
template <typename W>
W* findTopLevel() {
    for (QWidget* w : QApplication::topLevelWidgets())
        if (auto* t = qobject_cast<W*>(w); t && t->isVisible()) return t;
    return nullptr;
}
// Selects what is in the field and types `text` over it.
void typeOver(QWidget* field, const QString& text) {
    QTest::mouseClick(field, Qt::LeftButton, {}, field->rect().center());
    QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(field, text);
}
// Chooses the item that starts with `text` in a combo box with the keyboard (Home, then Down).
bool pickWithKeys(QComboBox* box, const QString& text) {
    click(box);  // opens the list; Escape closes it again with the focus on the box
    if (QWidget* popup = QApplication::activePopupWidget()) QTest::keyClick(popup, Qt::Key_Escape);
    QTest::keyClick(box, Qt::Key_Home);
    for (int i = 0; i < box->count() && !box->currentText().startsWith(text); ++i) QTest::keyClick(box, Qt::Key_Down);
    return box->currentText().startsWith(text);
}
QPushButton* buttonNamed(QWidget* w, const QString& text) {
    for (QPushButton* b : w->findChildren<QPushButton*>())
        if (b->text() == text && b->isVisible()) return b;
    return nullptr;
}
// Whether the wizard's frames pane shows its newest row (the last request or answer) where
// the user looks, at the bottom of the pane.
bool paneShowsNewest(QWidget* wizard) {
    auto* pane = wizard->findChild<WizardFramesPane*>();
    auto* view = pane ? pane->findChild<QTableView*>(QStringLiteral("wizardFrames")) : nullptr;
    if (!view || !view->isVisible() || view->model()->rowCount() == 0) return false;
    const QRect last = view->visualRect(view->model()->index(view->model()->rowCount() - 1, 0));
    return last.isValid() && view->viewport()->rect().contains(last);
}
// With COSCOPE_GRAB_DIR set, saves the window as NAME.png there (README pictures of each step).
void shot(QWidget* w, const char* name) {
    const QString dir = qEnvironmentVariable("COSCOPE_GRAB_DIR");
    if (dir.isEmpty()) return;
    QTest::qWait(300);  // let the last answers and repaints land
    w->grab().save(QStringLiteral("%1/%2.png").arg(dir, QLatin1String(name)));
}
// Clicks the Nodes dock's row of `node`.
bool clickNodeInDock(NodesDock* dock, int node) {
    const int row = dock->model()->rowOfNode(node);
    if (row < 0) return false;
    QTableView* view = dock->view();
    const QModelIndex index = view->model()->index(row, NodesModel::Node);
    view->scrollTo(index);
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->visualRect(index).center());
    return true;
}
}  // namespace

class TestTechnicianWalk : public QObject {
    Q_OBJECT
    std::unique_ptr<MainWindow> w_;

    Workspace* ws() const { return w_->workspace(); }
    sim::SimNetwork* net() const { return static_cast<SimBus*>(ws()->bus())->network(); }
    // The drive's own state, from the virtual drive (not from what the wizard shows).
    State driveState(int node) const {
        State s = State::Unknown;
        net()->runOnNetworkThread([&] {
            if (auto* d = net()->device(static_cast<uint8_t>(node)); d && d->drive(0)) s = d->drive(0)->state();
        });
        return s;
    }
    QString dictionaryInDock(int node) const {
        NodesModel* m = w_->nodesDock()->model();
        const int row = m->rowOfNode(node);
        return row < 0 ? QString() : m->data(m->index(row, NodesModel::Dictionary), Qt::DisplayRole).toString();
    }
    // Opens the CiA 402 wizard from the menu and waits until it has read its drive.
    Ds402Wizard* openDs402(bool byKeys) {
        if (!pickCommission(*w_, QStringLiteral("CiA 402 enable"), byKeys)) return nullptr;
        Ds402Wizard* wiz = nullptr;
        if (!waitFor([&] { return (wiz = findTopLevel<Ds402Wizard>()) != nullptr; })) return nullptr;
        return QTest::qWaitForWindowExposed(wiz) ? wiz : nullptr;
    }
    // Shutdown, Switch on, Enable operation… by clicks on the step buttons; Yes to the question.
    bool enableByClicks(Ds402Wizard* wiz, int node) {
        auto stepTo = [&](canopen::ds402::Command c, State expect) {
            QPushButton* b = wiz->stepButton(c);
            if (!waitFor([&] { return b->isEnabled(); }, 6000)) return false;
            click(b);
            return waitFor([&] { return driveState(node) == expect && wiz->shownState() == expect; }, 6000);
        };
        if (!stepTo(canopen::ds402::Command::Shutdown, State::ReadyToSwitchOn)) return false;
        if (!stepTo(canopen::ds402::Command::SwitchOn, State::SwitchedOn)) return false;
        QString asked;
        auto yes = answerBox(QMessageBox::Yes, &asked);
        if (!stepTo(canopen::ds402::Command::EnableOperation, State::OperationEnabled)) return false;
        return asked.contains(QStringLiteral("energises"));
    }
    QString statuswordShown(Ds402Wizard* wiz) const {
        return wiz->findChild<QLabel*>(QStringLiteral("statuswordValue"))->text();
    }

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_technician_walk"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
        // As `coscope --simulate` starts: the window, the virtual drives, the demo (scan, start).
        w_ = std::make_unique<MainWindow>();
        w_->show();
        QVERIFY(QTest::qWaitForWindowActive(w_.get()));
        QVERIFY(w_->connectBus(QStringLiteral("sim://")));
        startSimulationDemo(ws());
        QVERIFY(waitFor([&] { return ws()->canTransmit(); }));
        // The scan identified the three drives (1 Delta, 2 AIMOTOR, 3 generic CiA 402).
        QVERIFY2(
            waitFor([&] { return dictionaryInDock(1) == u"delta-asda-a2" && dictionaryInDock(3) == u"generic-cia402"; },
                    20000),
            qPrintable(dictionaryInDock(1) + u'/' + dictionaryInDock(3)));
    }

    // PDO mapping… by a click: node 1, TPDO2 chosen by keys; 606Ch and 6041h found by typing
    // and double-clicked into the message; Next to the last page, Apply; the drive reads back
    // the new mapping; Finish closes the window.
    void pdoMappingByClicks() {
        QVERIFY(pickCommission(*w_, QStringLiteral("PDO mapping"), false));
        PdoWizard* wiz = nullptr;
        QVERIFY(waitFor([&] { return (wiz = findTopLevel<PdoWizard>()) != nullptr; }));
        QPointer<PdoWizard> alive(wiz);
        QVERIFY(QTest::qWaitForWindowExposed(wiz));
        auto* nodeBox = wiz->findChild<QComboBox*>(QStringLiteral("pdoNode"));
        auto* pdoBox = wiz->findChild<QComboBox*>(QStringLiteral("pdoNumber"));
        QVERIFY(waitFor([&] { return nodeBox->count() >= 3; }));
        QVERIFY(pickWithKeys(nodeBox, QStringLiteral("Node 1")));
        QVERIFY(pickWithKeys(pdoBox, QStringLiteral("TPDO2")));
        QAbstractButton* next = wiz->button(QWizard::NextButton);
        QVERIFY2(waitFor([&] { return next->isEnabled() && wiz->state().node == 1 && wiz->state().pdo.number == 2; }),
                 qPrintable(wiz->readError()));
        shot(wiz, "wizard-pdo-1-choose");
        click(next);
        QCOMPARE(wiz->currentId(), int(PdoWizard::MappingPageId));

        auto* available = wiz->findChild<QListWidget*>(QStringLiteral("pdoAvailable"));
        auto* mapped = wiz->findChild<QListWidget*>(QStringLiteral("pdoMapped"));
        auto* search = wiz->findChild<QLineEdit*>(QStringLiteral("pdoSearch"));
        click(buttonNamed(wiz, QStringLiteral("Clear")));
        QCOMPARE(mapped->count(), 0);
        for (const QString& what : {QStringLiteral("606C"), QStringLiteral("6041")}) {
            typeOver(search, what);
            QListWidgetItem* first = nullptr;
            for (int i = 0; i < available->count() && !first; ++i)
                if (!available->item(i)->isHidden()) first = available->item(i);
            QVERIFY2(first && first->text().startsWith(what), qPrintable(what));
            available->scrollToItem(first);
            QTest::qWait(100);  // the list lays out its filtered rows
            doubleClick(available->viewport(), available->visualItemRect(first).center());
        }
        QCOMPARE(mapped->count(), 2);
        QVERIFY(mapped->item(0)->text().startsWith(QStringLiteral("606C")));
        QVERIFY(mapped->item(1)->text().startsWith(QStringLiteral("6041")));
        shot(wiz, "wizard-pdo-2-mapping");
        click(next);
        QCOMPARE(wiz->currentId(), int(PdoWizard::TimingPageId));
        QVERIFY(next->isEnabled());
        shot(wiz, "wizard-pdo-3-timing");
        click(next);
        QCOMPARE(wiz->currentId(), int(PdoWizard::ApplyPageId));
        auto* apply = wiz->currentPage()->findChild<QPushButton*>(QStringLiteral("pdoApply"));
        QVERIFY(apply && apply->isEnabled());
        click(apply);
        auto* result = wiz->findChild<QLabel*>(QStringLiteral("pdoResult"));
        QVERIFY2(waitFor([&] { return wiz->outcome() != PdoWizard::Outcome::None && !wiz->isApplying(); }, 30000),
                 qPrintable(result->text()));
        QVERIFY2(wiz->outcome() == PdoWizard::Outcome::Succeeded, qPrintable(result->text()));
        QVERIFY2(result->isVisible() && !result->text().isEmpty(), qPrintable(result->text()));
        QVERIFY2(waitFor([&] { return paneShowsNewest(wiz); }, 3000),
                 "the frames pane does not show the apply's frames");
        shot(wiz, "wizard-pdo-4-applied");

        // The drive itself now maps 606Ch, 6041h into TPDO2.
        canopen::PdoConfigurator cfg(*ws()->sdo());
        std::optional<canopen::PdoReadResult> read;
        cfg.read(1, canopen::PdoId{true, 2}, [&](const canopen::PdoReadResult& r) { read = r; });
        QVERIFY(waitFor([&] { return read.has_value(); }));
        QVERIFY2(read->ok, qPrintable(read->error));
        QCOMPARE(read->config.entries.size(), size_t(2));
        QCOMPARE(read->config.entries[0].index, uint16_t(0x606C));
        QCOMPARE(read->config.entries[1].index, uint16_t(0x6041));

        QAbstractButton* finish = wiz->button(QWizard::FinishButton);
        QVERIFY(finish->isVisible() && finish->isEnabled());
        click(finish);
        QVERIFY2(waitFor([&] { return !alive || !alive->isVisible(); }, 3000), "the PDO wizard is still open");
        QTRY_VERIFY(!alive);  // deleted on close
    }

    // Baud rate and node-ID… by Alt+C and the arrow keys: node 3 clicked in the list, 7 typed,
    // Next to the dry run, Change it now, Finish. The Nodes dock lists node 7 with its
    // dictionary and no node 3; a click on node 7 shows its dictionary in the Object Dictionary.
    void nodeIdThreeToSeven() {
        QVERIFY(pickCommission(*w_, QStringLiteral("Baud rate and node-ID"), true));
        NodeIdWizard* wiz = nullptr;
        QVERIFY(waitFor([&] { return (wiz = findTopLevel<NodeIdWizard>()) != nullptr; }));
        QPointer<NodeIdWizard> alive(wiz);
        QVERIFY(QTest::qWaitForWindowExposed(wiz));
        QTableWidget* table = wiz->findPage()->nodeTable();
        int row = -1;
        QVERIFY(waitFor([&] {
            for (int r = 0; r < table->rowCount(); ++r)
                if (table->item(r, 0) && table->item(r, 0)->text() == u"3") row = r;
            return row >= 0;
        }));
        QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, table->visualItemRect(table->item(row, 0)).center());
        auto* target = wiz->findChild<QLabel*>(QStringLiteral("target"));
        QVERIFY2(waitFor([&] { return target->text().contains(QStringLiteral("node 3")); }, 3000),
                 qPrintable(target->text()));
        QAbstractButton* next = wiz->button(QWizard::NextButton);
        QVERIFY(next->isEnabled());
        shot(wiz, "wizard-nodeid-1-find");
        click(next);
        QCOMPARE(wiz->currentId(), int(NodeIdWizard::ChangePageId));
        auto* newId = wiz->findChild<QAbstractSpinBox*>(QStringLiteral("newNodeId"));
        typeOver(newId->findChild<QLineEdit*>(), QStringLiteral("7"));
        QCOMPARE(newId->text(), QStringLiteral("7"));
        QVERIFY2(waitFor([&] { return next->isEnabled(); }, 3000), qPrintable(wiz->blockingProblem()));
        shot(wiz, "wizard-nodeid-2-change");
        click(next);
        QCOMPARE(wiz->currentId(), int(NodeIdWizard::RunPageId));
        QPushButton* run = wiz->runPage()->runButton();
        QVERIFY2(waitFor([&] { return run->isEnabled(); }, 8000), qPrintable(wiz->planError()));
        shot(wiz, "wizard-nodeid-3-dry-run");
        click(run);
        QLabel* status = wiz->runPage()->statusLabel();
        QVERIFY2(waitFor([&] { return wiz->outcome() != NodeIdWizard::Outcome::None && !wiz->isRunning(); }, 30000),
                 qPrintable(status->text()));
        QVERIFY2(wiz->outcome() == NodeIdWizard::Outcome::Succeeded, qPrintable(status->text()));
        QVERIFY2(status->text().contains(QStringLiteral("node-ID 7")), qPrintable(status->text()));
        QVERIFY2(waitFor([&] { return paneShowsNewest(wiz); }, 3000),
                 "the frames pane does not show the change's frames");
        shot(wiz, "wizard-nodeid-4-done");
        QAbstractButton* finish = wiz->button(QWizard::FinishButton);
        QVERIFY(finish->isVisible() && finish->isEnabled());
        click(finish);
        QVERIFY2(waitFor([&] { return !alive || !alive->isVisible(); }, 3000), "the node-ID wizard is still open");

        // The Nodes dock: node 7 with its dictionary, no node 3.
        QVERIFY2(waitFor([&] { return dictionaryInDock(7) == u"generic-cia402"; }, 15000),
                 qPrintable(dictionaryInDock(7)));
        QVERIFY(waitFor([&] { return w_->nodesDock()->model()->rowOfNode(3) < 0; }));
        QVERIFY(clickNodeInDock(w_->nodesDock(), 7));
        ObjectDictionaryDock* od = w_->odDock();
        QVERIFY(waitFor([&] { return od->node() == 7 && od->model()->hasDictionary(); }));
        auto* header = od->findChild<QLabel*>(QStringLiteral("odHeader"));
        QVERIFY(header->isVisible());
        QVERIFY2(header->text().contains(QStringLiteral("Node 7")) &&
                     header->text().contains(QStringLiteral("generic-cia402")),
                 qPrintable(header->text()));
        QVERIFY(od->view()->isVisible());
    }

    // CiA 402 enable step-through… by a click (it opens on node 7, selected in the Nodes dock):
    // node 1 chosen in its list by keys, enabled by the step buttons (Yes to the question),
    // Disable, Close: the window is gone and the drive stays disabled.
    void ds402EnableDisableAndClose() {
        Ds402Wizard* wiz = openDs402(false);
        QVERIFY(wiz);
        QPointer<Ds402Wizard> alive(wiz);
        auto* nodeBox = wiz->findChild<QComboBox*>(QStringLiteral("nodeCombo"));
        QVERIFY(waitFor([&] { return wiz->node() == 7; }));
        QVERIFY(pickWithKeys(nodeBox, QStringLiteral("Node 1")));
        QVERIFY(waitFor([&] { return wiz->node() == 1 && wiz->shownState() == State::SwitchOnDisabled; }, 8000));
        shot(wiz, "wizard-ds402-1-disabled");
        QVERIFY(enableByClicks(wiz, 1));
        QVERIFY2(statuswordShown(wiz).contains(QStringLiteral("Operation enabled")), qPrintable(statuswordShown(wiz)));
        // The message under the steps writes the statusword as the rest of the app does (0637h).
        const QString said = wiz->findChild<QLabel*>(QStringLiteral("message"))->text();
        QVERIFY2(said.contains(QStringLiteral("statusword 0637h")) && !said.contains(QStringLiteral("0x")),
                 qPrintable(said));
        QVERIFY2(waitFor([&] { return paneShowsNewest(wiz); }, 3000),
                 "the frames pane does not show the steps' frames");
        shot(wiz, "wizard-ds402-2-enabled");
        click(wiz->disableButton());
        QVERIFY(waitFor([&] { return driveState(1) == State::SwitchOnDisabled; }, 5000));
        QVERIFY2(waitFor([&] { return statuswordShown(wiz).contains(QStringLiteral("Switch on disabled")); }, 5000),
                 qPrintable(statuswordShown(wiz)));
        click(buttonNamed(wiz, QStringLiteral("Close")));
        QVERIFY2(waitFor([&] { return !alive || !alive->isVisible(); }, 3000),
                 "the CiA 402 wizard is still open after Close");
        QTRY_VERIFY(!alive);
        QTest::qWait(500);
        QCOMPARE(driveState(1), State::SwitchOnDisabled);
    }

    // Node 1 clicked in the Nodes dock, the wizard opened again by Alt+C and the arrow keys,
    // the drive enabled, then Esc: the window is gone and the drive disabled.
    void ds402EnableAndEscape() {
        QVERIFY(clickNodeInDock(w_->nodesDock(), 1));
        QVERIFY(waitFor([&] { return w_->nodesDock()->selectedNode() == 1; }, 3000));
        Ds402Wizard* wiz = openDs402(true);
        QVERIFY(wiz);
        QPointer<Ds402Wizard> alive(wiz);
        QCOMPARE(wiz->node(), 1);
        QVERIFY(waitFor([&] { return wiz->shownState() == State::SwitchOnDisabled; }, 8000));
        QVERIFY(enableByClicks(wiz, 1));
        QCOMPARE(driveState(1), State::OperationEnabled);
        QTest::keyClick(wiz, Qt::Key_Escape);
        QVERIFY2(waitFor([&] { return !alive || !alive->isVisible(); }, 3000),
                 "the CiA 402 wizard is still open after Esc");
        QVERIFY(waitFor([&] { return driveState(1) == State::SwitchOnDisabled; }, 5000));
        QTRY_VERIFY(!alive);
    }

    // Bus ▸ Connect…: the virtual drives with "Listen only" ticked, OK; Discard the unsaved
    // capture. The Commission items are disabled and clicking one opens nothing.
    void listenOnlyDisablesCommission() {
        auto connect = std::make_unique<ModalAnswerer>([](QWidget* w) {
            auto* dialog = qobject_cast<ConnectDialog*>(w);
            if (!dialog) return false;
            if (dialog->backend()->currentData().toString() != u"sim") return false;
            QCheckBox* listen = dialog->listenOnly();
            if (!listen->isChecked()) QTest::mouseClick(listen, Qt::LeftButton, {}, QPoint(8, listen->height() / 2));
            auto* url = dialog->findChild<QLineEdit*>(QStringLiteral("urlPreview"));
            if (!listen->isChecked() || !url || !url->text().contains(QStringLiteral("listen-only=1"))) return false;
            auto* buttons = dialog->findChild<QDialogButtonBox*>();
            QAbstractButton* ok = buttons ? buttons->button(QDialogButtonBox::Ok) : nullptr;
            if (!ok) return false;
            click(ok);
            return true;
        });
        QString asked;
        auto discard = answerBox(QMessageBox::Discard, &asked);
        QVERIFY(clickBusConnect(*w_));
        QVERIFY(waitFor([&] { return connect->answered(); }));
        QVERIFY2(waitFor([&] {
                     return ws()->bus() && ws()->bus()->isListenOnly() && ws()->bus()->state() == CanBus::State::Open;
                 }),
                 qPrintable(w_->lastError()));
        QVERIFY2(asked.contains(QStringLiteral("not saved")), qPrintable(asked));
        QTest::qWait(200);
        QMenu* menu = openCommission(*w_, false);
        QVERIFY(menu);
        int items = 0;
        for (QAction* a : menu->actions()) {
            if (a->isSeparator()) continue;
            ++items;
            QVERIFY2(!a->isEnabled(), qPrintable(a->text() + QStringLiteral(" is enabled on a listen-only bus")));
        }
        QCOMPARE(items, 3);
        // A click on a disabled item opens nothing.
        QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(menu->actions().first()).center());
        QTest::qWait(300);
        if (menu->isVisible()) QTest::keyClick(menu, Qt::Key_Escape);
        QVERIFY(!findTopLevel<NodeIdWizard>() && !findTopLevel<Ds402Wizard>() && !findTopLevel<PdoWizard>());
        QCOMPARE(ws()->bus()->counters().tx, uint64_t(0));
    }

    // A step that failed may leave its wizard open: close it, so the next step starts as the
    // walk expects (the steps check closing themselves).
    void cleanup() {
        for (QWidget* t : QApplication::topLevelWidgets())
            if (t != w_.get() && t->isVisible() &&
                (qobject_cast<NodeIdWizard*>(t) || qobject_cast<Ds402Wizard*>(t) || qobject_cast<PdoWizard*>(t)))
                t->close();
        QTest::qWait(100);
    }

    void cleanupTestCase() {
        if (!w_) return;
        w_->setQuiet(true);  // the walk is over: no "save first?" for the capture
        w_.reset();
    }
};

QTEST_MAIN(TestTechnicianWalk)
#include "test_technician_walk.moc"
