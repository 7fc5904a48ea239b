// SPDX-License-Identifier: GPL-3.0-or-later
// The Connect dialog and the Commission wizards reopen where the user left them (issue 35,
// item 7), through the menus and clicks in the real main window: Bus ▸ Connect… opens on the
// last connection (its backend and settings), and the CiA 402 wizard closed on node 2 opens on
// node 2 again from Commission ▸ (while the Nodes dock's selection is the one it was opened
// with); a node picked in the Nodes dock afterwards wins.
#include "app/gui/MainWindow.h"
#include "app/gui/connect/ConnectDialog.h"
#include "app/gui/connect/RecentConnections.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/ds402/Ds402Wizard.h"
#include "eds/SimulatorDictionaries.h"

#include <QApplication>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFile>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QTableView>
#include <QTemporaryDir>
#include <QtTest>

#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::clickMenuItem;
using coscope::testing::ModalAnswerer;
using coscope::testing::waitFor;

namespace {
const QString kAll = QStringLiteral("sim://?nodes=1:delta-asda-a2,2:aimotor,3:dexmart-dev,4:generic-cia402");

Ds402Wizard* shownDs402() {
    for (QWidget* w : QApplication::topLevelWidgets())
        if (auto* d = qobject_cast<Ds402Wizard*>(w); d && d->isVisible()) return d;
    return nullptr;
}

// Commission ▸ CiA 402 enable step-through…: the wizard shown, on a node.
Ds402Wizard* openDs402(MainWindow& w) {
    if (!clickMenuItem(w, QStringLiteral("Commission"), QStringLiteral("CiA 402"))) return nullptr;
    Ds402Wizard* d = nullptr;
    waitFor([&] { return (d = shownDs402()) && d->node() > 0; });
    return d;
}

bool closeWizard(Ds402Wizard* d) {
    QTest::mouseClick(d->findChild<QPushButton*>(QStringLiteral("close")), Qt::LeftButton);
    return waitFor([] { return !shownDs402(); });
}
}  // namespace

class TestReopenLast : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_reopen_last"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
        QVERIFY(dir_.isValid());
    }

    void connectDialogOpensOnTheLastConnection() {
        const QString log = dir_.filePath(QStringLiteral("short.log"));
        QFile f(log);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("(100.000000) can0 701#05\n(100.100000) can0 701#05\n");
        f.close();
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        // First time: the virtual drives. The user picks "Replay a log file", types the path, Connect.
        QString firstBackend;
        ModalAnswerer connectReplay([&](QWidget* modal) {
            auto* d = qobject_cast<ConnectDialog*>(modal);
            if (!d) return false;
            firstBackend = d->backend()->currentData().toString();
            d->backend()->setFocus();
            QTest::keyClick(d->backend(), Qt::Key_Home);
            for (int i = 0; i < d->backend()->count() && d->backend()->currentData().toString() != u"replay"; ++i)
                QTest::keyClick(d->backend(), Qt::Key_Down);
            auto* path = d->findChild<QLineEdit*>(QStringLiteral("replayPath"));
            QTest::mouseClick(path, Qt::LeftButton);
            QTest::keyClick(path, Qt::Key_A, Qt::ControlModifier);
            QTest::keyClicks(path, log);
            QTest::mouseClick(d->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok), Qt::LeftButton);
            return true;
        });
        QVERIFY(clickMenuItem(w, QStringLiteral("Bus"), QStringLiteral("Connect…")));
        QVERIFY(waitFor([&] { return connectReplay.answered() && w.workspace()->bus(); }));
        QCOMPARE(firstBackend, QStringLiteral("sim"));
        QCOMPARE(w.workspace()->bus()->url().scheme, QStringLiteral("replay"));

        // Again: the dialog shows the replay and its file, as the user left it.
        QString backend, path;
        ModalAnswerer look([&](QWidget* modal) {
            auto* d = qobject_cast<ConnectDialog*>(modal);
            if (!d) return false;
            backend = d->backend()->currentData().toString();
            path = d->findChild<QLineEdit*>(QStringLiteral("replayPath"))->text();
            QTest::keyClick(d, Qt::Key_Escape);
            return true;
        });
        QVERIFY(clickMenuItem(w, QStringLiteral("Bus"), QStringLiteral("Connect…")));
        QVERIFY(waitFor([&] { return look.answered() && !QApplication::activeModalWidget(); }));
        QCOMPARE(backend, QStringLiteral("replay"));
        QCOMPARE(path, log);
        w.disconnectBus();
    }

    void wizardOpensOnTheLastNode() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.connectBus(kAll));
        QVERIFY(waitFor([&] { return w.workspace()->nodes().node(2) && w.workspace()->nodes().node(4); }));
        w.nodesDock()->assignDictionary(1, QStringLiteral("delta-asda-a2"));
        w.nodesDock()->assignDictionary(2, QStringLiteral("aimotor"));
        w.nodesDock()->assignDictionary(4, QStringLiteral("generic-cia402"));
        w.refresh();

        Ds402Wizard* d = openDs402(w);
        QVERIFY(d);
        const int first = d->node();
        // The user picks node 2 in the wizard's drive list, then closes the wizard.
        QComboBox* nodes = d->findChild<QComboBox*>(QStringLiteral("nodeCombo"));
        const int item = nodes->findData(2);
        QVERIFY(item >= 0);
        nodes->setFocus();
        QTest::keyClick(nodes, Qt::Key_Home);
        for (int i = 0; i < item; ++i) QTest::keyClick(nodes, Qt::Key_Down);
        QVERIFY(waitFor([&] { return d->node() == 2; }));
        QVERIFY(first != 2);
        QVERIFY(closeWizard(d));

        // Reopened: node 2 again.
        d = openDs402(w);
        QVERIFY(d);
        QCOMPARE(d->node(), 2);
        QVERIFY(closeWizard(d));

        // Node 4 picked in the Nodes dock: that is the user's new choice.
        QTableView* table = w.nodesDock()->view();
        const int row = w.nodesDock()->model()->rowOfNode(4);
        QTest::mouseClick(table->viewport(), Qt::LeftButton, {},
                          table->visualRect(table->model()->index(row, 1)).center());
        QCOMPARE(w.nodesDock()->selectedNode(), 4);
        d = openDs402(w);
        QVERIFY(d);
        QCOMPARE(d->node(), 4);
        QVERIFY(closeWizard(d));
        w.disconnectBus();
    }
};

QTEST_MAIN(TestReopenLast)
#include "test_reopen_last.moc"
