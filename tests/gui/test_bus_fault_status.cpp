// SPDX-License-Identifier: GPL-3.0-or-later
// The status bar shows the CAN controller's fault confinement state and error counters from the
// error frames (linux/can/error.h layout), and after bus-off offers to restart the controller;
// a backend that cannot restart says so in the status bar and the Events.
#include "app/gui/MainWindow.h"
#include "app/gui/events/EventsDock.h"
#include "app/gui/events/EventsModel.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/status/BusStatusBar.h"

#include <QFile>
#include <QPushButton>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QtTest>

using namespace coscope;
using namespace coscope::gui;

class TestBusFaultStatus : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_bus_fault_status"));
    }

    void busOffShowsStateAndRestart() {
        QTemporaryDir dir;
        const QString log = dir.filePath(QStringLiteral("busoff.log"));
        QFile f(log);
        QVERIFY(f.open(QIODevice::WriteOnly));
        // A heartbeat, then CAN_ERR_CRTL|CAN_ERR_CNT with TX passive (data[1] 0x20) and counters
        // TEC 136 REC 0 (data[6], data[7]), then CAN_ERR_BUSOFF (0x40).
        f.write(
            "(1700000000.000000) can0 701#05\n"
            "(1700000000.100000) can0 20000204#0020000000008800\n"
            "(1700000000.200000) can0 20000040#0000000000000000\n");
        f.close();
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.connectBus(QStringLiteral("replay://%1?speed=0").arg(log)));
        QTRY_VERIFY_WITH_TIMEOUT(w.busStatus()->controllerText().contains(QStringLiteral("bus-off")), 10000);
        auto* restart = w.statusBar()->findChild<QPushButton*>(QStringLiteral("restartController"));
        QVERIFY(restart);
        QVERIFY(restart->isVisible());
        QAbstractItemModel* events = w.eventsDock()->view()->model();
        const int before = events->rowCount();
        QTest::mouseClick(restart, Qt::LeftButton);
        // A replay has no controller to restart: the user reads why, in the status bar and the Events.
        QTRY_VERIFY_WITH_TIMEOUT(events->rowCount() > before, 5000);
        const QString last = events->index(events->rowCount() - 1, EventsModel::Text).data().toString();
        QVERIFY2(last.contains(QStringLiteral("cannot restart")), qPrintable(last));
        QVERIFY2(w.statusBar()->currentMessage().contains(QStringLiteral("Restart after bus-off failed")),
                 qPrintable(w.statusBar()->currentMessage()));
    }

    void passiveShowsCounters() {
        QTemporaryDir dir;
        const QString log = dir.filePath(QStringLiteral("passive.log"));
        QFile f(log);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(
            "(1700000000.000000) can0 701#05\n"
            "(1700000000.100000) can0 20000204#0020000000008800\n");
        f.close();
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(w.connectBus(QStringLiteral("replay://%1?speed=0").arg(log)));
        QTRY_VERIFY_WITH_TIMEOUT(w.busStatus()->controllerText().contains(QStringLiteral("error passive")), 10000);
        QVERIFY2(w.busStatus()->controllerText().contains(QStringLiteral("TEC 136 REC 0")),
                 qPrintable(w.busStatus()->controllerText()));
        QVERIFY(!w.statusBar()->findChild<QPushButton*>(QStringLiteral("restartController"))->isVisible());
    }
};

QTEST_MAIN(TestBusFaultStatus)
#include "test_bus_fault_status.moc"
