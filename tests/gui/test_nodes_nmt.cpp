// SPDX-License-Identifier: GPL-3.0-or-later
// The Nodes dock's NMT commands as a technician sends them, from the context menu of a node (or
// of all nodes) against the virtual drives: the confirmation, the warning about an enabled
// CiA 402 drive before a command that stops it, and what goes out.
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "core/canopen/Ds402Controller.h"
#include "eds/SimulatorDictionaries.h"

#include <QAction>
#include <QMenu>
#include <QMessageBox>
#include <QSignalSpy>
#include <QTableView>
#include <QtTest>

#include "tests/gui/ContextMenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/SimDriveRig.h"

using namespace coscope;
using namespace coscope::gui;
using canopen::ds402::State;

namespace {
// Right-clicks row `row` of the Nodes dock (-1: where no node is, for "All nodes") and clicks the
// context menu item `text` once the menu shows.
bool nmtFromMenu(NodesDock& dock, int row, const QString& text) {
    QTableView* view = dock.view();
    QPoint pos(4, view->viewport()->height() - 4);
    if (row >= 0) {
        pos = view->visualRect(view->model()->index(row, 0)).center();
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, pos);
    }
    return coscope::testing::contextMenuClick(view, pos, text);
}
}  // namespace

class TestNodesNmt : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() { eds::installSimulatorDictionaries(); }

    // Issue 13: the NMT question from the Nodes dock's context menu reads the drives' statusword
    // 6041h first without an event loop of its own on the GUI thread: the menu click returns at
    // once, the question shows when the answers are in and then names an enabled drive.
    void nmtResetWarnsAboutAnEnabledDrive() {
        coscope::testing::SimDriveRig rig;
        QVERIFY(rig.open(QStringLiteral("sim://?nodes=1:delta-asda-a2,2:aimotor,3:dexmart-dev,4:generic-cia402")));
        NodesDock dock(&rig.ws);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        QVERIFY(QTest::qWaitFor(
            [&] {
                dock.refresh();  // as the main window's update timer does
                return dock.model()->rowCount() >= 4;
            },
            5000));
        QSignalSpy finished(&dock, &NodesDock::nmtFinished);
        // Reset communication of all nodes and of node 1 (its row's menu) while drive 1 is in
        // Operation enabled: the question names it; "no" (Escape) sends nothing.
        canopen::Ds402Controller ctl(*rig.ws.sdo(), 1);
        bool on = false;
        ctl.enable([&](const canopen::Ds402Result& r) { on = r.ok; });
        QVERIFY(QTest::qWaitFor([&] { return on; }, 6000));
        QCOMPARE(rig.driveState(1), State::OperationEnabled);
        for (int row : {-1, dock.model()->rowOfNode(1)}) {
            QString asked;
            auto no = coscope::testing::answerEscape(&asked);
            const int before = int(finished.count());
            // All nodes: the table has a current row once shown, so ask the dock as its menu would.
            QVERIFY(row < 0 ? dock.sendNmt(0x82, 0) : nmtFromMenu(dock, row, QStringLiteral("Reset communication")));
            // Back from the click with nothing asked yet: the 6041h reads are under way.
            QVERIFY2(asked.isEmpty(), qPrintable(asked));
            QVERIFY(QTest::qWaitFor([&] { return finished.count() > before; }, 5000));
            QCOMPARE(finished.last().first().toBool(), false);  // answered "no": nothing sent
            QVERIFY2(asked.contains(QStringLiteral("Drive 1 is enabled (Operation enabled")), qPrintable(asked));
            QVERIFY2(asked.contains(QStringLiteral("a reset stops it abruptly")), qPrintable(asked));
            QVERIFY2(asked.contains(QStringLiteral("AL401")), qPrintable(asked));
            QVERIFY2(asked.contains(row < 0 ? QStringLiteral("to all nodes") : QStringLiteral("to node 1")),
                     qPrintable(asked));
            QVERIFY(!asked.contains(QStringLiteral("Drive 2")));  // node 2 is not enabled
            QCOMPARE(rig.driveState(1), State::OperationEnabled);
        }
        // Start (01h) does not stop anything: the plain question, no warning.
        {
            QString asked;
            auto yes = coscope::testing::answerBox(QMessageBox::Yes, &asked);
            QVERIFY(nmtFromMenu(dock, dock.model()->rowOfNode(1), QStringLiteral("Start (Operational)")));
            QVERIFY(QTest::qWaitFor([&] { return !asked.isEmpty(); }, 5000));
            QVERIFY2(asked.startsWith(QStringLiteral("Send NMT")), qPrintable(asked));
        }
        bool off = false;
        ctl.disable([&](const canopen::Ds402Result& r) { off = r.ok; });
        QVERIFY(QTest::qWaitFor([&] { return off; }, 6000));
        // A reset of node 2, not enabled: its statusword is read, the plain question follows; yes sends it.
        QString asked;
        auto yes = coscope::testing::answerBox(QMessageBox::Yes, &asked);
        const int before = int(finished.count());
        QVERIFY(nmtFromMenu(dock, dock.model()->rowOfNode(2), QStringLiteral("Reset node")));
        QVERIFY(QTest::qWaitFor([&] { return finished.count() > before; }, 5000));
        QVERIFY2(asked.startsWith(QStringLiteral("Send NMT")), qPrintable(asked));
        QCOMPARE(finished.last().first().toBool(), true);
    }

    // Issue 35: the NMT state and where it comes from, as the dock shows them. Nodes boot
    // (Pre-operational, from their boot-up; the virtual drives have no heartbeat); Start of node 2
    // (AIMOTOR: its TPDOs wait for SYNC) from its context menu shows Operational "after our NMT
    // Start (not confirmed)"; node 4 (generic drive: event-driven TPDOs, sent on entering
    // Operational) is shown Operational from its PDOs. Before, the dock kept "Pre-operational".
    void startShowsTheStateAndWhereItComesFrom() {
        coscope::testing::SimDriveRig rig;
        QVERIFY(rig.open(QStringLiteral("sim://?nodes=2:aimotor,4:generic-cia402")));
        NodesDock dock(&rig.ws);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        NodesModel* m = dock.model();
        auto cell = [&](int node, int column) {
            dock.refresh();  // as the main window's update timer does
            const int row = m->rowOfNode(node);
            return row < 0 ? QString() : m->index(row, column).data().toString();
        };
        QVERIFY(QTest::qWaitFor(
            [&] {
                return cell(2, NodesModel::StateSource) == u"boot-up" && cell(4, NodesModel::StateSource) == u"boot-up";
            },
            5000));
        QCOMPARE(cell(2, NodesModel::State), QStringLiteral("Pre-operational"));
        QCOMPARE(m->headerData(NodesModel::StateSource, Qt::Horizontal, Qt::DisplayRole).toString(),
                 QStringLiteral("State from"));
        for (int node : {2, 4}) {
            QString asked;
            auto yes = coscope::testing::answerBox(QMessageBox::Yes, &asked);
            QSignalSpy finished(&dock, &NodesDock::nmtFinished);
            QVERIFY(nmtFromMenu(dock, m->rowOfNode(node), QStringLiteral("Start (Operational)")));
            QVERIFY(QTest::qWaitFor([&] { return finished.count() > 0; }, 5000));
            QVERIFY2(asked.contains(QStringLiteral("node %1").arg(node)), qPrintable(asked));
        }
        QVERIFY(QTest::qWaitFor([&] { return cell(2, NodesModel::State) == u"Operational"; }, 3000));
        QCOMPARE(cell(2, NodesModel::StateSource), QStringLiteral("after our NMT Start (not confirmed)"));
        const QModelIndex state2 = m->index(m->rowOfNode(2), NodesModel::State);
        QVERIFY2(state2.data(Qt::ToolTipRole)
                     .toString()
                     .startsWith(QStringLiteral("CoScope sent NMT Start; the node has not confirmed it")),
                 qPrintable(state2.data(Qt::ToolTipRole).toString()));
        QVERIFY(state2.data(Qt::FontRole).value<QFont>().italic());
        QVERIFY(QTest::qWaitFor([&] { return cell(4, NodesModel::StateSource) == u"its PDOs"; }, 3000));
        QCOMPARE(cell(4, NodesModel::State), QStringLiteral("Operational"));
        // And the view shows it: the cell as drawn is the model's text.
        const QRect r = dock.view()->visualRect(m->index(m->rowOfNode(4), NodesModel::StateSource));
        QVERIFY(r.isValid() && dock.view()->viewport()->rect().intersects(r));
    }
};

QTEST_MAIN(TestNodesNmt)
#include "test_nodes_nmt.moc"
