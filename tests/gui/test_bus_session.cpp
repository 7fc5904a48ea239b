// SPDX-License-Identifier: GPL-3.0-or-later
// What the window shows when the source changes, driven by clicks as a technician does: every
// connection scans and identifies the nodes (Bus ▸ Connect to virtual drives, again and again),
// Scan network is in the Bus menu and on the toolbar, the Commission items wait for a bus, and
// another bus or log leaves nothing of the previous one in the Object Dictionary and Plot docks
// (the Plot's empty list says why it is empty).
#include "app/gui/MainWindow.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/od/ObjectDictionaryDock.h"
#include "app/gui/plot/PlotDock.h"
#include "app/gui/plot/SignalPicker.h"
#include "app/gui/session/Workspace.h"
#include "eds/SimulatorDictionaries.h"

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QSettings>
#include <QTableView>
#include <QTemporaryDir>
#include <QToolBar>
#include <QtTest>

#include "tests/gui/MenuClick.h"
#include "tests/gui/OpenLog.h"
#include "tests/gui/WaitFor.h"

#include "tests/gui/ModalAnswer.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::answerBox;
using coscope::testing::answerFileDialog;
using coscope::testing::openLogByMenu;

namespace {
using coscope::testing::clickMenuItem;
using coscope::testing::menuItem;
using coscope::testing::openMenu;
using coscope::testing::waitFor;
QString plain(const QString& t) { return coscope::testing::withoutAccelerator(t); }

// The Dictionary column of every node row, as the Nodes dock shows it.
QStringList dictionaryColumn(MainWindow& w) {
    QStringList out;
    NodesModel* m = w.nodesDock()->model();
    for (int r = 0; r < m->rowCount(); ++r)
        out << m->data(m->index(r, NodesModel::Dictionary), Qt::DisplayRole).toString();
    return out;
}
bool identified(MainWindow& w, int nodes) {
    const QStringList d = dictionaryColumn(w);
    return d.size() >= nodes && d.count(QStringLiteral("delta-asda-a2")) == 1;
}
// Clicks the row of `node` in the Nodes dock.
bool clickNode(MainWindow& w, int node) {
    QTableView* view = w.nodesDock()->view();
    const int row = w.nodesDock()->model()->rowOfNode(node);
    if (row < 0) return false;
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->visualRect(view->model()->index(row, 0)).center());
    return w.nodesDock()->selectedNode() == node;
}
// Chooses `name` in the OD dock's dictionary list by typing, then clicks Assign dictionary.
bool assignInOdDock(MainWindow& w, const QString& name) {
    auto* choice = w.odDock()->findChild<QComboBox*>();
    if (!choice || !choice->isVisible()) return false;
    QTest::mouseClick(choice, Qt::LeftButton);  // opens the list
    if (!waitFor([&] { return choice->view()->isVisible(); })) return false;
    // Down the list by the arrow key to the name (typing races the list's search interval).
    QTest::keyClick(choice->view(), Qt::Key_Home);
    for (int i = 0; i < choice->count() && choice->view()->currentIndex().data().toString() != name; ++i)
        QTest::keyClick(choice->view(), Qt::Key_Down);
    QTest::keyClick(choice->view(), Qt::Key_Return);
    if (choice->currentText() != name) {
        QStringList items;
        for (int i = 0; i < choice->count(); ++i) items << choice->itemText(i);
        qWarning("chose %s of %s", qPrintable(choice->currentText()), qPrintable(items.join(u',')));
        return false;
    }
    for (auto* b : w.odDock()->findChildren<QPushButton*>())
        if (b->text() == QStringLiteral("Assign dictionary")) {
            QTest::mouseClick(b, Qt::LeftButton);
            return true;
        }
    return false;
}
QLabel* odHeader(MainWindow& w) { return w.odDock()->findChild<QLabel*>(QStringLiteral("odHeader")); }
// A candump log: heartbeats of node 5 and, with `pdos`, its TPDO1 (181h + 4) without a mapping.
QString writeLog(const QString& path, bool pdos) {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    for (int i = 0; i < 50; ++i) {
        f.write(QStringLiteral("(1700000000.%1) can0 705#05\n").arg(i * 10000, 6, 10, QLatin1Char('0')).toLatin1());
        if (pdos)
            f.write(QStringLiteral("(1700000000.%1) can0 185#0102030405060708\n")
                        .arg(i * 10000 + 5000, 6, 10, QLatin1Char('0'))
                        .toLatin1());
    }
    return path;
}
}  // namespace

class TestBusSession : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_bus_session"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
        QVERIFY(dir_.isValid());
    }

    void everyConnectionIdentifiesTheNodes() {
        MainWindow w;
        w.setQuiet(true);  // no "save first?" between the connections
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        for (int round = 0; round < 2; ++round) {
            const auto before = w.workspace()->store();
            QVERIFY(clickMenuItem(w, QStringLiteral("Bus"), QStringLiteral("Connect to virtual drives")));
            QVERIFY(waitFor([&] { return w.workspace()->store() != before && w.workspace()->isLive(); }));
            // The nodes get their identity and dictionary (the Delta drive by its 1018h), not "(none)".
            QVERIFY2(waitFor([&] { return identified(w, 3); }), qPrintable(dictionaryColumn(w).join(u',')));
        }
    }

    void scanIsInTheBusMenuAndOnTheToolbar() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        // Not connected: the Bus menu's Scan network is there, disabled, and says why.
        QMenu* bus = openMenu(w, QStringLiteral("Bus"));
        QVERIFY(bus);
        QAction* scan = menuItem(bus, QStringLiteral("Scan network"));
        QVERIFY(scan);
        QVERIFY(!scan->isEnabled());
        QVERIFY2(scan->statusTip().contains(QStringLiteral("Connect")), qPrintable(scan->statusTip()));
        QTest::keyClick(bus, Qt::Key_Escape);

        QVERIFY(w.connectBus(QStringLiteral("sim://")));  // a connection that does not scan by itself
        QVERIFY(waitFor([&] { return w.workspace()->canTransmit() && w.nodesDock()->model()->rowCount() >= 3; }));
        QTest::qWait(300);
        QVERIFY(!identified(w, 3));
        // Bus ▸ Scan network, confirmed: the nodes are identified.
        QString asked;
        auto yes = answerBox(QMessageBox::Yes, &asked);
        QVERIFY(waitFor([&] { return w.nodesDock()->scanAction()->isEnabled(); }));
        QVERIFY(clickMenuItem(w, QStringLiteral("Bus"), QStringLiteral("Scan network")));
        QVERIFY(waitFor([&] { return yes->answered(); }));
        QVERIFY2(asked.contains(QStringLiteral("1000h")), qPrintable(asked));
        QVERIFY2(waitFor([&] { return identified(w, 3); }), qPrintable(dictionaryColumn(w).join(u',')));

        // Again on a fresh connection, by the toolbar's button.
        QVERIFY(w.connectBus(QStringLiteral("sim://")));
        QVERIFY(waitFor([&] { return w.workspace()->canTransmit() && w.nodesDock()->model()->rowCount() >= 3; }));
        QVERIFY(!identified(w, 3));
        auto* toolbar = w.findChild<QToolBar*>(QStringLiteral("busToolBar"));
        QVERIFY(toolbar && toolbar->isVisible());
        QWidget* button = toolbar->widgetForAction(w.nodesDock()->scanAction());
        QVERIFY(button && button->isVisible());
        QVERIFY(waitFor([&] { return button->isEnabled(); }));
        asked.clear();
        auto again = answerBox(QMessageBox::Yes, &asked);
        QTest::mouseClick(button, Qt::LeftButton);
        QVERIFY(waitFor([&] { return again->answered(); }));
        QVERIFY2(waitFor([&] { return identified(w, 3); }), qPrintable(dictionaryColumn(w).join(u',')));
    }

    void commissionWaitsForABus() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        auto check = [&](bool expectEnabled) {
            QMenu* menu = openMenu(w, QStringLiteral("Commission"));
            if (!menu) return QStringLiteral("no Commission menu");
            QString problem;
            QString section;
            int items = 0;
            for (QAction* a : menu->actions()) {
                if (a->isSeparator()) {
                    if (a->isVisible()) section += a->text();
                    continue;
                }
                ++items;
                if (a->isEnabled() != expectEnabled)
                    problem += plain(a->text()) +
                               (a->isEnabled() ? QStringLiteral(" enabled; ") : QStringLiteral(" disabled; "));
                if (!expectEnabled && !a->toolTip().contains(QStringLiteral("Connect to a bus first")))
                    problem += QStringLiteral("tooltip: ") + a->toolTip() + u';';
                if (!expectEnabled && !a->statusTip().contains(QStringLiteral("Connect to a bus first")))
                    problem += QStringLiteral("status tip: ") + a->statusTip() + u';';
            }
            if (items < 3) problem += QStringLiteral("fewer than 3 items; ");
            // The reason is also a line of the menu (a section, not an item one could click).
            if (!expectEnabled && section != QStringLiteral("Connect to a bus first"))
                problem += QStringLiteral("section: ") + section;
            if (expectEnabled && !section.isEmpty())
                problem += QStringLiteral("section shown while enabled: ") + section;
            // A click on a disabled item opens nothing.
            if (!expectEnabled) {
                QAction* first = menuItem(menu, QStringLiteral("CiA 402"));
                QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(first).center());
                QTest::qWait(100);
                for (QWidget* top : QApplication::topLevelWidgets())
                    if (top != &w && top->isVisible() && !qobject_cast<QMenu*>(top))
                        problem += QStringLiteral("a window opened: ") + top->windowTitle() + u';';
            }
            if (menu->isVisible()) QTest::keyClick(menu, Qt::Key_Escape);
            return problem;
        };
        QString problem = check(false);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));

        QVERIFY(clickMenuItem(w, QStringLiteral("Bus"), QStringLiteral("Connect to virtual drives")));
        QVERIFY(waitFor([&] { return w.workspace()->canTransmit(); }));
        QTest::qWait(100);
        problem = check(true);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));

        QVERIFY(clickMenuItem(w, QStringLiteral("Bus"), QStringLiteral("Disconnect")));
        QVERIFY(waitFor([&] { return !w.workspace()->isLive(); }));
        QTest::qWait(100);
        problem = check(false);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }

    void anotherSourceLeavesNothingOfThePreviousOne() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        w.showView(QStringLiteral("od"));
        QVERIFY(w.connectBus(QStringLiteral("sim://")));
        QVERIFY(waitFor([&] { return w.nodesDock()->model()->rowOfNode(2) >= 0; }));
        // Node 2 chosen in the Nodes dock, a dictionary assigned in the OD dock by its button.
        QVERIFY(clickNode(w, 2));
        QVERIFY(waitFor([&] { return odHeader(w)->text().contains(QStringLiteral("Node 2")); }));
        QVERIFY(assignInOdDock(w, QStringLiteral("aimotor")));
        QVERIFY2(w.odDock()->messageText().contains(QStringLiteral("aimotor")), qPrintable(w.odDock()->messageText()));

        // A log of another network (node 5, its PDO without a mapping): no node shown, no message.
        QVERIFY(openLogByMenu(w, writeLog(dir_.filePath(QStringLiteral("node5.log")), true)));
        QVERIFY(waitFor([&] { return w.nodesDock()->model()->rowCount() == 1; }));
        QTest::qWait(100);
        QVERIFY2(!odHeader(w)->text().contains(QStringLiteral("Node 2")), qPrintable(odHeader(w)->text()));
        QVERIFY2(odHeader(w)->text().contains(QStringLiteral("No node selected")), qPrintable(odHeader(w)->text()));
        QVERIFY2(w.odDock()->messageText().isEmpty(), qPrintable(w.odDock()->messageText()));
        // The Plot's empty list says why and what there is: node 5's TPDO1 185h, no dictionary.
        w.showView(QStringLiteral("plot"));
        SignalPicker* picker = w.plotDock()->picker();
        QVERIFY(w.plotDock()->pickedSignals().empty());
        QVERIFY2(waitFor([&] {
                     const QString t = picker->hintText();
                     return t.contains(QStringLiteral("No dictionary")) && t.contains(QStringLiteral("185h")) &&
                            t.contains(QStringLiteral("node 5")) && t.contains(QStringLiteral("Assign dictionary"));
                 }),
                 qPrintable(picker->hintText()));

        // As offered: node 5 gets a dictionary (its TPDO1 carries the statusword 6041h by
        // default): the list shows the signal, the reason goes.
        w.showView(QStringLiteral("od"));
        QVERIFY(clickNode(w, 5));
        QVERIFY(waitFor([&] { return odHeader(w)->text().contains(QStringLiteral("Node 5")); }));
        QVERIFY(assignInOdDock(w, QStringLiteral("generic-cia402")));
        const dissect::SignalKey status5{0, 5, 0x6041, 0, -1};
        QVERIFY2(waitFor([&] { return picker->info(status5) && picker->hintText().isEmpty(); }),
                 qPrintable(picker->hintText()));
        QVERIFY(picker->catalog().size() > 1);

        // A log without PDOs: the list says so and names the nodes seen.
        QVERIFY(openLogByMenu(w, writeLog(dir_.filePath(QStringLiteral("nopdo.log")), false)));
        QVERIFY2(waitFor([&] {
                     return picker->hintText().contains(QStringLiteral("No PDOs")) &&
                            picker->hintText().contains(QStringLiteral("5"));
                 }),
                 qPrintable(picker->hintText()));

        // Another bus: node 2 chosen again, then a listen-only connection: nothing of it stays.
        w.showView(QStringLiteral("od"));
        QVERIFY(w.connectBus(QStringLiteral("sim://")));
        QVERIFY(waitFor([&] { return w.nodesDock()->model()->rowOfNode(2) >= 0; }));
        QVERIFY(clickNode(w, 2));
        QVERIFY(waitFor([&] { return odHeader(w)->text().contains(QStringLiteral("Node 2")); }));
        QVERIFY(w.connectBus(QStringLiteral("sim://?listen-only=1")));
        // No node, or one the new bus has shown since (its boot-ups select the first node seen),
        // as listen-only: never node 2 of the bus before.
        QVERIFY2(
            waitFor([&] {
                const QString t = odHeader(w)->text();
                return t.contains(QStringLiteral("No node selected")) ||
                       (t.contains(QStringLiteral("listen-only: no SDO")) && !t.contains(QStringLiteral("Node 2<")));
            }),
            qPrintable(odHeader(w)->text()));
        QTest::qWait(200);
        QVERIFY2(!odHeader(w)->text().contains(QStringLiteral("Node 2<")), qPrintable(odHeader(w)->text()));
    }
};

QTEST_MAIN(TestBusSession)
#include "test_bus_session.moc"
