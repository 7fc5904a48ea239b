// SPDX-License-Identifier: GPL-3.0-or-later
// DESIGN.md "Reliability and safety": the app never transmits in listen-only mode. Every backend
// refuses send() on a listen-only URL and nothing reaches the other side.
#include "core/can/CanBus.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "eds/SimulatorDictionaries.h"
#include "integration/FakeSocketcandServer.h"
#include "tests/CliRun.h"

#include <QElapsedTimer>
#include <QLoggingCategory>
#include <QtTest>

using namespace coscope;

namespace {
// True when `bus` receives a frame with `id` within timeoutMs.
bool sees(CanBus& bus, uint32_t id, int timeoutMs) {
    QElapsedTimer t;
    t.start();
    CanFrame buf[64];
    while (t.elapsed() < timeoutMs) {
        bus.waitForFrames(20);
        for (size_t n = bus.read(buf, 64), i = 0; i < n; ++i)
            if (buf[i].id == id) return true;
    }
    return false;
}

void checkRefused(CanBus& bus) {
    QString err;
    QVERIFY(!bus.send(CanFrame::classic(0x123, {0xAA}), &err));
    QVERIFY2(err.contains(QStringLiteral("listen-only")), qPrintable(err));
    QCOMPARE(bus.counters().tx, uint64_t(0));
}
}  // namespace

class TestListenOnly : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QLoggingCategory::setFilterRules(
            QStringLiteral("qt.canbus.plugins.*.debug=false\nqt.canbus.plugins.*.info=false"));
        eds::installSimulatorDictionaries();
    }

    void simBus() {
        QString err;
        std::shared_ptr<sim::SimNetwork> net = sim::SimNetwork::fromSpec({}, &err);
        QVERIFY2(net, qPrintable(err));
        auto listenUrl = BusUrl::parse(QStringLiteral("sim://?listen-only=1"), &err);
        auto plainUrl = BusUrl::parse(QStringLiteral("sim://"), &err);
        QVERIFY(listenUrl && plainUrl);
        SimBus listener(*listenUrl, net);
        SimBus observer(*plainUrl, net);
        listener.open();
        observer.open();
        QVERIFY(listener.waitForOpen(2000) && observer.waitForOpen(2000));
        checkRefused(listener);
        QVERIFY(!sees(observer, 0x123, 300));
        QVERIFY(!sees(listener, 0x123, 50));  // no Tx echo either
        // Control: the same frame from a normal endpoint does get across.
        QVERIFY(observer.send(CanFrame::classic(0x124, {0xAA}), &err));
        QVERIFY(sees(listener, 0x124, 1000));
        listener.close();
        observer.close();
    }

    void virtualCan() {
        if (!qtCanPlugins().contains(QStringLiteral("virtualcan"))) QSKIP("Qt's virtualcan plugin is not installed");
        QString err;
        auto listener = createBus(QStringLiteral("virtualcan://can0?listen-only=1"), &err);
        auto observer = createBus(QStringLiteral("virtualcan://can0"), &err);
        QVERIFY2(listener && observer, qPrintable(err));
        listener->open();
        QVERIFY2(listener->waitForOpen(5000), qPrintable(listener->errorString()));
        observer->open();
        QVERIFY2(observer->waitForOpen(5000), qPrintable(observer->errorString()));
        QTest::qWait(200);
        checkRefused(*listener);
        QVERIFY(!sees(*observer, 0x123, 300));
        QVERIFY(observer->send(CanFrame::classic(0x124, {0xAA}), &err));  // control
        QVERIFY(sees(*listener, 0x124, 2000));
        observer->close();
        listener->close();
    }

    void socketcand() {
        FakeSocketcandServer server;
        QVERIFY(server.listen());
        QString err;
        auto bus = createBus(server.url(QStringLiteral("?listen-only=1")), &err);
        QVERIFY2(bus, qPrintable(err));
        bus->open();
        QVERIFY2(bus->waitForOpen(3000), qPrintable(bus->errorString()));
        server.write("< frame 181 1.0 01 >");  // receiving still works
        QVERIFY(sees(*bus, 0x181, 2000));
        checkRefused(*bus);
        QTest::qWait(300);
        QCOMPARE(server.afterHandshake, QByteArray());
        bus->close();
    }

    void cliSendRefuses() {
        const Run r =
            cli({QStringLiteral("send"), QStringLiteral("sim://?listen-only=1"), QStringLiteral("123#11")}, 10000);
        QCOMPARE(r.code, 1);
        const QString& err = r.err;
        QVERIFY2(err.contains(QStringLiteral("coscope-cli send: ")) && err.contains(QStringLiteral("listen-only")),
                 qPrintable(err));
    }
};

QTEST_GUILESS_MAIN(TestListenOnly)
#include "test_listen_only.moc"
