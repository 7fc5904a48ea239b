// SPDX-License-Identifier: GPL-3.0-or-later
// The node table and the event log the Nodes and Events docks show, fed from trace frames.
#include "app/gui/events/EventLog.h"
#include "core/canopen/NodeTable.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::gui;

namespace {
CanFrame at(int64_t ms, CanFrame f) {
    f.timestampNs = ms * 1'000'000;
    return f;
}
}  // namespace

class TestNodeEvents : public QObject {
    Q_OBJECT
private slots:
    void nodesFromTraffic() {
        TraceStore store;
        store.append(at(0, CanFrame::classic(0x702, {0x00})));  // boot-up node 2
        store.append(at(100, CanFrame::classic(0x702, {0x7F})));
        store.append(at(1100, CanFrame::classic(0x702, {0x05})));
        store.append(at(1200, CanFrame::classic(0x083, {0x10, 0x23, 0x05, 0, 0, 0, 0, 0})));  // EMCY node 3
        store.append(at(1300, CanFrame::classic(0x083, {0x00, 0x00, 0x00, 0, 0, 0, 0, 0})));  // error reset
        store.append(at(1400, CanFrame::classic(0x604, {0x40, 0x00, 0x10, 0, 0, 0, 0, 0})));  // request only: no node
        store.append(
            at(1500, CanFrame::classic(0x586, {0x43, 0x00, 0x10, 0, 0x92, 0x01, 0x02, 0x00})));  // SDO response node 6
        store.append(at(1600, CanFrame::classic(0x187, {1, 2})));                                // TPDO alone: no node
        canopen::NodeTable t;
        const uint64_t r0 = t.revision();
        t.consume(store, 0, store.size());
        QVERIFY(t.revision() != r0);
        const auto nodes = t.snapshot();
        QCOMPARE(nodes.size(), size_t(3));
        const auto n2 = t.node(2);
        QVERIFY(n2);
        QCOMPARE(n2->nmtState, 0x05);
        QCOMPARE(n2->bootUps, 1u);
        QVERIFY(n2->seenHeartbeat);
        QCOMPARE(n2->heartbeatPeriodNs, int64_t(1'000'000'000));
        const auto n3 = t.node(3);
        QVERIFY(n3);
        QCOMPARE(n3->emcyCount, 1u);  // the error reset is not counted
        QVERIFY(t.node(6) && t.node(6)->seenSdo);
        QVERIFY(!t.node(4));
        QVERIFY(!t.node(7));
        t.setDictionary(2, QStringLiteral("aimotor"));
        t.setIdentity(2, 0x1234, 0x42, std::nullopt, 7);
        QCOMPARE(t.node(2)->dictionary, QStringLiteral("aimotor"));
        QCOMPARE(*t.node(2)->vendorId, 0x1234u);
        t.clear();
        QVERIFY(t.snapshot().empty());
    }

    void eventsFromTraffic() {
        TraceStore store;
        store.append(at(0, CanFrame::classic(0x701, {0x00})));         // 0 boot-up
        store.append(at(10, CanFrame::classic(0x000, {0x01, 0x01})));  // 1 NMT start node 1
        store.append(at(100, CanFrame::classic(0x701, {0x7F})));       // 2 state pre-op (first seen)
        store.append(at(1100, CanFrame::classic(0x701, {0x05})));      // 3 pre-op -> operational
        store.append(at(2100, CanFrame::classic(0x701, {0x05})));      // 4 no change
        store.append(at(2200, CanFrame::classic(0x081, {0x10, 0x23, 0x05, 0, 0, 0, 0, 0})));                 // 5 EMCY
        store.append(at(2300, CanFrame::classic(0x581, {0x80, 0x00, 0x20, 0x01, 0x00, 0x00, 0x02, 0x06})));  // 6 abort
        store.append(at(9000, CanFrame::classic(0x702, {0x05})));  // 7 node 2, much later
        EventLog log;
        log.consume(store, 0, store.size());
        const auto ev = log.since(0);
        auto count = [&](TraceEvent::Kind k) {
            return std::count_if(ev.begin(), ev.end(), [k](const TraceEvent& e) { return e.kind == k; });
        };
        QCOMPARE(count(TraceEvent::Kind::BootUp), 1);
        QCOMPARE(count(TraceEvent::Kind::NmtCommand), 1);
        QCOMPARE(count(TraceEvent::Kind::Emcy), 1);
        QCOMPARE(count(TraceEvent::Kind::SdoAbort), 1);
        // operational after pre-operational; pre-op right after boot-up is not a change
        QCOMPARE(count(TraceEvent::Kind::NmtState), 2);  // node 1 pre-op -> op, node 2 first state
        // Node 1's heartbeat (period 1 s) stopped at 2.1 s; the log's clock says 9 s.
        QCOMPARE(count(TraceEvent::Kind::HeartbeatTimeout), 1);
        const auto emcy =
            std::find_if(ev.begin(), ev.end(), [](const TraceEvent& e) { return e.kind == TraceEvent::Kind::Emcy; });
        QCOMPARE(emcy->frame, FrameNo(5));
        QCOMPARE(emcy->node, 1);
        QVERIFY(emcy->text.contains(QStringLiteral("2310")));
        const auto abort = std::find_if(ev.begin(), ev.end(),
                                        [](const TraceEvent& e) { return e.kind == TraceEvent::Kind::SdoAbort; });
        QVERIFY2(abort->text.contains(QStringLiteral("06020000")), qPrintable(abort->text));
        QCOMPARE(abort->frame, FrameNo(6));
        // since() returns only what is new
        QCOMPARE(log.since(ev.size()).size(), size_t(0));
        log.add(renderedEvent(TraceEvent::Kind::Dropped, 0, kNoFrame, -1,
                              [] { return QStringLiteral("3 frames dropped"); }));
        QCOMPARE(log.since(ev.size()).size(), size_t(1));
        const auto gen = log.generation();
        log.clear();
        QVERIFY(log.generation() != gen);
        QCOMPARE(log.size(), size_t(0));
    }
};

QTEST_GUILESS_MAIN(TestNodeEvents)
#include "test_node_events.moc"
