// SPDX-License-Identifier: GPL-3.0-or-later
// The connect dialog builds the same bus URLs the CLI takes, and remembers recent connections.
#include "app/gui/connect/ConnectDialog.h"
#include "app/gui/connect/RecentConnections.h"
#include "core/can/BusUrl.h"
#include "core/can/SocketCanLinkJob.h"
#include "tests/gui/WaitFor.h"

#include <QCanBus>
#include <QCheckBox>
#include <QClipboard>
#include <QComboBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace coscope;
using namespace coscope::gui;

namespace {
// Picks the first entry of `c` for which `is(text, data)` holds from the keyboard, as a user
// would: Home, then Down until it is current; false when there is none.
template <typename Is>
bool pickByKeys(QComboBox* c, Is is) {
    c->setFocus();
    QTest::keyClick(c, Qt::Key_Home);
    for (int i = 0; i < c->count() && !is(c->currentText(), c->currentData()); ++i) QTest::keyClick(c, Qt::Key_Down);
    return is(c->currentText(), c->currentData());
}
// Picks the backend `key` in the combo from the keyboard.
bool chooseBackend(ConnectDialog& d, const QString& key) {
    return pickByKeys(d.backend(), [&](const QString&, const QVariant& v) { return v.toString() == key; });
}
bool pickText(QComboBox* c, const QString& text) {
    return pickByKeys(c, [&](const QString& t, const QVariant&) { return t == text; });
}
bool pickBitrate(QComboBox* c, int bitrate) {
    return pickByKeys(c, [&](const QString&, const QVariant& v) { return v.toInt() == bitrate; });
}
// A stand-in for ip(8), the shell script `body`, used by CoScope through COSCOPE_IP while this
// object lives.
class StandInIp {
public:
    explicit StandInIp(const QByteArray& body) {
        QFile f(dir_.filePath(QStringLiteral("ip")));
        ok_ = f.open(QIODevice::WriteOnly) && f.write("#!/bin/sh\n" + body) > 0;
        f.close();
        ok_ = ok_ && f.setPermissions(f.permissions() | QFileDevice::ExeOwner);
        qputenv("COSCOPE_IP", f.fileName().toLocal8Bit());
    }
    ~StandInIp() { qunsetenv("COSCOPE_IP"); }
    bool ok() const { return ok_; }

private:
    QTemporaryDir dir_;
    bool ok_ = false;
};
// Ticks or unticks the drive in `row` as a user does: click the row, Space toggles its box.
void toggleDrive(ConnectDialog& d, int row) {
    QTableWidget* t = d.drives();
    QTest::mouseClick(t->viewport(), Qt::LeftButton, {}, t->visualItemRect(t->item(row, 0)).center());
    QTest::keyClick(t->viewport(), Qt::Key_Space);
}
}  // namespace

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
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        // Keep only the first virtual drive, as node 9.
        for (int r = 1; r < d.drives()->rowCount(); ++r)
            if (d.drives()->item(r, 0)->checkState() == Qt::Checked) toggleDrive(d, r);
        if (d.drives()->item(0, 0)->checkState() != Qt::Checked) toggleDrive(d, 0);
        for (int r = 1; r < d.drives()->rowCount(); ++r) QCOMPARE(d.drives()->item(r, 0)->checkState(), Qt::Unchecked);
        auto* spin = static_cast<QSpinBox*>(d.drives()->cellWidget(0, 1));
        QLineEdit* number = spin->findChild<QLineEdit*>();
        QTest::mouseClick(number, Qt::LeftButton);
        QTest::keyClick(number, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(number, QStringLiteral("9"));
        // On its box, at the left (the widget may be wider than its label).
        QTest::mouseClick(d.listenOnly(), Qt::LeftButton, {}, QPoint(8, d.listenOnly()->height() / 2));
        // What the URL field shows is what connects.
        const QString url = d.findChild<QLineEdit*>(QStringLiteral("urlPreview"))->text();
        QVERIFY2(url.startsWith(QStringLiteral("sim://?nodes=9:") + d.drives()->item(0, 0)->text()), qPrintable(url));
        QVERIFY(url.contains(QStringLiteral("listen-only=1")));
        QCOMPARE(d.url(), url);
        const auto parsed = BusUrl::parse(url, nullptr);
        QVERIFY(parsed);
        QVERIFY(parsed->listenOnly());
    }

    // SocketCAN interfaces are listed with their state; one that is down shows the command that
    // brings it up at the chosen bit rate (ip-link(8) "type can bitrate").
    void socketcanInterfacesShowStateAndBringUpCommand() {
        if (!qtCanPlugins().contains(QStringLiteral("socketcan"))) QSKIP("Qt's socketcan plugin is not installed");
        StandInIp ip(
            "cat <<'EOF'\n"
            R"([{"ifname":"lo","flags":["UP"],"link_type":"loopback"},)"
            R"({"ifname":"can0","flags":["NOARP","ECHO"],"operstate":"DOWN","link_type":"can","linkinfo":{"info_kind":"can",)"
            R"("info_data":{"state":"STOPPED","bittiming":{"bitrate":250000}}}},)"
            R"({"ifname":"can1","flags":["NOARP","UP","LOWER_UP"],"operstate":"UP","link_type":"can","linkinfo":{"info_kind":"can",)"
            R"("info_data":{"state":"BUS-OFF","berr_counter":{"tx":256,"rx":0},"bittiming":{"bitrate":500000}}}}])"
            "\nEOF\n");
        QVERIFY(ip.ok());
        ConnectDialog d;
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        QVERIFY(chooseBackend(d, QStringLiteral("socketcan")));
        auto* device = d.findChild<QComboBox*>(QStringLiteral("device"));
        auto* state = d.findChild<QLabel*>(QStringLiteral("linkState"));
        // `ip` runs off the GUI thread; the list fills when it answers.
        QVERIFY(coscope::testing::waitFor([&] { return device->findText(QStringLiteral("can0")) >= 0; }, 5000));
        QVERIFY(device->findText(QStringLiteral("lo")) < 0);
        // Pick can0 from the list with the keyboard.
        QVERIFY(pickText(device, QStringLiteral("can0")));
        QVERIFY(state->isVisible());
        QVERIFY2(state->text().contains(QStringLiteral("can0 is down")), qPrintable(state->text()));
        // Choose 125 kbit/s: the command follows the choice.
        auto* bitrate = d.findChild<QComboBox*>(QStringLiteral("bitrate"));
        QVERIFY(pickBitrate(bitrate, 125000));
        QVERIFY2(state->text().contains(QStringLiteral("sudo ip link set can0 up type can bitrate 125000")),
                 qPrintable(state->text()));
        // can1 is up but bus-off: say so.
        device->setFocus();
        QTest::keyClick(device, Qt::Key_Down);
        QCOMPARE(device->currentText(), QStringLiteral("can1"));
        QVERIFY2(state->text().contains(QStringLiteral("bus-off")), qPrintable(state->text()));
    }

    // An interface that is down is brought up from the dialog when CoScope may configure links
    // (CAP_NET_ADMIN): one click runs the command shown, and the state shown follows the kernel.
    void bringUpRunsTheCommandShown() {
        if (!qtCanPlugins().contains(QStringLiteral("socketcan"))) QSKIP("Qt's socketcan plugin is not installed");
        if (!mayConfigureLinks()) QSKIP("this test runs without CAP_NET_ADMIN: the button is only offered with it");
        // Lists can0 down until "link set can0 up type can bitrate N" ran; logs every other call.
        QTemporaryDir dir;
        const QString calls = dir.filePath(QStringLiteral("calls"));
        StandInIp ip(
            QStringLiteral(
                "if [ \"$1\" = -details ]; then\n"
                "  if [ -f '%1.up' ]; then r=$(cat '%1.up'); flags='\"NOARP\",\"UP\",\"LOWER_UP\"'; st=ERROR-ACTIVE;\n"
                "  else r=250000; flags='\"NOARP\"'; st=STOPPED; fi\n"
                "  echo "
                "\"[{\\\"ifname\\\":\\\"can0\\\",\\\"flags\\\":[$flags],\\\"link_type\\\":\\\"can\\\",\\\"linkinfo\\\":"
                "{\\\"info_kind\\\":\\\"can\\\","
                "\\\"info_data\\\":{\\\"state\\\":\\\"$st\\\",\\\"bittiming\\\":{\\\"bitrate\\\":$r}}}}]\"\n  exit "
                "0\nfi\n"
                "echo \"$*\" >> '%1'\n"
                "if [ \"$4\" = up ] && [ \"$7\" = bitrate ]; then echo \"$8\" > '%1.up'; fi\n")
                .arg(calls)
                .toUtf8());
        QVERIFY(ip.ok());
        ConnectDialog d;
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        QVERIFY(chooseBackend(d, QStringLiteral("socketcan")));
        auto* device = d.findChild<QComboBox*>(QStringLiteral("device"));
        auto* state = d.findChild<QLabel*>(QStringLiteral("linkState"));
        auto* bringUp = d.findChild<QPushButton*>(QStringLiteral("bringUp"));
        QVERIFY(coscope::testing::waitFor([&] { return device->findText(QStringLiteral("can0")) >= 0; }, 5000));
        QVERIFY(pickText(device, QStringLiteral("can0")));
        QVERIFY2(state->text().contains(QStringLiteral("can0 is down")), qPrintable(state->text()));
        auto* bitrate = d.findChild<QComboBox*>(QStringLiteral("bitrate"));
        QVERIFY(pickBitrate(bitrate, 125000));
        QVERIFY(bringUp->isVisible());
        QVERIFY(bringUp->isEnabled());
        QTest::mouseClick(bringUp, Qt::LeftButton);
        QVERIFY2(coscope::testing::waitFor([&] { return state->text().contains(QStringLiteral("can0 is up")); }, 5000),
                 qPrintable(state->text()));
        QVERIFY2(state->text().contains(QStringLiteral("125")), qPrintable(state->text()));
        QVERIFY(!bringUp->isVisible());
        QFile log(calls);
        QVERIFY(log.open(QIODevice::ReadOnly));
        QCOMPARE(QString::fromUtf8(log.readAll()).trimmed(),
                 QStringLiteral("link set can0 up type can bitrate 125000 restart-ms 100"));
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
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        for (int r = 0; r < d.drives()->rowCount(); ++r)
            if (d.drives()->item(r, 0)->checkState() == Qt::Checked) toggleDrive(d, r);
        QPushButton* connectButton = nullptr;
        for (auto* b : d.findChildren<QPushButton*>())
            if (b->text() == QStringLiteral("Connect")) connectButton = b;
        QVERIFY(connectButton);
        QTest::mouseClick(connectButton, Qt::LeftButton);
        QVERIFY(d.isVisible());  // stays open with an inline error
        QCOMPARE(d.result(), int(QDialog::Rejected));
        bool said = false;
        for (auto* l : d.findChildren<QLabel*>())
            if (l->isVisible() && l->text().contains(QStringLiteral("drive"), Qt::CaseInsensitive)) said = true;
        QVERIFY(said);
    }

    void pastedUrlFillsTheChoices() {
        ConnectDialog d;
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        auto* field = d.findChild<QLineEdit*>(QStringLiteral("urlPreview"));
        QApplication::clipboard()->setText(QStringLiteral("socketcand://10.0.0.5:29536/can1?bitrate=250000"));
        QTest::mouseClick(field, Qt::LeftButton);
        QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClick(field, Qt::Key_V, Qt::ControlModifier);
        QCOMPARE(d.backend()->currentData().toString(), QStringLiteral("socketcand"));
        QCOMPARE(d.findChild<QLineEdit*>(QStringLiteral("host"))->text(), QStringLiteral("10.0.0.5"));
        QCOMPARE(field->text(), QStringLiteral("socketcand://10.0.0.5:29536/can1?bitrate=250000"));
        QCOMPARE(d.url(), QStringLiteral("socketcand://10.0.0.5:29536/can1?bitrate=250000"));
        // Typed by hand too.
        QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(field, QStringLiteral("sim://?listen-only=1"));
        QCOMPARE(d.backend()->currentData().toString(), QStringLiteral("sim"));
        QVERIFY(d.listenOnly()->isChecked());
        QCOMPARE(field->text(), QStringLiteral("sim://?listen-only=1"));
        QTest::keyClick(field, Qt::Key_Return);
        QCOMPARE(d.result(), int(QDialog::Accepted));
        QCOMPARE(d.url(), QStringLiteral("sim://?listen-only=1"));
    }

    void replayOffersSpeedAndLoop() {
        ConnectDialog d;
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        QVERIFY(chooseBackend(d, QStringLiteral("replay")));
        auto* path = d.findChild<QLineEdit*>(QStringLiteral("replayPath"));
        QTest::keyClicks(path, QStringLiteral("/tmp/x.log"));
        auto* speed = d.findChild<QComboBox*>(QStringLiteral("replaySpeed"));
        QVERIFY(speed && speed->isVisible());
        QCOMPARE(speed->currentText(), QStringLiteral("1×"));
        speed->setFocus();
        QTest::keyClick(speed, Qt::Key_End);  // as fast as possible
        auto* loop = d.findChild<QCheckBox*>(QStringLiteral("replayLoop"));
        QVERIFY(loop && loop->isVisible());
        QTest::mouseClick(loop, Qt::LeftButton, {}, QPoint(4, loop->height() / 2));
        const QString url = d.findChild<QLineEdit*>(QStringLiteral("urlPreview"))->text();
        QCOMPARE(url, QStringLiteral("replay:///tmp/x.log?speed=0&loop=1"));
        const auto u = BusUrl::parse(url, nullptr);
        QVERIFY(u);
        QCOMPARE(u->speed(), 0.0);
        QVERIFY(u->loop());
        QTest::keyClick(speed, Qt::Key_Home);
        QTest::keyClick(speed, Qt::Key_Down);  // 10×
        QVERIFY(d.url().contains(QStringLiteral("speed=10")));
    }

    void noSocketcanInterfaceSaysWhatToDo() {
        if (!QCanBus::instance()->plugins().contains(QStringLiteral("socketcan"))) QSKIP("no socketcan plugin");
        if (!QCanBus::instance()->availableDevices(QStringLiteral("socketcan")).isEmpty())
            QSKIP("this machine has CAN interfaces");
        ConnectDialog d;
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        QVERIFY(chooseBackend(d, QStringLiteral("socketcan")));
        auto* hint = d.findChild<QLabel*>(QStringLiteral("noDevices"));
        QVERIFY(hint);
        QVERIFY(coscope::testing::waitFor([&] { return hint->isVisible(); }, 5000));
        QVERIFY2(
            hint->text().contains(QStringLiteral("No CAN interfaces")) && hint->text().contains(QStringLiteral("vcan")),
            qPrintable(hint->text()));
        QVERIFY(chooseBackend(d, QStringLiteral("sim")));
        QVERIFY(!hint->isVisible());
    }

    void recentConnections() {
        RecentConnections::add(QStringLiteral("sim://"));
        RecentConnections::add(QStringLiteral("virtualcan://can0"));
        RecentConnections::add(QStringLiteral("sim://"));
        QCOMPARE(RecentConnections::list(),
                 (QStringList{QStringLiteral("sim://"), QStringLiteral("virtualcan://can0")}));
        for (int i = 0; i < 15; ++i) RecentConnections::add(QStringLiteral("virtualcan://can%1").arg(i));
        QCOMPARE(RecentConnections::list().size(), 10);
        RecentConnections::clear();
    }
};

QTEST_MAIN(TestConnectDialog)
#include "test_connect_dialog.moc"
