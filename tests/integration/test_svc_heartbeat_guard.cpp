// SPDX-License-Identifier: GPL-3.0-or-later
// HeartbeatGuard on the virtual drives: it picks the 1016h entry (the one watching CoScope's
// node-ID, else a free one), writes 6007h first and the entry with 3 x the heartbeat period,
// reports each write, puts the old values back on release, refuses without writing on a node
// without 1016h, with every entry in use or without CoScope's heartbeat, and arms a node without
// 6007h on 1016h alone, naming the drive's own reaction.
#include "SvcTestRig.h"

#include "core/canopen/HeartbeatGuard.h"
#include "core/canopen/HeartbeatProducer.h"
#include "core/canopen/ServiceWait.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;
using namespace svctest;

namespace {
HeartbeatGuardResult wait(const std::function<void(HeartbeatGuardCallback)>& start) {
    auto r = waitForResult<HeartbeatGuardResult>(start, 10000);
    if (!r) {
        HeartbeatGuardResult none;
        none.error = QStringLiteral("no result");
        return none;
    }
    return *r;
}
uint64_t value(Rig& rig, uint8_t node, uint16_t index, uint8_t sub) {
    uint64_t v = ~uint64_t(0);
    rig.onDevice(node, [&](sim::VirtualDevice& d) {
        if (auto x = d.value(index, sub)) v = x->toUInt64().value_or(~uint64_t(0));
    });
    return v;
}
void set(Rig& rig, uint8_t node, uint16_t index, uint8_t sub, const od::Value& v) {
    rig.onDevice(node, [&](sim::VirtualDevice& d) { QVERIFY(d.setValue(index, sub, v)); });
}

struct Bench {
    Rig rig;
    std::unique_ptr<SdoClient> sdo;
    std::unique_ptr<HeartbeatProducer> heartbeat;
    bool open() {
        if (!rig.useSpec(QStringLiteral("1:delta-asda-a2,3:generic-cia402,4:dexmart-dev")) || !rig.open()) return false;
        sdo = std::make_unique<SdoClient>(*rig.context);
        heartbeat = std::make_unique<HeartbeatProducer>(*rig.context);
        heartbeat->setPeriodMs(100);
        return heartbeat->start();
    }
};
}  // namespace

class TestSvcHeartbeatGuard : public QObject {
    Q_OBJECT
private slots:
    void armsAFreeEntryAndPutsBack() {
        Bench b;
        QVERIFY(b.open());
        set(b.rig, 3, 0x1016, 1, od::Value::unsignedInt(0x00050064));  // watching node 5 already
        HeartbeatGuard guard(*b.sdo, 3);
        QStringList sent;
        guard.setSendObserver([&](const QString& line) { sent << line; });
        const auto r = wait([&](auto cb) { guard.arm(*b.heartbeat, cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        QVERIFY(guard.armed());
        QCOMPARE(int(r.consumerSub), 2);
        QCOMPARE(r.consumerEntry, 0x007F012Cu);
        QCOMPARE(r.abortOption.value_or(-1), int16_t(3));
        QCOMPARE(sent.size(), 2);
        QVERIFY2(sent[0].startsWith(QStringLiteral("node 3: 6007h = 3 (quick stop")),
                 qPrintable(sent[0]));  // reaction first
        QVERIFY2(sent[1].startsWith(QStringLiteral("node 3: 1016h:02 = 0x007F012C")), qPrintable(sent[1]));
        QVERIFY2(r.summary.contains(QStringLiteral("300 ms")) &&
                     r.summary.contains(QStringLiteral("6007h = 3 (quick stop)")),
                 qPrintable(r.summary));
        QCOMPARE(value(b.rig, 3, 0x1016, 2), 0x007F012Cu);
        QCOMPARE(value(b.rig, 3, 0x6007, 0), 3u);

        sent.clear();
        const auto back = wait([&](auto cb) { guard.release(cb); });
        QVERIFY2(back.ok, qPrintable(back.error));
        QVERIFY(!guard.armed());
        QCOMPARE(sent.size(), 2);
        QVERIFY2(sent[0].startsWith(QStringLiteral("node 3: 1016h:02 = 0x00000000")),
                 qPrintable(sent[0]));  // stop watching first
        QCOMPARE(value(b.rig, 3, 0x1016, 2), 0u);
        QCOMPARE(value(b.rig, 3, 0x6007, 0), 1u);
        QCOMPARE(value(b.rig, 3, 0x1016, 1), 0x00050064u);  // untouched
        // Releasing again changes nothing.
        sent.clear();
        QVERIFY(wait([&](auto cb) { guard.release(cb); }).ok);
        QVERIFY(sent.isEmpty());
    }

    void reusesTheEntryWatchingCoScope() {
        Bench b;
        QVERIFY(b.open());
        set(b.rig, 3, 0x1016, 3, od::Value::unsignedInt(0x007F01F4));  // node 127, 500 ms
        HeartbeatGuard guard(*b.sdo, 3);
        guard.setAbortOption(2);
        guard.setConsumerTimeMs(250);
        const auto r = wait([&](auto cb) { guard.arm(*b.heartbeat, cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(int(r.consumerSub), 3);
        QCOMPARE(value(b.rig, 3, 0x1016, 3), 0x007F00FAu);
        QCOMPARE(value(b.rig, 3, 0x6007, 0), 2u);
        QVERIFY(wait([&](auto cb) { guard.release(cb); }).ok);
        QCOMPARE(value(b.rig, 3, 0x1016, 3), 0x007F01F4u);
    }

    void refusesWithoutWriting() {
        Bench b;
        QVERIFY(b.open());
        QStringList sent;
        // DEXMART DEV: no 1016h.
        HeartbeatGuard dev(*b.sdo, 4);
        dev.setSendObserver([&](const QString& line) { sent << line; });
        auto r = wait([&](auto cb) { dev.arm(*b.heartbeat, cb); });
        QVERIFY(!r.ok);
        QVERIFY2(r.error.contains(QStringLiteral("has no heartbeat consumer (1016h)")) &&
                     r.error.contains(QStringLiteral("nothing changed")),
                 qPrintable(r.error));
        // Delta: its one entry watches another node.
        set(b.rig, 1, 0x1016, 1, od::Value::unsignedInt(0x00050064));
        HeartbeatGuard delta(*b.sdo, 1);
        delta.setSendObserver([&](const QString& line) { sent << line; });
        r = wait([&](auto cb) { delta.arm(*b.heartbeat, cb); });
        QVERIFY(!r.ok);
        QVERIFY2(
            r.error.contains(QStringLiteral("all 1 heartbeat consumer entries (1016h) are in use, watching node 5")),
            qPrintable(r.error));
        // CoScope's heartbeat is not running.
        b.heartbeat->stop();
        HeartbeatGuard generic(*b.sdo, 3);
        generic.setSendObserver([&](const QString& line) { sent << line; });
        r = wait([&](auto cb) { generic.arm(*b.heartbeat, cb); });
        QVERIFY2(!r.ok && r.error.contains(QStringLiteral("heartbeat is not running")), qPrintable(r.error));
        QVERIFY2(sent.isEmpty(), qPrintable(sent.join(u'\n')));
        QCOMPARE(value(b.rig, 1, 0x1016, 1), 0x00050064u);
        QCOMPARE(value(b.rig, 3, 0x6007, 0), 1u);
    }

    // Delta ASDA-A2 has no 6007h: 1016h alone, and the summary names its alarm AL170.
    void withoutAbortOptionTheDrivesOwnReaction() {
        Bench b;
        QVERIFY(b.open());
        b.rig.context->setNodeDictionary(1, QStringLiteral("delta-asda-a2"));
        HeartbeatGuard guard(*b.sdo, 1);
        QStringList sent;
        guard.setSendObserver([&](const QString& line) { sent << line; });
        const auto r = wait([&](auto cb) { guard.arm(*b.heartbeat, cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        QVERIFY(!r.abortOption);
        QCOMPARE(sent,
                 QStringList{QStringLiteral("node 1: 1016h:01 = 0x007F012C (watch node 127's heartbeat, 300 ms)")});
        QVERIFY2(r.summary.contains(QStringLiteral("no 6007h")) && r.summary.contains(QStringLiteral("AL170")),
                 qPrintable(r.summary));
        QVERIFY(wait([&](auto cb) { guard.release(cb); }).ok);
        QCOMPARE(value(b.rig, 1, 0x1016, 1), 0u);
    }
};

QTEST_GUILESS_MAIN(TestSvcHeartbeatGuard)
#include "test_svc_heartbeat_guard.moc"
