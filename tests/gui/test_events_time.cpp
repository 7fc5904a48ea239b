// SPDX-License-Identifier: GPL-3.0-or-later
// Events logged before the trace has a frame (a bus that does not open) show capture-relative
// time in the Events dock, not seconds since 1970.
#include "app/gui/MainWindow.h"
#include "app/gui/events/EventsDock.h"
#include "app/gui/events/EventsModel.h"

#include <QTableView>
#include <QTcpServer>
#include <QtTest>

using namespace coscope::gui;

class TestEventsTime : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_events_time"));
    }

    void eventBeforeFirstFrameHasRelativeTime() {
        quint16 port = 0;
        {
            QTcpServer probe;  // a port nobody listens on once the probe is gone
            QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
            port = probe.serverPort();
        }
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.connectBus(QStringLiteral("socketcand://127.0.0.1:%1/can0").arg(port));
        QAbstractItemModel* m = w.eventsDock()->view()->model();
        QTRY_VERIFY_WITH_TIMEOUT(m->rowCount() > 0, 10000);
        const QString time = m->index(0, EventsModel::Time).data().toString();
        bool ok = false;
        const double seconds = time.toDouble(&ok);
        QVERIFY2(ok && seconds >= 0 && seconds < 60, qPrintable(time));
        QVERIFY2(m->index(0, EventsModel::Text).data().toString().contains(QStringLiteral("socketcand")),
                 qPrintable(m->index(0, EventsModel::Text).data().toString()));
    }
};

QTEST_MAIN(TestEventsTime)
#include "test_events_time.moc"
