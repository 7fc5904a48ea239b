// SPDX-License-Identifier: GPL-3.0-or-later
// The node table's NMT state and where it comes from (core/canopen/NodeTable.h, issue 35), fed
// with frames as a bus carries them: boot-up 700h+n 00h, heartbeat 700h+n 05h/7Fh/04h (CiA 301
// §7.2.8.3.2), NMT 000h cs nn (§7.2.8.3.1) sent by us (Tx) or by another master, guarding RTR
// and answer, and the node's own TPDO 180h+n / SDO answer 580h+n / EMCY 80h+n, which only some
// states allow (§7.3.2.2: PDOs only in Operational; SDO and EMCY in Pre-operational and
// Operational; Stopped has only NMT and error control).
#include "core/canopen/NodeTable.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;

namespace {
constexpr int64_t kMs = 1'000'000;

struct Bus {
    TraceStore store;
    NodeTable table;
    int64_t ns = 0;

    // One frame `ms` after the previous one.
    void frame(uint32_t id, std::initializer_list<uint8_t> data, int64_t ms = 100, uint8_t flags = 0) {
        CanFrame f = CanFrame::classic(id, data);
        f.flags |= flags;
        f.timestampNs = ns += ms * kMs;
        const FrameNo n = store.append(f);
        table.consume(store, n, 1);
    }
    void rtr(uint32_t id, int64_t ms = 100) {
        CanFrame f;
        f.id = id;
        f.len = 1;
        f.flags = CanFrame::Remote | CanFrame::Tx;
        f.timestampNs = ns += ms * kMs;
        table.consume(store, store.append(f), 1);
    }
    int state(int node) const { return table.node(node).value_or(NodeInfo{}).nmtState; }
    NmtSource source(int node) const { return table.node(node).value_or(NodeInfo{}).nmtSource; }
    bool gap(int node) const { return table.node(node).value_or(NodeInfo{}).stateUnknownAfterGap; }
};
}  // namespace

class NodeTableNmtTest : public QObject {
    Q_OBJECT
private slots:
    void bootUpThenHeartbeat() {
        Bus b;
        b.frame(0x702, {0x00});
        QCOMPARE(b.state(2), 0x7F);  // boot-up leads to Pre-operational (CiA 301 §7.3.2.2.1)
        QCOMPARE(b.source(2), NmtSource::BootUp);
        for (uint8_t s : {0x05, 0x7F, 0x04}) {
            b.frame(0x702, {s});
            QCOMPARE(b.state(2), int(s));
            QCOMPARE(b.source(2), NmtSource::Heartbeat);
        }
        QVERIFY(b.table.node(2)->seenHeartbeat);
        QCOMPARE(b.table.node(2)->heartbeatPeriodNs, 100 * kMs);
    }

    // Today's bug: node 2 stayed Pre-operational after Start while it sent TPDOs.
    void ourStartThenThePdosConfirmIt() {
        Bus b;
        b.frame(0x702, {0x00});
        b.frame(0x703, {0x00});
        b.frame(0x000, {0x01, 0x02}, 100, CanFrame::Tx);  // our NMT Start of node 2
        QCOMPARE(b.state(2), 0x05);
        QCOMPARE(b.source(2), NmtSource::OurCommand);
        QCOMPARE(int(b.table.node(2)->nmtCommand), 0x01);
        QCOMPARE(b.state(3), 0x7F);  // not addressed
        QCOMPARE(b.source(3), NmtSource::BootUp);
        // Its first TPDO (event-driven ones go out on entering Operational) confirms it.
        b.frame(0x182, {1, 2}, 1);
        QCOMPARE(b.state(2), 0x05);
        QCOMPARE(b.source(2), NmtSource::Pdo);
        QCOMPARE(b.table.node(2)->nmtFrame, FrameNo(3));
        // After our Stop, a TPDO at once may have been queued before it: no evidence yet; one
        // later shows the node did not stop.
        b.frame(0x000, {0x02, 0x02}, 100, CanFrame::Tx);
        b.frame(0x182, {1, 2}, 1);
        QCOMPARE(b.state(2), 0x04);
        QCOMPARE(b.source(2), NmtSource::OurCommand);
        b.frame(0x182, {1, 2}, 50);
        QCOMPARE(b.state(2), 0x05);
        QCOMPARE(b.source(2), NmtSource::Pdo);
        QCOMPARE(b.table.node(2)->nmtFrame, FrameNo(6));
        // A node that sends PDOs is Operational whatever was last heard: node 3 said 7Fh.
        b.frame(0x183, {0}, 100);
        QCOMPARE(b.state(3), 0x05);
        QCOMPARE(b.source(3), NmtSource::Pdo);
        // A TPDO never creates a node (its COB-ID may be remapped), nor does a command.
        b.frame(0x185, {0});
        b.frame(0x000, {0x01, 0x06}, 100, CanFrame::Tx);
        QVERIFY(!b.table.node(5));
        QVERIFY(!b.table.node(6));
    }

    void anotherMastersCommandToAll() {
        Bus b;
        b.frame(0x701, {0x7F});
        b.frame(0x702, {0x00});
        b.frame(0x000, {0x01, 0x00});  // Rx: another master starts all nodes
        for (int n : {1, 2}) {
            QCOMPARE(b.state(n), 0x05);
            QCOMPARE(b.source(n), NmtSource::OtherCommand);
        }
        b.frame(0x000, {0x02, 0x01});  // stop node 1
        QCOMPARE(b.state(1), 0x04);
        QCOMPARE(int(b.table.node(1)->nmtCommand), 0x02);
        // Its heartbeat confirms it.
        b.frame(0x701, {0x04});
        QCOMPARE(b.source(1), NmtSource::Heartbeat);
        // A reset: the state is unknown until the boot-up.
        b.frame(0x000, {0x81, 0x02}, 100, CanFrame::Tx);
        QCOMPARE(b.state(2), -1);
        QCOMPARE(b.source(2), NmtSource::OurCommand);
        b.frame(0x702, {0x00});
        QCOMPARE(b.state(2), 0x7F);
        QCOMPARE(b.source(2), NmtSource::BootUp);
    }

    void framesTheStateDoesNotAllow() {
        Bus b;
        b.frame(0x704, {0x04});  // Stopped by its heartbeat
        // An SDO answer: Stopped has no SDO, so at least Pre-operational (not Operational).
        b.frame(0x584, {0x43, 0x00, 0x10, 0x00, 0x92, 0x01, 0x02, 0x00});
        QCOMPARE(b.state(4), 0x7F);
        QCOMPARE(b.source(4), NmtSource::Sdo);
        // SDO in Operational is allowed: nothing changes.
        b.frame(0x704, {0x05});
        b.frame(0x584, {0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0});
        QCOMPARE(b.state(4), 0x05);
        QCOMPARE(b.source(4), NmtSource::Heartbeat);
        // EMCY while Stopped (by our command): Pre-operational at least.
        b.frame(0x000, {0x02, 0x04}, 100, CanFrame::Tx);
        QCOMPARE(b.state(4), 0x04);
        b.frame(0x084, {0x10, 0x23, 0x01, 0, 0, 0, 0, 0});
        QCOMPARE(b.state(4), 0x7F);
        QCOMPARE(b.source(4), NmtSource::Emcy);
        // Our own frames at the node's TPDO id (an RTR asking for it, or a Tx) are no evidence.
        b.frame(0x704, {0x7F});
        b.frame(0x184, {1}, 100, CanFrame::Tx);
        QCOMPARE(b.state(4), 0x7F);
    }

    void guardingAnswer() {
        Bus b;
        b.frame(0x705, {0x00});
        b.rtr(0x705);
        b.frame(0x705, {0x05}, 2);  // toggle 0
        QCOMPARE(b.state(5), 0x05);
        QCOMPARE(b.source(5), NmtSource::Guarding);
        b.rtr(0x705);
        b.frame(0x705, {0x80 | 0x7F}, 2);  // toggle 1
        QCOMPARE(b.state(5), 0x7F);
        QCOMPARE(b.source(5), NmtSource::Guarding);
        QVERIFY(!b.table.node(5)->seenHeartbeat);
    }

    // After a lost bus the state is unknown until the node's frames show it, heartbeat or not.
    void gapClearsOnTheNodesFrames() {
        Bus b;
        b.frame(0x702, {0x00});
        b.frame(0x000, {0x01, 0x02}, 100, CanFrame::Tx);
        b.frame(0x182, {1}, 50);
        b.frame(0x703, {0x00});
        b.frame(0x704, {0x05});
        b.table.markGap(FrameNo(b.store.size()));
        for (int n : {2, 3, 4}) QVERIFY(b.gap(n));
        b.frame(0x182, {1}, 500);  // node 2, no heartbeat: its PDO shows Operational
        QVERIFY(!b.gap(2));
        QCOMPARE(b.state(2), 0x05);
        QCOMPARE(b.source(2), NmtSource::Pdo);
        b.frame(0x583, {0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0});  // node 3 answers SDO: Pre-operational
        QVERIFY(!b.gap(3));
        QCOMPARE(b.state(3), 0x7F);
        QCOMPARE(b.source(3), NmtSource::Sdo);
        // Node 4 was Operational: an SDO answer does not tell whether it still is.
        b.frame(0x584, {0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0});
        QVERIFY(b.gap(4));
        b.frame(0x704, {0x05});
        QVERIFY(!b.gap(4));
        // A command after the gap sets it too.
        b.table.markGap(FrameNo(b.store.size()));
        b.frame(0x000, {0x80, 0x00}, 100, CanFrame::Tx);
        for (int n : {2, 3, 4}) {
            QVERIFY(!b.gap(n));
            QCOMPARE(b.state(n), 0x7F);
            QCOMPARE(b.source(n), NmtSource::OurCommand);
        }
    }
};

QTEST_GUILESS_MAIN(NodeTableNmtTest)
#include "test_node_table_nmt.moc"
