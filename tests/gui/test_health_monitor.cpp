// SPDX-License-Identifier: GPL-3.0-or-later
// HealthMonitor's two ways in: consume() (live, analysed at once) and consumeLater() (a log
// being opened: analysed behind, at the lowest priority, and published as a whole report).
// Traffic: node 5's heartbeat every 100 ms (CiA 301 §7.2.8.3.2, 705h, state 05h operational),
// its TPDO1 (185h) every 10 ms and one EMCY (085h, error code 2310h "continuous over-current",
// CiA 301 §7.2.7.3.1) in the middle.
#include "app/gui/health/HealthMonitor.h"
#include "core/trace/TraceStore.h"
#include "tests/gui/WaitFor.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::waitFor;

namespace {

CanFrame frame(int64_t ns, uint32_t id, std::initializer_list<uint8_t> data) {
    CanFrame f;
    f.timestampNs = ns;
    f.id = id;
    f.len = static_cast<uint8_t>(data.size());
    std::copy(data.begin(), data.end(), f.data.begin());
    return f;
}

// `seconds` of traffic: 100 TPDOs and 10 heartbeats a second, the EMCY at half time.
std::shared_ptr<TraceStore> traffic(int seconds) {
    auto store = std::make_shared<TraceStore>();
    std::vector<CanFrame> frames;
    for (int64_t ms = 0; ms < seconds * 1000; ms += 10) {
        const int64_t ns = ms * 1'000'000;
        frames.push_back(frame(ns, 0x185, {uint8_t(ms), 0, 0, 0}));
        if (ms % 100 == 0) frames.push_back(frame(ns + 1000, 0x705, {0x05}));
        if (ms == seconds * 500) frames.push_back(frame(ns + 2000, 0x085, {0x10, 0x23, 0x02, 0, 0, 0, 0, 0}));
    }
    store->append(std::span<const CanFrame>(frames));
    return store;
}

const dissect::NodeHealth* node5(const dissect::HealthReport& r) {
    for (const auto& n : r.nodes)
        if (n.node == 5) return &n;
    return nullptr;
}

}  // namespace

class HealthMonitorTest : public QObject {
    Q_OBJECT

private slots:
    // Handed over in pieces, as a loading log does, the report comes out the same as live.
    void laterGivesTheSameReportAsLive() {
        const auto store = traffic(60);
        HealthMonitor live, later;
        live.consume(*store, 0, store->size());
        const size_t half = store->size() / 2;
        later.consumeLater(store, 0, half);
        later.consumeLater(store, FrameNo(half), store->size() - half);
        QVERIFY(waitFor([&] { return later.caughtUp(); }, 30000));
        const auto a = live.report(INT64_MIN), b = later.report(INT64_MIN);
        QCOMPARE(b.bus.frames, uint64_t(store->size()));
        QCOMPARE(b.bus.frames, a.bus.frames);
        QVERIFY(node5(a) && node5(b));
        QCOMPARE(node5(b)->beats, node5(a)->beats);
        QCOMPARE(node5(b)->beats, uint64_t(600));
        QCOMPARE(node5(b)->emcys, uint64_t(1));
        QCOMPARE(b.pdos.size(), a.pdos.size());
        QCOMPARE(b.findings.size(), a.findings.size());
        QCOMPARE(b.endNs, a.endNs);
    }

    // Until it has caught up, the report is one the thread published: never more frames than
    // were handed over, and the revision moves when a new one is out.
    void publishedWhileBehind() {
        const auto store = traffic(600);  // 66,000 frames
        HealthMonitor m;
        const uint64_t rev0 = m.revision();
        QCOMPARE(m.report(INT64_MIN).bus.frames, uint64_t(0));
        m.consumeLater(store, 0, store->size());
        QVERIFY(waitFor([&] { return m.caughtUp(); }, 30000));
        QVERIFY(m.revision() > rev0);
        QCOMPARE(m.report(INT64_MIN).bus.frames, uint64_t(store->size()));
    }

    // clear() (another log opened) drops what waits, and nothing of the old frames comes back
    // once the thread has finished the turn it was in.
    void clearDropsWhatWaits() {
        const auto store = traffic(3600);  // 396,000 frames
        HealthMonitor m;
        m.consumeLater(store, 0, store->size());
        m.clear();
        QVERIFY(waitFor([&] { return m.caughtUp(); }, 30000));
        QTest::qWait(200);
        QCOMPARE(m.report(INT64_MIN).bus.frames, uint64_t(0));
        // The monitor works again afterwards, live.
        const auto small = traffic(2);
        m.consume(*small, 0, small->size());
        QCOMPARE(m.report(INT64_MIN).bus.frames, uint64_t(small->size()));
    }
};

QTEST_MAIN(HealthMonitorTest)
#include "test_health_monitor.moc"
