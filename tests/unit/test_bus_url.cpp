// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/BusInterfaceName.h"
#include "core/can/BusUrl.h"
#include "core/can/CanBus.h"

#include <QtTest>

using namespace coscope;

class TestBusUrl : public QObject {
    Q_OBJECT
private slots:
    void parsesQtPluginUrls() {
        QString err;
        auto u = BusUrl::parse(QStringLiteral("socketcan://can0"), &err);
        QVERIFY2(u, qPrintable(err));
        QCOMPARE(u->scheme, QStringLiteral("socketcan"));
        QCOMPARE(u->target, QStringLiteral("can0"));
        QVERIFY(u->isQtPlugin());
        QCOMPARE(busInterfaceName(*u), QStringLiteral("can0"));

        u = BusUrl::parse(QStringLiteral("VirtualCAN://can1?bitrate=250000&fd=1&data-bitrate=2000000&listen-only=1"),
                          &err);
        QVERIFY2(u, qPrintable(err));
        QCOMPARE(u->scheme, QStringLiteral("virtualcan"));
        QCOMPARE(u->target, QStringLiteral("can1"));
        QCOMPARE(u->bitrate(), 250000);
        QCOMPARE(u->dataBitrate(), 2000000);
        QVERIFY(u->canFd());
        QVERIFY(u->listenOnly());
    }
    void optionDefaultsAndBooleans() {
        QString err;
        auto u = BusUrl::parse(QStringLiteral("socketcan://can0"), &err);
        QVERIFY(u);
        QCOMPARE(u->bitrate(), 0);
        QCOMPARE(u->dataBitrate(), 0);
        QVERIFY(!u->canFd());
        QVERIFY(!u->listenOnly());
        u = BusUrl::parse(QStringLiteral("socketcan://can0?listen-only"), &err);  // bare flag = on
        QVERIFY(u && u->listenOnly());
        u = BusUrl::parse(QStringLiteral("socketcan://can0?listen-only=0"), &err);
        QVERIFY(u && !u->listenOnly());
        u = BusUrl::parse(QStringLiteral("socketcan://can0?listen-only=true"), &err);
        QVERIFY(u && u->listenOnly());
    }
    void parsesSocketcand() {
        QString err;
        auto u = BusUrl::parse(QStringLiteral("socketcand://192.168.1.5:29000/can1"), &err);
        QVERIFY2(u, qPrintable(err));
        QCOMPARE(u->scheme, QStringLiteral("socketcand"));
        QCOMPARE(u->host, QStringLiteral("192.168.1.5"));
        QCOMPARE(u->port, quint16(29000));
        QCOMPARE(u->channel, QStringLiteral("can1"));
        QVERIFY(!u->isQtPlugin());
        QCOMPARE(busInterfaceName(*u), QStringLiteral("can1"));

        u = BusUrl::parse(QStringLiteral("socketcand://pi.local/vcan0"), &err);
        QVERIFY2(u, qPrintable(err));
        QCOMPARE(u->host, QStringLiteral("pi.local"));
        QCOMPARE(u->port, kSocketcandDefaultPort);
        QCOMPARE(u->channel, QStringLiteral("vcan0"));

        u = BusUrl::parse(QStringLiteral("socketcand://[::1]:1234/can0?listen-only=1"), &err);
        QVERIFY2(u, qPrintable(err));
        QCOMPARE(u->host, QStringLiteral("::1"));
        QCOMPARE(u->port, quint16(1234));
        QVERIFY(u->listenOnly());
    }
    void parsesSimAndReplay() {
        QString err;
        auto u = BusUrl::parse(QStringLiteral("sim://"), &err);
        QVERIFY2(u, qPrintable(err));
        QCOMPARE(u->scheme, QStringLiteral("sim"));
        QCOMPARE(busInterfaceName(*u), QStringLiteral("sim"));
        u = BusUrl::parse(QStringLiteral("sim://?nodes=1:delta-asda-a2,2:aimotor"), &err);
        QVERIFY2(u, qPrintable(err));
        QCOMPARE(u->option(QStringLiteral("nodes")), QStringLiteral("1:delta-asda-a2,2:aimotor"));

        u = BusUrl::parse(QStringLiteral("replay:///tmp/field%20log.log?speed=2.5&loop=1"), &err);
        QVERIFY2(u, qPrintable(err));
        QCOMPARE(u->target, QStringLiteral("/tmp/field log.log"));
        QCOMPARE(u->speed(), 2.5);
        QVERIFY(u->loop());
        QCOMPARE(busInterfaceName(*u), QStringLiteral("field_log"));
    }
    void unknownSchemeListsKnownOnes() {
        QString err;
        QVERIFY(!BusUrl::parse(QStringLiteral("sockcan://can0"), &err));
        QVERIFY2(err.startsWith(QStringLiteral("unknown scheme 'sockcan'; known: ")), qPrintable(err));
        for (const char* s : {"socketcan", "virtualcan", "socketcand", "sim", "replay"})
            QVERIFY2(err.contains(QLatin1String(s)), qPrintable(err));
    }
    void clearErrors_data() {
        QTest::addColumn<QString>("url");
        QTest::addColumn<QString>("expected");
        QTest::newRow("no scheme") << "can0"
                                   << "expected SCHEME://TARGET";
        QTest::newRow("missing device") << "socketcan://"
                                        << "needs a device name";
        QTest::newRow("missing channel") << "socketcand://host:29536"
                                         << "needs a channel";
        QTest::newRow("empty channel") << "socketcand://host:29536/"
                                       << "needs a channel";
        QTest::newRow("bad port") << "socketcand://host:99999/can0"
                                  << "port '99999' is not a port number";
        QTest::newRow("text port") << "socketcand://host:abc/can0"
                                   << "port 'abc'";
        QTest::newRow("no host") << "socketcand://:29536/can0"
                                 << "needs a host";
        QTest::newRow("bad bitrate") << "socketcan://can0?bitrate=fast"
                                     << "bitrate must be a positive number";
        QTest::newRow("zero bitrate") << "socketcan://can0?bitrate=0"
                                      << "bitrate must be a positive number";
        QTest::newRow("bad data bitrate") << "socketcan://can0?data-bitrate=-1"
                                          << "data-bitrate must be a positive number";
        QTest::newRow("unknown option") << "socketcan://can0?baud=500k"
                                        << "unknown option 'baud'";
        QTest::newRow("bad speed") << "replay:///x.log?speed=fast"
                                   << "speed must be a number";
        QTest::newRow("replay without file") << "replay://"
                                             << "needs a file";
    }
    void clearErrors() {
        QFETCH(QString, url);
        QFETCH(QString, expected);
        QString err;
        QVERIFY2(!BusUrl::parse(url, &err), qPrintable(url));
        QVERIFY2(err.contains(expected), qPrintable(err));
        QVERIFY(!err.contains(u'\n'));
    }
    void roundTripsThroughToString() {
        QString err;
        auto u = BusUrl::parse(QStringLiteral("socketcand://10.0.0.2:29536/can0?listen-only=1"), &err);
        QVERIFY(u);
        auto again = BusUrl::parse(u->toString(), &err);
        QVERIFY2(again, qPrintable(err));
        QCOMPARE(again->host, u->host);
        QCOMPARE(again->channel, u->channel);
        QCOMPARE(again->listenOnly(), true);
    }
    void createBusPicksTheBackend() {
        QString err;
        auto bus = createBus(QStringLiteral("socketcand://127.0.0.1:1/can0"), &err);
        QVERIFY2(bus, qPrintable(err));
        QVERIFY(bus->state() == CanBus::State::Closed);
        QVERIFY(!createBus(QStringLiteral("sockcan://x"), &err));
        QVERIFY(err.contains(QStringLiteral("unknown scheme")));
        if (!qtCanPlugins().contains(QStringLiteral("vectorcan"))) {
            QVERIFY(!createBus(QStringLiteral("vectorcan://can0"), &err));
            QVERIFY2(err.contains(QStringLiteral("not installed")), qPrintable(err));
        }
    }
};

QTEST_GUILESS_MAIN(TestBusUrl)
#include "test_bus_url.moc"
