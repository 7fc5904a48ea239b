// SPDX-License-Identifier: GPL-3.0-or-later
// CoScope as the master of the virtual network (issue 35), in the real window by mouse and keys:
// SYNC from the toolbar at the period set in Bus ▸ Master settings…, the AIMOTOR's default TPDOs
// (transmission type 1: sent on SYNC, extract-aimotor §3.6) then reach the plot without any
// remapping; the Transmit panel sends a frame typed in candump syntax every 20 ms, stops it, and
// asks before a frame aimed at a drive's RPDO that carries its controlword; listen-only disables
// all of it with the reason.
#include "app/gui/MainWindow.h"
#include "app/gui/master/MasterActions.h"
#include "app/gui/master/TransmitDock.h"
#include "app/gui/master/TransmitModel.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/plot/PlotDock.h"
#include "app/gui/session/Workspace.h"
#include "core/canopen/SyncProducer.h"
#include "eds/SimulatorDictionaries.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QTabBar>
#include <QTableView>
#include <QToolBar>
#include <QToolButton>
#include <QTreeWidget>
#include <QtTest>

#include <algorithm>
#include <vector>

#include "tests/gui/ContextMenuClick.h"
#include "tests/gui/ItemClick.h"
#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/TxFrames.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::clickCheckBox;
using coscope::testing::clickDockTab;
using coscope::testing::countTx;
using coscope::testing::median;
using coscope::testing::signalItem;
using coscope::testing::txIntervalsMs;
using coscope::testing::waitFor;

namespace {
constexpr int kPatienceMs = 30000;

}  // namespace

class TestMasterTransmit : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_master_transmit"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
    }

    void syncAndTransmitOnTheVirtualNetwork() {
        MainWindow w;
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(coscope::testing::clickMenuItem(w, QStringLiteral("Bus"), QStringLiteral("Connect to virtual drives")));
        Workspace* ws = w.workspace();
        // The scan after connecting identifies the three drives (they get their dictionaries).
        QVERIFY(waitFor(
            [&] {
                int known = 0;
                for (const canopen::NodeInfo& n : ws->nodes().snapshot()) known += !n.dictionary.isEmpty();
                return ws->canTransmit() && known >= 3;
            },
            kPatienceMs));

        // Without SYNC the AIMOTOR sends no TPDO (type 1): NMT Start for all nodes first.
        QTableView* nodes = w.nodesDock()->view();
        QString asked;
        {
            auto yes = coscope::testing::answerBox(QMessageBox::Yes, &asked);
            QVERIFY(coscope::testing::contextMenuClick(nodes, QPoint(4, nodes->viewport()->height() - 4),
                                                       QStringLiteral("Start (Operational)")));
            QVERIFY(waitFor([&] { return yes->answered(); }, kPatienceMs));
        }

        // Bus ▸ Master settings…: SYNC every 10 ms.
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
            QVERIFY(coscope::testing::clickMenuItem(w, QStringLiteral("Bus"), QStringLiteral("Master settings")));
            QVERIFY(waitFor([&] { return settings.answered() && !QApplication::activeModalWidget(); }, kPatienceMs));
        }
        QCOMPARE(QSettings().value(QStringLiteral("master/syncPeriodUs")).toUInt(), 10000u);

        // The toolbar's SYNC button starts it; the status bar says so.
        auto* bar = w.findChild<QToolBar*>(QStringLiteral("busToolBar"));
        QVERIFY(bar);
        QWidget* syncButton = bar->widgetForAction(w.masterActions()->syncAction());
        QVERIFY(syncButton && syncButton->isEnabled());
        const size_t before = ws->store()->size();
        QTest::mouseClick(syncButton, Qt::LeftButton);
        QVERIFY(w.masterActions()->syncAction()->isChecked());
        QVERIFY(waitFor([&] { return txIntervalsMs(*ws->store(), 0x80, before).size() >= 100; }, kPatienceMs));
        const double syncMs = median(txIntervalsMs(*ws->store(), 0x80, before));
        QVERIFY2(syncMs > 9.0 && syncMs < 11.0, qPrintable(QString::number(syncMs)));
        auto* masterLabel = w.findChild<QLabel*>(QStringLiteral("statusMaster"));
        QVERIFY(masterLabel && masterLabel->text().contains(QStringLiteral("SYNC 10 ms")));

        // The AIMOTOR's default TPDO1 (6041h, 6061h, 6064h) follows SYNC: its position is offered
        // in the plot without any remapping.
        QVERIFY(clickDockTab(w, QStringLiteral("Plot")));
        auto* tree = w.plotDock()->findChild<QTreeWidget*>(QStringLiteral("signalTree"));
        QVERIFY(tree);
        QVERIFY(waitFor([&] { return signalItem(tree, 2, QStringLiteral("Position actual value")) != nullptr; },
                        kPatienceMs));

        // Transmit: 123#1122 every 20 ms, typed, Enter.
        QVERIFY(clickDockTab(w, QStringLiteral("Transmit")));
        TransmitDock* tx = w.transmitDock();
        QVERIFY(waitFor([&] { return tx->frameEdit()->isVisible(); }, kPatienceMs));
        QTest::mouseClick(tx->frameEdit(), Qt::LeftButton);
        QTest::keyClicks(tx->frameEdit(), QStringLiteral("123#1122"));
        QTest::mouseClick(tx->everyEdit(), Qt::LeftButton);
        QTest::keyClicks(tx->everyEdit(), QStringLiteral("20"));
        const size_t txFrom = ws->store()->size();
        QTest::keyClick(tx->everyEdit(), Qt::Key_Return);
        QCOMPARE(tx->model()->rowCount(), 1);
        QVERIFY(waitFor([&] { return txIntervalsMs(*ws->store(), 0x123, txFrom).size() >= 40; }, kPatienceMs));
        const double everyMs = median(txIntervalsMs(*ws->store(), 0x123, txFrom));
        QVERIFY2(everyMs > 19.0 && everyMs < 21.0, qPrintable(QString::number(everyMs)));
        QVERIFY(waitFor(
            [&] {
                return tx->model()->data(tx->model()->index(0, TransmitModel::Sent)).toString().remove(u',').toInt() >=
                       40;
            },
            kPatienceMs));
        // A click on its Periodic box stops it.
        clickCheckBox(tx->view(), tx->model()->index(0, TransmitModel::Run));
        QVERIFY(waitFor([&] { return !tx->model()->isRunning(0); }, kPatienceMs));
        const size_t stoppedAt = countTx(*ws->store(), 0x123);
        QTest::qWait(200);
        QVERIFY(countTx(*ws->store(), 0x123) <= stoppedAt + 1);

        // RPDO1 of the AIMOTOR carries 6040h, 6060h, 607Ah: asked first; "No" sends nothing.
        QTest::mouseClick(tx->frameEdit(), Qt::LeftButton);
        QTest::keyClick(tx->frameEdit(), Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(tx->frameEdit(), QStringLiteral("202#0600000000000000"));
        QTest::mouseClick(tx->everyEdit(), Qt::LeftButton);
        QTest::keyClick(tx->everyEdit(), Qt::Key_A, Qt::ControlModifier);
        QTest::keyClick(tx->everyEdit(), Qt::Key_Delete);
        {
            auto no = coscope::testing::answerBox(QMessageBox::No, &asked);
            QTest::keyClick(tx->frameEdit(), Qt::Key_Return);
            QVERIFY(waitFor([&] { return no->answered(); }, kPatienceMs));
        }
        QVERIFY2(asked.contains(QStringLiteral("RPDO1 of node 2")) && asked.contains(QStringLiteral("6040h")),
                 qPrintable(asked));
        QTest::qWait(100);
        QCOMPARE(countTx(*ws->store(), 0x202), size_t(0));
        // "Yes" sends it; asked once: Enter on its row sends it again without a question.
        {
            auto yes = coscope::testing::answerBox(QMessageBox::Yes, &asked);
            QTest::keyClick(tx->frameEdit(), Qt::Key_Return);
            QVERIFY(waitFor([&] { return yes->answered(); }, kPatienceMs));
        }
        QVERIFY(waitFor([&] { return countTx(*ws->store(), 0x202) == 1; }, kPatienceMs));
        QTest::mouseClick(tx->view()->viewport(), Qt::LeftButton, {},
                          tx->view()->visualRect(tx->model()->index(1, TransmitModel::Data)).center());
        QTest::keyClick(tx->view(), Qt::Key_Return);
        QVERIFY(waitFor([&] { return countTx(*ws->store(), 0x202) == 2; }, kPatienceMs));
        QVERIFY(!QApplication::activeModalWidget());

        // Toolbar SYNC again: stopped.
        QTest::mouseClick(syncButton, Qt::LeftButton);
        QVERIFY(waitFor([&] { return !ws->syncProducer()->isRunning(); }, kPatienceMs));
    }

    // The rows are kept for the next session; listen-only disables sending with the reason.
    void keptRowsAndListenOnly() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        TransmitDock* tx = w.transmitDock();
        QCOMPARE(tx->model()->rowCount(), 2);  // 123#1122 every 20 ms, 202#06...
        QCOMPARE(tx->model()->entry(0).periodUs, 20000u);
        QVERIFY(tx->banner()->text().contains(QStringLiteral("Connect to a bus first")));
        QVERIFY(w.connectBus(QStringLiteral("sim://?listen-only=1")));
        QVERIFY(waitFor([&] { return w.workspace()->bus() && w.workspace()->bus()->state() == CanBus::State::Open; },
                        kPatienceMs));
        QVERIFY(waitFor([&] { return tx->banner()->text().contains(QStringLiteral("Listen-only")); }, kPatienceMs));
        QVERIFY(!tx->findChild<QPushButton*>(QStringLiteral("transmitSend"))->isEnabled());
        QVERIFY(!w.masterActions()->syncAction()->isEnabled());
        waitFor([&] { return w.masterActions()->syncAction()->toolTip().contains(QStringLiteral("Listen-only")); },
                5000);  // the window's next tick
        QVERIFY2(w.masterActions()->syncAction()->toolTip().contains(QStringLiteral("Listen-only")),
                 qPrintable(w.masterActions()->syncAction()->toolTip()));
    }
};

QTEST_MAIN(TestMasterTransmit)
#include "test_master_transmit.moc"
