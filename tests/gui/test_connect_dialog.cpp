// SPDX-License-Identifier: GPL-3.0-or-later
// The connect dialog builds the same bus URLs the CLI takes, and remembers recent connections.
#include "app/gui/connect/ConnectDialog.h"
#include "app/gui/connect/RecentConnections.h"
#include "core/can/BusUrl.h"

#include <QCheckBox>
#include <QComboBox>
#include <QSpinBox>
#include <QTableWidget>
#include <QtTest>

using namespace coscope;
using namespace coscope::gui;

class TestConnectDialog : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_connect_dialog"));
        RecentConnections::clear();
    }

    void defaultIsTheVirtualNetwork() {
        ConnectDialog d;
        QCOMPARE(d.backend()->currentData().toString(), QStringLiteral("sim"));
        QCOMPARE(d.url(), QStringLiteral("sim://"));
        QVERIFY(BusUrl::parse(d.url(), nullptr));
    }

    void choicesMakeTheUrl() {
        ConnectDialog d;
        // Keep only the first virtual drive, as node 9.
        for (int r = 1; r < d.drives()->rowCount(); ++r) d.drives()->item(r, 0)->setCheckState(Qt::Unchecked);
        d.drives()->item(0, 0)->setCheckState(Qt::Checked);
        static_cast<QSpinBox*>(d.drives()->cellWidget(0, 1))->setValue(9);
        d.listenOnly()->setChecked(true);
        const QString url = d.url();
        QVERIFY2(url.startsWith(QStringLiteral("sim://?nodes=9:") + d.drives()->item(0, 0)->text()), qPrintable(url));
        QVERIFY(url.contains(QStringLiteral("listen-only=1")));
        const auto parsed = BusUrl::parse(url, nullptr);
        QVERIFY(parsed);
        QVERIFY(parsed->listenOnly());
    }

    void socketcandRoundTrip() {
        ConnectDialog d;
        d.setUrl(QStringLiteral("socketcand://10.0.0.5:29536/can1?bitrate=250000"));
        QCOMPARE(d.backend()->currentData().toString(), QStringLiteral("socketcand"));
        const auto u = BusUrl::parse(d.url(), nullptr);
        QVERIFY2(u, qPrintable(d.url()));
        QCOMPARE(u->host, QStringLiteral("10.0.0.5"));
        QCOMPARE(u->channel, QStringLiteral("can1"));
        QCOMPARE(u->bitrate(), 250000);
        QVERIFY(!u->listenOnly());
    }

    void qtPluginsAreOffered() {
        ConnectDialog d;
        for (const QString& p : qtCanPlugins()) QVERIFY2(d.backend()->findData(p) >= 0, qPrintable(p));
    }

    void noDriveIsRefused() {
        ConnectDialog d;
        for (int r = 0; r < d.drives()->rowCount(); ++r) d.drives()->item(r, 0)->setCheckState(Qt::Unchecked);
        d.accept();
        QCOMPARE(d.result(), int(QDialog::Rejected));  // stays open with an inline error
    }

    void recentConnections() {
        RecentConnections::add(QStringLiteral("sim://"));
        RecentConnections::add(QStringLiteral("virtualcan://can0"));
        RecentConnections::add(QStringLiteral("sim://"));
        QCOMPARE(RecentConnections::list(), (QStringList{QStringLiteral("sim://"), QStringLiteral("virtualcan://can0")}));
        for (int i = 0; i < 15; ++i) RecentConnections::add(QStringLiteral("virtualcan://can%1").arg(i));
        QCOMPARE(RecentConnections::list().size(), 10);
        RecentConnections::clear();
    }
};

QTEST_MAIN(TestConnectDialog)
#include "test_connect_dialog.moc"
