// SPDX-License-Identifier: GPL-3.0-or-later
// The PDO engine of the virtual devices (CiA 301 §7.2.2) with raw frames.
#include "SimTestHarness.h"

#include "core/canopen/SdoAbort.h"

#include <QtTest>

#include <algorithm>
#include <cstdint>
#include <functional>

using namespace coscope;
using namespace coscope::testing;

namespace {
int countId(const std::vector<CanFrame>& fs, uint32_t id) {
    return int(std::count_if(fs.begin(), fs.end(), [id](const CanFrame& f) { return f.id == id; }));
}
CanFrame syncFrame() { return CanFrame::classic(0x080, {}); }

// Collects until `enough` holds for what came, however late a loaded machine's simulator
// answers (up to 30 s), then 50 ms more so that one frame too many would show.
std::vector<CanFrame> collectUntil(SimHarness& h, const std::function<bool(const std::vector<CanFrame>&)>& enough) {
    std::vector<CanFrame> got;
    QElapsedTimer t;
    t.start();
    while (!enough(got) && t.elapsed() < 30000) {
        const auto more = h.collect(20);
        got.insert(got.end(), more.begin(), more.end());
    }
    const auto late = h.collect(50);
    got.insert(got.end(), late.begin(), late.end());
    return got;
}

// The simulator's time of each frame `id` (its frames carry its clock), in order.
std::vector<int64_t> timesOf(const std::vector<CanFrame>& fs, uint32_t id) {
    std::vector<int64_t> ts;
    for (const auto& f : fs)
        if (f.id == id) ts.push_back(f.timestampNs);
    return ts;
}

// Consecutive times (ns) never closer than `least`, and at least once within `onTime` (on time
// while the simulator keeps up; it skips the stalls of a loaded machine, so some gaps are longer).
bool spacedAtLeast(const std::vector<int64_t>& ts, int64_t least, int64_t onTime) {
    int64_t shortest = INT64_MAX;
    for (size_t i = 1; i < ts.size(); ++i) {
        if (ts[i] - ts[i - 1] < least) {
            qWarning("frames %lld ns apart (at least %lld)", static_cast<long long>(ts[i] - ts[i - 1]),
                     static_cast<long long>(least));
            return false;
        }
        shortest = std::min(shortest, ts[i] - ts[i - 1]);
    }
    if (shortest > onTime)
        qWarning("shortest gap %lld ns (on time: %lld)", static_cast<long long>(shortest),
                 static_cast<long long>(onTime));
    return shortest <= onTime;
}
}  // namespace

class TestSimPdo : public QObject {
    Q_OBJECT
    static constexpr uint8_t A = 2;  // aimotor
    static constexpr uint8_t G = 3;  // generic-cia402

    // Re-maps TPDO1 of `node` to the statusword only with transmission type `type`, as a master
    // would: disable (bit 31), mapping, re-enable (CiA 301 §7.5.2.36 procedure).
    static void configureTpdo1(SimHarness& h, uint8_t node, uint8_t type, uint16_t inhibit100us = 0,
                               uint16_t eventMs = 0) {
        QVERIFY(h.download(node, 0x1800, 1, SimHarness::u32(0x80000180u + node)).ok());
        QVERIFY(h.download(node, 0x1800, 2, SimHarness::u8(type)).ok());
        QVERIFY(h.download(node, 0x1800, 3, SimHarness::u16(inhibit100us)).ok());
        QVERIFY(h.download(node, 0x1800, 5, SimHarness::u16(eventMs)).ok());
        QVERIFY(h.download(node, 0x1A00, 0, SimHarness::u8(0)).ok());
        QVERIFY(h.download(node, 0x1A00, 1, SimHarness::u32(0x60640020)).ok());  // position actual value
        QVERIFY(h.download(node, 0x1A00, 0, SimHarness::u8(1)).ok());
        QVERIFY(h.download(node, 0x1800, 1, SimHarness::u32(0x180u + node)).ok());
    }

private slots:
    void initTestCase() { eds::installSimulatorDictionaries(); }

    void aimotorDefaultTpdosOnSync() {
        SimHarness h;
        QString err;
        QVERIFY2(h.open(QStringLiteral("2:aimotor"), &err), qPrintable(err));
        h.send(syncFrame());
        QCOMPARE(countId(h.collect(50), 0x182), 0);  // PRE-OPERATIONAL: no PDOs
        h.send(CanFrame::classic(0x000, {0x01, A}));
        h.collect(20);
        for (int i = 0; i < 5; ++i) {
            h.send(syncFrame());
            QTest::qWait(5);
        }
        const auto fs =
            collectUntil(h, [](const auto& got) { return countId(got, 0x182) >= 5 && countId(got, 0x282) >= 5; });
        // Default TPDO1 = 6041h + 6061h + 6064h, 7 bytes; TPDO2 = 606Ch + 6077h, 6 bytes; type 1
        // (extract-aimotor §3.6 "Default mappings").
        QCOMPARE(countId(fs, 0x182), 5);
        QCOMPARE(countId(fs, 0x282), 5);
        const auto t1 = std::find_if(fs.begin(), fs.end(), [](const CanFrame& f) { return f.id == 0x182; });
        QCOMPARE(int(t1->len), 7);
        QCOMPARE(t1->data[0] & 0x4F, 0x40);  // statusword: switch on disabled
        const auto t2 = std::find_if(fs.begin(), fs.end(), [](const CanFrame& f) { return f.id == 0x282; });
        QCOMPARE(int(t2->len), 6);
    }

    void everyNthSync() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("3:generic-cia402"), &err));
        configureTpdo1(h, G, 3);
        h.send(CanFrame::classic(0x000, {0x01, G}));
        h.collect(20);
        for (int i = 0; i < 9; ++i) {
            h.send(syncFrame());
            QTest::qWait(4);
        }
        QCOMPARE(countId(collectUntil(h, [](const auto& got) { return countId(got, 0x183) >= 3; }), 0x183), 3);
    }

    void rtrRequestsTpdo() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("3:generic-cia402"), &err));
        configureTpdo1(h, G, 253);  // asynchronous, RTR only
        h.send(CanFrame::classic(0x000, {0x01, G}));
        QCOMPARE(countId(h.collect(60), 0x183), 0);
        CanFrame rtr = CanFrame::classic(0x183, {});
        rtr.flags |= CanFrame::Remote;
        rtr.len = 4;
        h.send(rtr);
        QCOMPARE(countId(collectUntil(h, [](const auto& got) { return countId(got, 0x183) >= 1; }), 0x183), 1);
    }

    void eventTimer() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("3:generic-cia402"), &err));
        configureTpdo1(h, G, 254, 0, 50);  // event-driven, event timer 50 ms
        h.send(CanFrame::classic(0x000, {0x01, G}));
        // One per 50 ms of the simulator's clock: never sooner, and on time while the simulator
        // keeps up (it skips the stalls of a loaded machine, so some gaps may be longer).
        const auto ts = timesOf(collectUntil(h, [](const auto& got) { return countId(got, 0x183) >= 11; }), 0x183);
        QVERIFY2(ts.size() >= 11, qPrintable(QString::number(ts.size())));
        QVERIFY(spacedAtLeast(ts, 49'000'000, 51'000'000));
    }

    void inhibitTimeSpacesChanges() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("3:generic-cia402"), &err));
        configureTpdo1(h, G, 255, 200, 0);  // position actual on change, inhibit 20 ms
        // Move the axis in profile velocity so the position changes every millisecond.
        QVERIFY(h.download(G, 0x6060, 0, SimHarness::u8(3)).ok());
        QVERIFY(h.download(G, 0x60FF, 0, SimHarness::u32(100000)).ok());
        for (uint16_t cw : {0x06, 0x07, 0x0F}) QVERIFY(h.download(G, 0x6040, 0, SimHarness::u16(cw)).ok());
        h.send(CanFrame::classic(0x000, {0x01, G}));
        // In the simulator's time: never sooner than the inhibit time, and as soon as it allows
        // (the position changes every millisecond) while the simulator keeps up.
        const auto ts = timesOf(collectUntil(h, [](const auto& got) { return countId(got, 0x183) >= 8; }), 0x183);
        QVERIFY2(ts.size() >= 8, qPrintable(QString::number(ts.size())));
        QVERIFY(spacedAtLeast(ts, 19'000'000, 22'000'000));
    }

    void rpdoAppliesOnSync() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("2:aimotor"), &err));
        h.send(CanFrame::classic(0x000, {0x01, A}));
        // Default RPDO1 = 6040h + 6060h + 607Ah, type 1: takes effect at the next SYNC.
        h.send(CanFrame::classic(0x202, {0x06, 0x00, 0x01, 0x10, 0x27, 0x00, 0x00}));
        h.collect(20);
        QCOMPARE(h.read(A, 0x607A, 0).value_or(1), 0u);
        h.send(syncFrame());
        h.collect(20);
        QCOMPARE(h.read(A, 0x607A, 0).value_or(0), 10000u);
        QCOMPARE(h.read(A, 0x6061, 0).value_or(0), 1u);
        QCOMPARE(h.read(A, 0x6041, 0).value_or(0) & 0x6F, 0x21u);  // ready to switch on
    }

    void mappingRules() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("3:generic-cia402"), &err));
        // Mapping while the PDO is valid is refused; a non-mappable object is refused.
        QCOMPARE(h.download(G, 0x1A00, 0, SimHarness::u8(0)).abort, canopen::sdoabort::UnsupportedAccess);
        QVERIFY(h.download(G, 0x1800, 1, SimHarness::u32(0x80000183u)).ok());
        QVERIFY(h.download(G, 0x1A00, 0, SimHarness::u8(0)).ok());
        QCOMPARE(h.download(G, 0x1A00, 1, SimHarness::u32(0x10180120)).abort, canopen::sdoabort::NotMappable);
        QCOMPARE(h.download(G, 0x1A00, 1, SimHarness::u32(0x2FFF0020)).abort, canopen::sdoabort::NoObject);
    }
};

QTEST_GUILESS_MAIN(TestSimPdo)
#include "test_sim_pdo.moc"
