// SPDX-License-Identifier: GPL-3.0-or-later
// The Object Dictionary dock follows what the rest of the app changed (issue 35, item 7), in the
// real main window on sim://, through clicks: 6040h read in the dock shows 0006h after the CiA 402
// wizard's Shutdown and, for a node shown before, 0000h after its Disable when that node is shown
// again (never the value read before); a node moved from node-ID 3 to 7 by the node-ID wizard is
// followed to 7 with its dictionary, and node 3's values are gone. A PDO's transmission type 255
// reads "FFh (event)"; the statusword's bits are named by the mode of operation.
#include "app/gui/MainWindow.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/od/ObjectDictionaryDock.h"
#include "app/gui/od/OdFilterModel.h"
#include "app/gui/od/OdTreeModel.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/ds402/Ds402Wizard.h"
#include "app/gui/wizards/nodeid/NodeIdPages.h"
#include "app/gui/wizards/nodeid/NodeIdWizard.h"
#include "eds/SimulatorDictionaries.h"

#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QSpinBox>
#include <QTableView>
#include <QTreeView>
#include <QtTest>

#include "tests/gui/ContextMenuClick.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using canopen::ds402::Command;
using canopen::ds402::State;

namespace {
using coscope::testing::waitFor;
const QString kAll = QStringLiteral("sim://?nodes=1:delta-asda-a2,2:aimotor,3:dexmart-dev,4:generic-cia402");

void click(QAbstractButton* b) { QTest::mouseClick(b, Qt::LeftButton, {}, b->rect().center()); }

struct Window {
    MainWindow w;
    ObjectDictionaryDock* dock() { return w.odDock(); }
    bool open() {
        w.setQuiet(true);
        w.show();
        if (!QTest::qWaitForWindowExposed(&w)) return false;
        w.showView(QStringLiteral("od"));
        if (!w.connectBus(kAll)) return false;
        return waitFor([&] {
            for (int n = 1; n <= 4; ++n)
                if (!w.workspace()->nodes().node(n)) return false;
            return true;
        });
    }
    // Clicks the node's row in the Nodes dock.
    bool choose(int node) {
        QTableView* nodes = w.nodesDock()->view();
        const int row = w.nodesDock()->model()->rowOfNode(node);
        if (row < 0) return false;
        QTest::mouseClick(nodes->viewport(), Qt::LeftButton, {},
                          nodes->visualRect(nodes->model()->index(row, 1)).center());
        w.refresh();
        return dock()->model()->node() == node && dock()->model()->hasDictionary();
    }
    // Types the index into the dock's search box, clicks the entry's row and Read in its menu.
    bool read(uint16_t index, uint8_t sub) {
        QLineEdit* search = dock()->searchBox();
        QTest::mouseClick(search, Qt::LeftButton);
        QTest::keyClick(search, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(search, QString::number(index, 16));
        dock()->view()->expandAll();
        const QModelIndex cell =
            dock()->filter()->mapFromSource(dock()->model()->indexOf(index, sub, OdTreeModel::Name));
        if (!cell.isValid()) return false;
        dock()->view()->scrollTo(cell);
        const QPoint at = dock()->view()->visualRect(cell).center();
        QTest::mouseClick(dock()->view()->viewport(), Qt::LeftButton, {}, at);
        if (!coscope::testing::contextMenuClick(dock()->view(), at, QStringLiteral("Read"))) return false;
        return waitFor([&] { return dock()->model()->state(index, sub) == OdTreeModel::State::Read; });
    }
    QString shown(uint16_t index, uint8_t sub) {
        return dock()
            ->model()
            ->data(dock()->model()->indexOf(index, sub, OdTreeModel::Value), Qt::DisplayRole)
            .toString();
    }
    QString header() { return dock()->findChild<QLabel*>(QStringLiteral("odHeader"))->text(); }
};

// Waits for the wizard's first state read of a drive that finished initialising.
bool waitReady(Ds402Wizard& wizard, QSignalSpy& read) {
    return waitFor(
        [&] {
            for (const auto& args : read)
                if (args.first().toBool() && wizard.shownState() == State::SwitchOnDisabled) return true;
            return false;
        },
        6000);
}
}  // namespace

class TestOdFollow : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_od_follow"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
    }

    void controlwordWrittenByTheWizard() {
        Window win;
        QVERIFY(win.open());
        win.w.nodesDock()->assignDictionary(1, QStringLiteral("delta-asda-a2"));
        win.w.nodesDock()->assignDictionary(2, QStringLiteral("aimotor"));
        win.w.refresh();
        QVERIFY(win.choose(1));
        // Units as written in SI: 1006h in µs, not "us".
        QCOMPARE(win.dock()
                     ->model()
                     ->data(win.dock()->model()->indexOf(0x1006, 0, OdTreeModel::Unit), Qt::DisplayRole)
                     .toString(),
                 QStringLiteral("µs"));
        QVERIFY(win.read(0x6040, 0));
        QVERIFY2(win.shown(0x6040, 0) != u"0006h" && !win.shown(0x6040, 0).isEmpty(), qPrintable(win.shown(0x6040, 0)));

        Ds402Wizard wizard(win.w.workspace(), 1);
        QSignalSpy read(&wizard, &Ds402Wizard::stateRead);
        wizard.show();
        QVERIFY(waitReady(wizard, read));
        QSignalSpy stepped(&wizard, &Ds402Wizard::stepFinished);
        QPushButton* shutdown = wizard.stepButton(Command::Shutdown);
        QVERIFY(shutdown && shutdown->isEnabled());
        click(shutdown);
        QVERIFY(stepped.count() > 0 || stepped.wait(6000));
        // The shown node: the controlword the wizard wrote, at once, no read asked for.
        QVERIFY2(waitFor([&] { return win.shown(0x6040, 0) == u"0006h"; }), qPrintable(win.shown(0x6040, 0)));

        // Another node shown meanwhile: node 1's kept 6040h is the wizard's Disable when shown again.
        QVERIFY(win.choose(2));
        QSignalSpy disabled(&wizard, &Ds402Wizard::stepFinished);
        click(wizard.disableButton());
        QVERIFY(waitFor([&] { return wizard.shownState() == State::SwitchOnDisabled && !wizard.isBusy(); }));
        QVERIFY(win.choose(1));
        QVERIFY2(waitFor([&] { return win.shown(0x6040, 0) == u"0000h"; }), qPrintable(win.shown(0x6040, 0)));
        wizard.close();
    }

    // The statusword's bits in the dock, 12/13 named by the mode of operation read with it, as
    // the trace and the plot name them (CiA 402-2 §14.1: PV bit 12 "zero speed").
    void statuswordBitsByMode() {
        Window win;
        QVERIFY(win.open());
        win.w.nodesDock()->assignDictionary(4, QStringLiteral("generic-cia402"));
        win.w.refresh();
        Ds402Wizard wizard(win.w.workspace(), 4);
        wizard.setAutoConfirm(true);
        QSignalSpy read(&wizard, &Ds402Wizard::stateRead);
        wizard.show();
        QVERIFY(waitReady(wizard, read));
        // Profile velocity chosen in the wizard's list and set, then enabled step by step.
        QComboBox* modes = wizard.modeCombo();
        const int pv = modes->findData(3);
        QVERIFY(pv >= 0);
        modes->setFocus();
        QTest::keyClick(modes, Qt::Key_Home);
        for (int i = 0; i < pv; ++i) QTest::keyClick(modes, Qt::Key_Down);
        QSignalSpy moded(&wizard, &Ds402Wizard::modeFinished);
        for (QPushButton* b : wizard.findChildren<QPushButton*>())
            if (b->text() == u"Set and verify") click(b);
        QVERIFY(moded.count() > 0 || moded.wait(6000));
        QCOMPARE(wizard.modeDisplay(), int8_t(3));
        for (Command c : {Command::Shutdown, Command::SwitchOn, Command::EnableOperation}) {
            QSignalSpy stepped(&wizard, &Ds402Wizard::stepFinished);
            QVERIFY(wizard.stepButton(c) && wizard.stepButton(c)->isEnabled());
            click(wizard.stepButton(c));
            QVERIFY(stepped.count() > 0 || stepped.wait(6000));
        }
        QVERIFY(waitFor([&] { return wizard.shownState() == State::OperationEnabled; }));

        QVERIFY(win.choose(4));
        QVERIFY(win.read(0x6061, 0));
        QVERIFY(win.read(0x6041, 0));
        const QString tip = win.dock()
                                ->model()
                                ->data(win.dock()->model()->indexOf(0x6041, 0, OdTreeModel::Value), Qt::ToolTipRole)
                                .toString();
        QVERIFY2(tip.contains(QStringLiteral("Bits on:")) && tip.contains(QStringLiteral("operation enabled")) &&
                     tip.contains(QStringLiteral("zero speed")),
                 qPrintable(tip));
        QVERIFY2(!tip.contains(QStringLiteral("operation mode specific")), qPrintable(tip));
        click(wizard.disableButton());
        QVERIFY(waitFor([&] { return wizard.shownState() == State::SwitchOnDisabled && !wizard.isBusy(); }));
        wizard.close();
    }

    // PDO transmission type 255 reads "FFh (event)", never "-1" or a bare 255 (CiA 301 §7.2.2.2).
    void transmissionTypeByName() {
        Window win;
        QVERIFY(win.open());
        win.w.nodesDock()->assignDictionary(4, QStringLiteral("generic-cia402"));
        win.w.refresh();
        QVERIFY(win.choose(4));
        QVERIFY(win.read(0x1800, 2));
        QCOMPARE(win.shown(0x1800, 2), QStringLiteral("FFh (event)"));
    }

    void nodeMovedByTheNodeIdWizard() {
        Window win;
        QVERIFY(win.open());
        win.w.nodesDock()->assignDictionary(3, QStringLiteral("dexmart-dev"));
        win.w.refresh();
        QVERIFY(win.choose(3));
        QVERIFY(win.read(0x1017, 0));
        QVERIFY(win.dock()->model()->valuesRead() > 0);

        NodeIdWizard wizard(win.w.workspace(), 3);
        wizard.show();
        QVERIFY(QTest::qWaitForWindowExposed(&wizard));
        click(wizard.button(QWizard::NextButton));
        click(wizard.findChild<QRadioButton*>(QStringLiteral("changeNodeId")));
        click(wizard.findChild<QRadioButton*>(QStringLiteral("viaLss")));
        QLineEdit* id = wizard.findChild<QAbstractSpinBox*>(QStringLiteral("newNodeId"))->findChild<QLineEdit*>();
        QTest::mouseClick(id, Qt::LeftButton);
        QTest::keyClick(id, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(id, QStringLiteral("7"));
        QSignalSpy ready(&wizard, &NodeIdWizard::dryRunReady);
        while (wizard.currentId() != NodeIdWizard::RunPageId) {
            QVERIFY2(wizard.button(QWizard::NextButton)->isEnabled(), qPrintable(wizard.blockingProblem()));
            click(wizard.button(QWizard::NextButton));
        }
        QVERIFY((ready.count() > 0 || ready.wait(8000)) && ready.last().at(0).toBool());
        QSignalSpy done(&wizard, &NodeIdWizard::finished);
        click(wizard.runPage()->runButton());
        QVERIFY(done.wait(30000) && done.last().at(0).toBool());
        wizard.close();

        // The dock follows the device: node 7, its dictionary, nothing of what was read at 3.
        QVERIFY(waitFor([&] {
            win.w.refresh();
            return win.dock()->node() == 7;
        }));
        QCOMPARE(win.dock()->dictionaryName(), QStringLiteral("dexmart-dev"));
        QVERIFY2(win.header().contains(QStringLiteral("Node 7")), qPrintable(win.header()));
        QCOMPARE(win.dock()->model()->valuesRead(), 0);
        QVERIFY2(win.dock()->messageText().contains(QStringLiteral("node-ID 7")),
                 qPrintable(win.dock()->messageText()));
        QVERIFY(win.read(0x1017, 0));  // node 7 answers
        QVERIFY(!win.w.workspace()->nodes().node(3));
    }
};

QTEST_MAIN(TestOdFollow)
#include "test_od_follow.moc"
