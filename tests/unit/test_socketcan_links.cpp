// SPDX-License-Identifier: GPL-3.0-or-later
// SocketCAN interfaces as `ip -details -json link show` reports them (iproute2 ip/iplink_can.c
// prints IFLA_CAN_STATE as "state", IFLA_CAN_BITTIMING as "bittiming", IFLA_CAN_BERR_COUNTER as
// "berr_counter"), and what an open error means to a technician.
#include "core/can/BusUrl.h"
#include "core/can/SocketCanLinks.h"

#include <QtTest>

using namespace coscope;

namespace {
// Written after iproute2's JSON output: a loopback, a virtual CAN that is up, a real CAN interface
// that is down with its last bit timing, and a CAN FD interface that went error passive.
const char* kIpJson = R"([
 {"ifindex":1,"ifname":"lo","flags":["LOOPBACK","UP","LOWER_UP"],"mtu":65536,"operstate":"UNKNOWN","link_type":"loopback"},
 {"ifindex":5,"ifname":"vcan0","flags":["NOARP","UP","LOWER_UP"],"mtu":72,"operstate":"UNKNOWN","link_type":"can",
  "linkinfo":{"info_kind":"vcan"}},
 {"ifindex":6,"ifname":"can0","flags":["NOARP","ECHO"],"mtu":16,"operstate":"DOWN","link_type":"can",
  "linkinfo":{"info_kind":"can","info_data":{"state":"STOPPED","berr_counter":{"tx":0,"rx":0},"restart_ms":0,
   "bittiming":{"bitrate":250000,"sample_point":"0.875","tq":250,"prop_seg":6,"phase_seg1":7,"phase_seg2":2,"sjw":1,"brp":1}}}},
 {"ifindex":7,"ifname":"can1","flags":["NOARP","UP","LOWER_UP","ECHO"],"mtu":72,"operstate":"UP","link_type":"can",
  "linkinfo":{"info_kind":"can","info_data":{"ctrlmode":["FD"],"state":"ERROR-PASSIVE","berr_counter":{"tx":128,"rx":3},
   "restart_ms":100,"bittiming":{"bitrate":500000,"sample_point":"0.800"},"data_bittiming":{"bitrate":2000000,"sample_point":"0.750"}}}}
])";
}  // namespace

class TestSocketCanLinks : public QObject {
    Q_OBJECT
private slots:
    void parsesOnlyCanLinksWithStateAndTiming() {
        QList<SocketCanLink> links;
        QString error;
        QVERIFY2(parseIpLinkJson(kIpJson, &links, &error), qPrintable(error));
        QCOMPARE(links.size(), 3);  // lo is not CAN
        QCOMPARE(links[0].name, QStringLiteral("vcan0"));
        QVERIFY(links[0].isVirtual());
        QVERIFY(links[0].up);
        QCOMPARE(links[0].bitrate, 0);
        QCOMPARE(links[1].name, QStringLiteral("can0"));
        QVERIFY(!links[1].up);
        QCOMPARE(links[1].bitrate, 250000);
        QCOMPARE(links[1].controllerState, QStringLiteral("STOPPED"));
        QCOMPARE(links[2].bitrate, 500000);
        QCOMPARE(links[2].dataBitrate, 2000000);
        QVERIFY(links[2].fd);
        QCOMPARE(links[2].controllerState, QStringLiteral("ERROR-PASSIVE"));
        QCOMPARE(links[2].txErrors, 128);
        QCOMPARE(links[2].rxErrors, 3);
        QCOMPARE(describeLink(links[1]), QStringLiteral("down"));
        QCOMPARE(describeLink(links[2]), QStringLiteral("up, 500 kbit/s, FD 2 Mbit/s, ERROR-PASSIVE, TEC 128 REC 3"));
    }

    void refusesWhatIsNotIpJson() {
        QList<SocketCanLink> links;
        QString error;
        QVERIFY(!parseIpLinkJson("1: lo: <LOOPBACK,UP> mtu 65536", &links, &error));
        QVERIFY2(error.contains(QStringLiteral("not JSON")), qPrintable(error));
        QVERIFY(!parseIpLinkJson(R"({"ifname":"can0"})", &links, &error));
    }

    void bringUpCommandsFollowIpLink8() {
        QList<SocketCanLink> links;
        QVERIFY(parseIpLinkJson(kIpJson, &links, nullptr));
        QCOMPARE(bringUpCommand(links[0], 500000), QStringLiteral("sudo ip link set vcan0 up"));
        QCOMPARE(bringUpCommand(links[1], 500000),
                 QStringLiteral("sudo ip link set can0 up type can bitrate 500000 restart-ms 100"));
        QCOMPARE(bringUpCommand(links[2], 1000000, 4000000),
                 QStringLiteral("sudo ip link set can1 down; sudo ip link set can1 up type can bitrate 1000000 "
                                "dbitrate 4000000 fd on restart-ms 100"));
    }

    void openErrorsSayWhatToDo() {
        // The texts are strerror(3) of EAFNOSUPPORT, ENODEV, ENETDOWN and EPERM, as Qt's socketcan plugin passes them on.
        QVERIFY(
            explainSocketCanError(QStringLiteral("can0"), QStringLiteral("Address family not supported by protocol"), 0)
                .contains(QStringLiteral("modprobe can_raw")));
        qputenv("COSCOPE_IP", "/nonexistent/ip");  // no interfaces to name
        const QString nodev = explainSocketCanError(QStringLiteral("can7"), QStringLiteral("No such device"), 0);
        QVERIFY2(nodev.contains(QStringLiteral("no CAN interface named 'can7'")), qPrintable(nodev));
        qunsetenv("COSCOPE_IP");
        QVERIFY(explainSocketCanError(QStringLiteral("can0"), QStringLiteral("Network is down"), 125000)
                    .contains(QStringLiteral("sudo ip link set can0 up type can bitrate 125000")));
        QVERIFY(explainSocketCanError(QStringLiteral("can0"), QStringLiteral("Operation not permitted"), 0)
                    .contains(QStringLiteral("CAP_NET_ADMIN")));
        QCOMPARE(explainSocketCanError(QStringLiteral("can0"), QStringLiteral("something else"), 0),
                 QStringLiteral("something else"));
    }

    void tinycanListsWithoutProbing() {
        QVERIFY(!pluginProbesHardware(QStringLiteral("tinycan")));
        QVERIFY(pluginProbesHardware(QStringLiteral("socketcan")));
    }
};

QTEST_GUILESS_MAIN(TestSocketCanLinks)
#include "test_socketcan_links.moc"
