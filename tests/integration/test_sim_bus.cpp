// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/CanBus.h"
#include "core/sim/SimBus.h"
#include "core/trace/CaptureSession.h"
#include "eds/SimulatorDictionaries.h"

#include <QtTest>

using namespace coscope;

namespace {
// Collects frames for `ms`; with syncEveryMs > 0 it also sends a SYNC (080h) that often.
std::vector<CanFrame> collect(CanBus& bus, int ms, int syncEveryMs = 0) {
    std::vector<CanFrame> out;
    QElapsedTimer t;
    t.start();
    CanFrame buf[64];
    qint64 nextSync = 0;
    while (t.elapsed() < ms) {
        if (syncEveryMs > 0 && t.elapsed() >= nextSync) {
            bus.send(CanFrame::classic(0x080, {}));
            nextSync = t.elapsed() + syncEveryMs;
        }
        bus.waitForFrames(syncEveryMs > 0 ? 2 : 20);
        const size_t n = bus.read(buf, 64);
        out.insert(out.end(), buf, buf + n);
    }
    return out;
}
}  // namespace

class TestSimBus : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { eds::installSimulatorDictionaries(); }

    void nodesBootAndAnswerNmt() {
        QString err;
        auto bus = createBus(QStringLiteral("sim://?nodes=5:aimotor,6:aimotor"), &err);
        QVERIFY2(bus, qPrintable(err));
        bus->open();
        QVERIFY(bus->waitForOpen(1000));
        auto frames = collect(*bus, 300);
        // Boot-up: 700h + node-ID with one byte 00h (CiA 301 §7.2.8.3.3).
        auto bootOf = [&](uint32_t id) {
            return std::count_if(frames.begin(), frames.end(),
                                 [id](const CanFrame& f) { return f.id == id && f.len == 1 && f.data[0] == 0; });
        };
        QCOMPARE(bootOf(0x705), 1);
        QCOMPARE(bootOf(0x706), 1);

        // NMT start node 5 only: TPDO1 of node 5 (185h, transmission type 1: every SYNC,
        // extract-aimotor §3.6) flows, node 6 stays silent on 186h.
        QVERIFY2(bus->send(CanFrame::classic(0x000, {0x01, 0x05}), &err), qPrintable(err));
        frames = collect(*bus, 300, 10);
        const auto tx =
            std::find_if(frames.begin(), frames.end(), [](const CanFrame& f) { return f.id == 0 && f.isTx(); });
        QVERIFY2(tx != frames.end(), "our NMT frame is echoed as Tx");
        const auto pdo5 = std::count_if(frames.begin(), frames.end(), [](const CanFrame& f) { return f.id == 0x185; });
        const auto pdo6 = std::count_if(frames.begin(), frames.end(), [](const CanFrame& f) { return f.id == 0x186; });
        QVERIFY2(pdo5 >= 10, qPrintable(QString::number(pdo5)));
        QCOMPARE(pdo6, 0);
        const auto counters = bus->counters();
        QVERIFY(counters.tx >= uint64_t(11));  // NMT + SYNCs
        QCOMPARE(counters.dropped, uint64_t(0));
        bus->close();
        QVERIFY(bus->state() == CanBus::State::Closed);
    }

    void heartbeatsCarryState() {
        QString err;
        auto bus = createBus(QStringLiteral("sim://?nodes=9:generic-cia402"), &err);
        QVERIFY(bus);
        bus->open();
        QVERIFY(bus->waitForOpen(1000));
        collect(*bus, 30);
        // The bundled dictionaries have 1017h = 0 (no heartbeat): set 1000 ms by SDO.
        QVERIFY(bus->send(CanFrame::classic(0x609, {0x2B, 0x17, 0x10, 0x00, 0xE8, 0x03, 0x00, 0x00})));
        const auto frames = collect(*bus, 1300);
        QVERIFY(std::any_of(frames.begin(), frames.end(),
                            [](const CanFrame& f) { return f.id == 0x589 && f.data[0] == 0x60; }));
        // Heartbeat with state 7Fh (pre-operational), once per second.
        const auto hb = std::count_if(frames.begin(), frames.end(), [](const CanFrame& f) {
            return f.id == 0x709 && f.len == 1 && f.data[0] == 0x7F;
        });
        QCOMPARE(hb, 1);
    }

    void rejectsBadNodeSpec_data() {
        QTest::addColumn<QString>("url");
        QTest::addColumn<QString>("reason");
        QTest::newRow("node 0") << "sim://?nodes=0:aimotor"
                                << "1-127";
        QTest::newRow("twice") << "sim://?nodes=1:aimotor,1:aimotor"
                               << "twice";
        QTest::newRow("unknown drive") << "sim://?nodes=1:nosuch"
                                       << "unknown virtual drive";
        QTest::newRow("ethercat") << "sim://?nodes=1:icpdas-ecat-2094p"
                                  << "EtherCAT";
    }
    void rejectsBadNodeSpec() {
        QFETCH(QString, url);
        QFETCH(QString, reason);
        QString err;
        auto bus = createBus(url, &err);
        QVERIFY(bus);
        bus->open();
        QVERIFY(!bus->waitForOpen(500));
        QVERIFY(bus->state() == CanBus::State::Error);
        QVERIFY2(bus->errorString().contains(reason), qPrintable(bus->errorString()));
    }

    void twoEndpointsShareOneNetwork() {
        BusUrl url = *BusUrl::parse(QStringLiteral("sim://?nodes=1:aimotor"), nullptr);
        SimBus a(url);
        a.open();
        QVERIFY(a.waitForOpen(1000));
        SimBus b(url, a.sharedNetwork());
        b.open();
        QVERIFY(b.waitForOpen(1000));
        collect(a, 50);
        collect(b, 50);
        QVERIFY(a.send(*parseCansend(u"123#AABB", nullptr)));
        const auto got = collect(b, 100);
        QVERIFY(std::any_of(got.begin(), got.end(),
                            [](const CanFrame& f) { return f.id == 0x123 && !f.isTx() && f.len == 2; }));
        b.close();
        a.close();
    }

    void captureSessionFillsStore() {
        QString err;
        auto bus = createBus(QStringLiteral("sim://?nodes=3:aimotor"), &err);
        QVERIFY(bus);
        CaptureSession session;
        session.start(bus.get());
        bus->open();
        QVERIFY(bus->waitForOpen(1000));
        QTRY_VERIFY_WITH_TIMEOUT(session.store()->size() >= 1, 2000);
        QVERIFY(bus->send(CanFrame::classic(0x000, {0x01, 0x00})));
        // AIMOTOR TPDOs are synchronous (type 1): send SYNCs.
        QElapsedTimer t;
        t.start();
        while (session.store()->countFor(TraceStore::keyOf(0x183, false)) < 5 &&
               t.elapsed() < 30000) {  // a loaded machine answers late
            bus->send(CanFrame::classic(0x080, {}));
            QTest::qWait(10);
        }
        QVERIFY(session.store()->countFor(TraceStore::keyOf(0x183, false)) >= 5);
        session.stop();
        bus->close();
        QCOMPARE(session.store()->record(0).id, 0x703u);  // boot-up came first
    }
};

QTEST_GUILESS_MAIN(TestSimBus)
#include "test_sim_bus.moc"
