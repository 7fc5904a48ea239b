// SPDX-License-Identifier: GPL-3.0-or-later
// NetworkHealth on frames built from CiA 301: heartbeat 700h+node (§7.2.8.3.2), boot-up 00h,
// NMT 000h (§7.2.8.3.1), SDO 600h/580h (§7.2.4), EMCY 80h+node (§7.2.7), SYNC 080h, PDOs; each
// with figures worked out by hand.
#include "core/can/CanFrame.h"
#include "dissectors/HealthOutput.h"
#include "dissectors/HealthRules.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/NetworkHealth.h"
#include "dissectors/TraceStats.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QtTest>

using namespace coscope;
using namespace coscope::dissect;

namespace {
constexpr int64_t kMs = 1'000'000;

struct Feed {
    NetworkContext ctx;
    Dissection d;
    NetworkHealth h;
    Feed() { ctx.setGenericNames(false); }
    void at(double ms, uint32_t id, std::initializer_list<uint8_t> bytes, uint8_t flags = 0) {
        CanFrame f = CanFrame::classic(id, bytes);
        f.flags |= flags;
        f.timestampNs = static_cast<int64_t>(ms * kMs);
        if (!f.isError()) ctx.dissect(f, d, Dissection::Level::Stats);
        h.add(f, d, ctx);
    }
    HealthReport report(double nowMs = -1) const {
        return nowMs < 0 ? h.report(&ctx) : h.report(&ctx, static_cast<int64_t>(nowMs * kMs));
    }
};

const NodeHealth* nodeOf(const HealthReport& r, int id) {
    for (const NodeHealth& n : r.nodes)
        if (n.node == id) return &n;
    return nullptr;
}
bool hasFinding(const HealthReport& r, const QString& text) {
    for (const HealthFinding& f : r.findings)
        if (f.text.contains(text)) return true;
    return false;
}
QString findings(const HealthReport& r) {
    QStringList l;
    for (const HealthFinding& f : r.findings) l << f.text;
    return l.join(QStringLiteral(" | "));
}
}  // namespace

class NetworkHealthTest : public QObject {
    Q_OBJECT
private slots:
    void heartbeatPeriodLateAndTimeouts() {
        Feed f;
        // Node 5 at 100 ms (observed): gaps 100 x5, 170 (late), 100, 400 (lost), 100.
        for (double t : {0.0, 100.0, 200.0, 300.0, 400.0, 500.0, 670.0, 770.0, 1170.0, 1270.0}) f.at(t, 0x705, {0x05});
        HealthReport r = f.report();
        const NodeHealth* n = nodeOf(r, 5);
        QVERIFY(n);
        QCOMPARE(n->errorControl, QStringLiteral("heartbeat"));
        QCOMPARE(n->beats, 10u);
        QCOMPARE(n->periodMinMs, 100.0);
        QCOMPARE(n->periodMaxMs, 400.0);
        QVERIFY(qAbs(n->periodAvgMs - 1270.0 / 9) < 1e-6);
        QCOMPARE(n->expectedPeriodMs, 100.0);
        QCOMPARE(n->periodSource, QStringLiteral("observed"));
        QCOMPARE(n->late, 1u);
        QCOMPARE(n->timeouts, 1u);
        QVERIFY(!n->silentNow);
        QCOMPARE(n->state, 5);
        QVERIFY2(hasFinding(r, QStringLiteral("node 5 heartbeat lost once")), qPrintable(findings(r)));
        QVERIFY2(hasFinding(r, QStringLiteral("node 5 heartbeat late once")), qPrintable(findings(r)));
        // Half a second of silence later the heartbeat has stopped: a timeout that lasts.
        r = f.report(1770);
        n = nodeOf(r, 5);
        QVERIFY(n->silentNow);
        QCOMPARE(n->timeouts, 2u);
        QCOMPARE(n->silentForMs, 500.0);
        QCOMPARE(r.findings.front().kind, QStringLiteral("heartbeat_stopped"));
    }

    // A heartbeat that starts late (boot-up, then 1017h set seconds later) is not lost; "lost"
    // is a stop after regular beats (issue 37). Node 6 boots at 0, beats at 100 ms from 4 s.
    void heartbeatThatStartsLateIsNotLost() {
        Feed f;
        f.at(0, 0x706, {0x00});
        // Before its producer runs, one stray state answer at 1 s, then regular beats from 4 s.
        f.at(1000, 0x706, {0x7F});
        for (int i = 0; i < 10; ++i) f.at(4000 + 100.0 * i, 0x706, {0x7F});
        HealthReport r = f.report(4950);
        const NodeHealth* n = nodeOf(r, 6);
        QVERIFY(n);
        QCOMPARE(n->expectedPeriodMs, 100.0);
        QCOMPARE(n->timeouts, 0u);
        QCOMPARE(n->late, 0u);
        QVERIFY(!n->silentNow);
        QVERIFY2(!hasFinding(r, QStringLiteral("node 6 heartbeat lost")), qPrintable(findings(r)));
        // Then it stops after those regular beats: that is lost.
        r = f.report(5500);
        n = nodeOf(r, 6);
        QVERIFY(n->silentNow);
        QCOMPARE(n->timeouts, 1u);
        // A node that booted and never beat is not "lost" either (no heartbeat configured).
        Feed g;
        g.at(0, 0x707, {0x00});
        r = g.report(10000);
        QVERIFY(nodeOf(r, 7));
        QCOMPARE(nodeOf(r, 7)->timeouts, 0u);
        QVERIFY(!nodeOf(r, 7)->silentNow);
    }

    void heartbeatPeriodFrom1017h() {
        Feed f;
        // Expedited download of 1017h:00 = 200 ms (2Bh: 2 bytes), then the server's answer.
        f.at(0, 0x603, {0x2B, 0x17, 0x10, 0x00, 0xC8, 0x00, 0x00, 0x00});
        f.at(1, 0x583, {0x60, 0x17, 0x10, 0x00, 0x00, 0x00, 0x00, 0x00});
        // Beats at 200 ms, one after 350 ms (> 1.5 x 200: late), none over 600 ms.
        for (double t : {10.0, 210.0, 410.0, 760.0, 960.0}) f.at(t, 0x703, {0x7F});
        const HealthReport r = f.report();
        const NodeHealth* n = nodeOf(r, 3);
        QVERIFY(n);
        QCOMPARE(n->expectedPeriodMs, 200.0);
        QCOMPARE(n->periodSource, QStringLiteral("1017h"));
        QCOMPARE(n->late, 1u);
        QCOMPARE(n->timeouts, 0u);
        QCOMPARE(n->sdoOk, 1u);
    }

    void bootUpsResetsAndNmtCauses() {
        Feed f;
        f.at(0, 0x70F, {0x00});         // power-on boot-up: not a reset
        f.at(10, 0x000, {0x01, 0x00});  // NMT start, all nodes
        f.at(20, 0x70F, {0x05});
        f.at(1000, 0x70F, {0x00});  // boot-up with no command: the node reset itself
        f.at(1100, 0x70F, {0x7F});
        f.at(2000, 0x000, {0x81, 0x0F});  // NMT reset node 15
        f.at(2100, 0x70F, {0x00});        // expected boot-up
        f.at(3000, 0x70F, {0x00});        // another reset
        const HealthReport r = f.report();
        const NodeHealth* n = nodeOf(r, 15);
        QVERIFY(n);
        QCOMPARE(n->bootUps, 4u);
        QCOMPARE(n->resets, 2u);
        QCOMPARE(n->nmtCommands, 2u);
        QVERIFY(n->nmtChanges.size() >= 5);
        QCOMPARE(n->nmtChanges[0].cause, QStringLiteral("power-on"));
        QCOMPARE(n->nmtChanges[1].to, 5);
        QVERIFY2(n->nmtChanges[1].cause.contains(QStringLiteral("Start")) &&
                     n->nmtChanges[1].cause.contains(QStringLiteral("all nodes")),
                 qPrintable(n->nmtChanges[1].cause));
        QVERIFY(n->nmtChanges[2].cause.contains(QStringLiteral("unexpected")));
        QVERIFY2(n->nmtChanges[4].cause.contains(QStringLiteral("node 15")), qPrintable(n->nmtChanges[4].cause));
        QVERIFY2(hasFinding(r, QStringLiteral("node 15 rebooted 2 times")), qPrintable(findings(r)));
        QCOMPARE(r.findings.front().kind, QStringLiteral("reset"));
    }

    void sdoResponseTimesAbortsAndTimeouts() {
        Feed f;
        double t = 0;
        // Upload 1000h:00 answered after 2, 5 and 180 ms (expedited, 4 bytes: 43h).
        for (double rt : {2.0, 5.0, 180.0}) {
            f.at(t, 0x62A, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
            f.at(t + rt, 0x5AA, {0x43, 0x00, 0x10, 0x00, 0x92, 0x01, 0x02, 0x00});
            t += 1000;
        }
        // Upload 2000h:00 aborted after 3 ms with 06020000h (object does not exist).
        f.at(t, 0x62A, {0x40, 0x00, 0x20, 0x00, 0, 0, 0, 0});
        f.at(t + 3, 0x5AA, {0x80, 0x00, 0x20, 0x00, 0x00, 0x00, 0x02, 0x06});
        t += 1000;
        f.at(t, 0x62A, {0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0});  // never answered
        const HealthReport r = f.report(t + 2000);
        const NodeHealth* n = nodeOf(r, 42);
        QVERIFY(n);
        QCOMPARE(n->sdoRequests, 5u);
        QCOMPARE(n->sdoResponses, 4u);
        QCOMPARE(n->sdoTransfers, 4u);
        QCOMPARE(n->sdoOk, 3u);
        QCOMPARE(n->sdoAborted, 1u);
        QCOMPARE(n->sdoTimeouts, 1u);
        QCOMPARE(n->sdoRtMinMs, 2.0);
        QCOMPARE(n->sdoRtMaxMs, 180.0);
        QCOMPARE(n->sdoRtP99Ms, 180.0);
        QVERIFY(qAbs(n->sdoRtAvgMs - 47.5) < 1e-3);
        QCOMPARE(n->sdoAborts.size(), size_t(1));
        QCOMPARE(n->sdoAborts[0].code, 0x06020000u);
        QVERIFY2(n->sdoAborts[0].text.contains(QStringLiteral("not exist")), qPrintable(n->sdoAborts[0].text));
        QVERIFY2(hasFinding(r, QStringLiteral("node 42 answered SDO in 180 ms p99")), qPrintable(findings(r)));
        QVERIFY2(hasFinding(r, QStringLiteral("node 42 left 1 SDO request unanswered")), qPrintable(findings(r)));
        QVERIFY2(hasFinding(r, QStringLiteral("06020000h")), qPrintable(findings(r)));
    }

    // A scan probes node-IDs with one upload of 1000h each and aborts (client abort 80h,
    // 05040000h timeout, CiA 301 §7.2.4.3.17) where nothing answers: those IDs are one finding,
    // not a table row each. A node-ID asked again and again without an answer is a finding.
    void scanProbesAreSummarisedNotListed() {
        Feed f;
        double t = 0;
        f.at(t, 0x701, {0x05});  // node 1 is there
        for (int id = 5; id <= 9; ++id) {
            f.at(t, 0x600u + id, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0});
            f.at(t + 100, 0x600u + id, {0x80, 0x00, 0x10, 0x00, 0x00, 0x00, 0x04, 0x05});
            t += 150;
        }
        for (int i = 0; i < 5; ++i, t += 1500) f.at(t, 0x60C, {0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0});
        const HealthReport r = f.report(t);
        QVERIFY(nodeOf(r, 1));
        for (int id = 5; id <= 9; ++id) QVERIFY2(!nodeOf(r, id), qPrintable(QString::number(id)));
        QCOMPARE(r.bus.silentAddressed, (std::vector<int>{5, 6, 7, 8, 9}));
        QVERIFY2(hasFinding(r, QStringLiteral("5 node-IDs (5..9) got an SDO request and never answered")),
                 qPrintable(findings(r)));
        // Node 12, asked again and again, never sent anything: no node row (issue 37: only nodes
        // seen are listed), but its unanswered requests are an error finding with their frames.
        QVERIFY(!nodeOf(r, 12));
        const HealthFinding* missing = nullptr;
        for (const HealthFinding& x : r.findings)
            if (x.rule == QLatin1String("sdo.timeout") && x.node == 12) missing = &x;
        QVERIFY2(missing, qPrintable(findings(r)));
        QCOMPARE(missing->severity, int(HealthFinding::Error));
        QVERIFY(missing->at.count >= 4);
        QCOMPARE(missing->at.frames.front(), uint64_t{11});  // frames 0..10: heartbeat and 5 probes of 2, then node 12
        const QJsonObject json = healthJson(r);
        QCOMPARE(json.value(QStringLiteral("bus"))
                     .toObject()
                     .value(QStringLiteral("silent_addressed_nodes"))
                     .toArray()
                     .size(),
                 5);
    }

    // Issue 37: CoScope's own scan (requests marked Tx, CanFrame::Tx) is no device's fault. It
    // reads 1000h of node-IDs 1..20 (only node 1 answers), then an optional object node 1 does
    // not have (abort 06020000h, CiA 301 §7.2.4.3.17), and a last request to node 30 times out.
    void ownScanGivesNoErrorOrWarning() {
        Feed f;
        double t = 0;
        f.at(t, 0x701, {0x05});
        for (int id = 1; id <= 20; ++id, t += 120) {
            f.at(t, 0x600u + id, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}, CanFrame::Tx);
            if (id == 1) f.at(t + 1, 0x581, {0x43, 0x00, 0x10, 0x00, 0x92, 0x01, 0x02, 0x00});
            else
                f.at(t + 100, 0x600u + id, {0x80, 0x00, 0x10, 0x00, 0x00, 0x00, 0x04, 0x05},
                     CanFrame::Tx);  // our abort: timed out
        }
        f.at(t, 0x601, {0x40, 0x08, 0x10, 0x00, 0, 0, 0, 0}, CanFrame::Tx);
        f.at(t + 2, 0x581, {0x80, 0x08, 0x10, 0x00, 0x00, 0x00, 0x02, 0x06});
        t += 10;
        f.at(t, 0x61E, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}, CanFrame::Tx);
        for (int i = 0; i < 30; ++i) f.at(t += 100, 0x701, {0x05});
        const HealthReport r = f.report();
        for (const HealthFinding& x : r.findings) {
            QVERIFY2(x.severity == HealthFinding::Info, qPrintable(x.rule + QStringLiteral(": ") + x.what));
            if (x.rule.startsWith(QLatin1String("coscope."))) QVERIFY(x.own);
        }
        QCOMPARE(r.verdict, QStringLiteral("No problems found"));
        QCOMPARE(r.nodes.size(), size_t(1));  // only node 1 was seen
        QStringList rules;
        for (const HealthFinding& x : r.findings) rules << x.rule;
        QVERIFY2(rules.contains(QStringLiteral("coscope.scan")) && rules.contains(QStringLiteral("coscope.sdo_abort")),
                 qPrintable(rules.join(u' ')));
        QVERIFY(!rules.contains(QStringLiteral("sdo.abort")) && !rules.contains(QStringLiteral("sdo.timeout")) &&
                !rules.contains(QStringLiteral("sdo.silent_nodes")));
        // The same requests from another master (not Tx) are the device's findings.
        Feed other;
        other.at(0, 0x701, {0x05});
        other.at(10, 0x601, {0x40, 0x08, 0x10, 0x00, 0, 0, 0, 0});
        other.at(12, 0x581, {0x80, 0x08, 0x10, 0x00, 0x00, 0x00, 0x02, 0x06});
        const HealthReport o = other.report();
        QVERIFY2(!o.findings.empty() && o.findings.front().rule == QLatin1String("sdo.abort") &&
                     o.findings.front().severity == HealthFinding::Warning,
                 qPrintable(findings(o)));
        QCOMPARE(o.findings.front().at.frames, (std::vector<uint64_t>{2}));
        QCOMPARE(o.verdict, QStringLiteral("Problems found: 1 warning"));
    }

    // Issue 37: every finding has its rule's three sentences with the values filled in.
    void findingsExplainThemselves() {
        Feed f;
        for (double t : {0.0, 100.0, 200.0, 300.0, 400.0, 500.0, 900.0, 1000.0}) f.at(t, 0x705, {0x05});
        const HealthReport r = f.report();
        QVERIFY(!r.findings.empty());
        const HealthFinding& lost = r.findings.front();
        QCOMPARE(lost.rule, QStringLiteral("heartbeat.lost"));
        QCOMPARE(
            lost.what,
            QStringLiteral(
                "Node 5's heartbeat was missing 1 time(s) after regular beats (longest gap 400 ms, period 100 ms)."));
        QVERIFY(!lost.why.isEmpty() && !lost.check.isEmpty() && !lost.check.contains(u'%'));
        QCOMPARE(lost.at.count, uint64_t{1});
        QCOMPARE(lost.at.frames, (std::vector<uint64_t>{6}));  // the beat at 900 ms ends the gap
        QCOMPARE(lost.at.firstNs, 900 * kMs);
        for (const HealthRule& rule : healthRules()) QVERIFY2(rule.what && rule.why && rule.check, rule.id);
    }

    void emcyListAndResets() {
        Feed f;
        f.at(1500, 0x081, {0x10, 0x23, 0x02, 0, 0, 0, 0, 0});  // 2310h, current error (bit 1)
        f.at(2500, 0x081, {0x00, 0x00, 0x00, 0, 0, 0, 0, 0});  // error reset
        const HealthReport r = f.report();
        const NodeHealth* n = nodeOf(r, 1);
        QVERIFY(n);
        QCOMPARE(n->emcys, 2u);
        QCOMPARE(n->emcyResets, 1u);
        QCOMPARE(n->emcyList.size(), size_t(2));
        QCOMPARE(n->emcyList[0].code, 0x2310);
        QCOMPARE(n->emcyList[0].reg, 0x02);
        QVERIFY(!n->emcyList[0].text.isEmpty());
        QVERIFY(n->emcyList[1].reset);
        // Relative timestamps: the time is given from the start of the trace.
        QVERIFY2(hasFinding(r, QStringLiteral("EMCY 2310h")) && hasFinding(r, QStringLiteral("from node 1 at 0.000 s")),
                 qPrintable(findings(r)));
    }

    void pdoRateJitterSyncAndConsumers() {
        Feed f;
        for (int i = 0; i < 100; ++i) {
            if (i != 50 && i != 51) f.at(i * 10.0, 0x080, {});  // SYNC every 10 ms, 2 missing
            f.at(i * 10.0 + 1, 0x181, {1, 2, 3, 4});            // TPDO1 of node 1
            f.at(i * 10.0 + 2, 0x205, {0, 0});                  // RPDO1 to node 5, which never speaks
        }
        const HealthReport r = f.report();
        QCOMPARE(r.bus.syncs, 98u);
        QVERIFY(qAbs(r.bus.syncPeriodMs - 10.0) < 0.01);
        QCOMPARE(r.bus.syncMissing, 2u);
        QCOMPARE(r.pdos.size(), size_t(2));
        const PdoHealth& t = r.pdos[0];
        QCOMPARE(t.cobId, 0x181u);
        QCOMPARE(t.service, QStringLiteral("TPDO1"));
        QCOMPARE(t.frames, 100u);
        QVERIFY(qAbs(t.rateHz - 100.0) < 1e-6);
        QVERIFY(qAbs(t.periodAvgMs - 10.0) < 1e-6);
        QVERIFY(t.jitterMs < 1e-3);
        QVERIFY(t.consumerSeen);
        QCOMPARE(r.pdos[1].service, QStringLiteral("RPDO1"));
        QVERIFY(!r.pdos[1].consumerSeen);
        QVERIFY2(hasFinding(r, QStringLiteral("2 SYNC cycles missing")), qPrintable(findings(r)));
        QVERIFY2(hasFinding(r, QStringLiteral("sent to node 5, which never answers")), qPrintable(findings(r)));
    }

    // Jitter is a cyclic PDO's (issue 37): a PDO sent on events, at irregular times, has no
    // period to jitter around, so no "every 35.9 s jitters by 104.3 s" finding; a cyclic one
    // whose period wanders by more than 20 % gets one.
    void pdoJitterOnlyForCyclicPdos() {
        Feed f;
        // TPDO1 of node 2 on events: 12 sends at irregular times over 7 minutes.
        double t = 0;
        for (double gap :
             {1000.0, 90000.0, 300.0, 35000.0, 120000.0, 5000.0, 800.0, 60000.0, 2000.0, 100000.0, 40.0, 15000.0}) {
            t += gap;
            f.at(t, 0x182, {1, 2});
        }
        // TPDO1 of node 3 cyclic at 10 ms, every tenth interval 30 ms (a stall): 90 % on the
        // period, standard deviation 6 ms of a 12 ms mean.
        double c = 0;
        for (int i = 0; i < 50; ++i) f.at(c += (i % 10 == 9 ? 30.0 : 10.0), 0x183, {1});
        const HealthReport r = f.report();
        QCOMPARE(r.pdos.size(), size_t(2));
        QVERIFY(!r.pdos[0].cyclic);
        QVERIFY(r.pdos[1].cyclic);
        QVERIFY2(!hasFinding(r, QStringLiteral("of node 2 (182h) every")), qPrintable(findings(r)));
        QVERIFY2(hasFinding(r, QStringLiteral("TPDO1 of node 3 (183h) every")), qPrintable(findings(r)));
        const QList<QByteArray> lines = healthText(r, false).split('\n');
        const auto line =
            std::find_if(lines.begin(), lines.end(), [](const QByteArray& l) { return l.contains("0x182"); });
        QVERIFY(line != lines.end());
        QVERIFY2(line->contains("event"), line->constData());
    }

    void busLoadErrorsAndOtherFrames() {
        Feed f;
        // 100 classic 8-byte frames in the first second: (34 + 64) x 1.1 + 13 bits each.
        for (int i = 0; i < 100; ++i) f.at(i * 10.0, 0x181, {1, 2, 3, 4, 5, 6, 7, 8});
        f.at(1500, 0x181, {1, 2, 3, 4, 5, 6, 7, 8});
        f.at(1600, 0x20000004, {0}, CanFrame::Error);
        f.at(1700, 0x18FF0001, {1, 2}, CanFrame::Extended);  // J1939-style: not CANopen
        f.at(1999, 0x181, {1, 2, 3, 4, 5, 6, 7, 8});
        const HealthReport r = f.report();
        const double bits = (34.0 + 64.0) * 1.1 + 13.0;
        QCOMPARE(r.bus.perSecondPct.size(), size_t(2));
        QVERIFY(qAbs(r.bus.perSecondPct[0] - 100 * bits * 100 / 500000) < 1e-9);
        QVERIFY(qAbs(r.bus.loadPeakPct - r.bus.perSecondPct[0]) < 1e-12);
        QCOMPARE(r.bus.errorFrames, 1u);
        QCOMPARE(r.bus.nonCanopen, 1u);
        QVERIFY2(hasFinding(r, QStringLiteral("1 CAN error frame")), qPrintable(findings(r)));
    }

    void loadOverTimeHasAtMost60Buckets() {
        Feed f;
        for (int s = 0; s < 200; ++s) f.at(s * 1000.0, 0x181, {1});
        const HealthReport r = f.report();
        QCOMPARE(r.bus.perSecondPct.size(), size_t(200));
        QCOMPARE(r.bus.loadOverTime.size(), size_t(50));  // 4 s each
        QCOMPARE(r.bus.loadOverTime[1].startS, 4.0);
        QCOMPARE(loadSparkline(r).size(), 50);
    }

    // Issue 37 item 7: the load chart scales to its data. 100 1-byte frames a second at 500 kbit/s
    // is about 1.2 % load: the HTML chart's top line is 2 %, not 100 %.
    void loadChartScalesToItsData() {
        QCOMPARE(loadScaleTopPct(0.0), 1.0);
        QCOMPARE(loadScaleTopPct(1.2), 2.0);
        QCOMPARE(loadScaleTopPct(3.0), 5.0);
        QCOMPARE(loadScaleTopPct(47.0), 50.0);
        QCOMPARE(loadScaleTopPct(48.0), 75.0);  // the 5 % margin: 50.4 > 50
        QCOMPARE(loadScaleTopPct(80.0), 100.0);
        QCOMPARE(loadScaleTopPct(130.0), 100.0);
        Feed f;
        for (int i = 0; i < 300; ++i) f.at(i * 10.0, 0x181, {1});
        const HealthReport r = f.report();
        QVERIFY2(r.bus.loadPeakPct > 1.0 && r.bus.loadPeakPct < 1.9, qPrintable(QString::number(r.bus.loadPeakPct)));
        const QString html = QString::fromUtf8(healthHtml(r, QStringLiteral("t")));
        QVERIFY2(html.contains(QStringLiteral(">2 %</text>")) && html.contains(QStringLiteral(">0.5 %</text>")),
                 qPrintable(html));
        QVERIFY(!html.contains(QStringLiteral(">100 %</text>")));
    }

    void jsonCarriesEveryPart() {
        Feed f;
        for (double t : {0.0, 100.0, 200.0, 450.0}) f.at(t, 0x705, {0x05});
        f.at(300, 0x085, {0x10, 0x23, 0x02, 0, 0, 0, 0, 0});
        const QJsonObject o = healthJson(f.report());
        QVERIFY(o[QStringLiteral("findings")].isArray());
        const QJsonObject n = o[QStringLiteral("nodes")].toArray().at(0).toObject();
        QCOMPARE(n[QStringLiteral("node")].toInt(), 5);
        QCOMPARE(n[QStringLiteral("heartbeat")].toObject()[QStringLiteral("late")].toInt(), 1);
        QCOMPARE(n[QStringLiteral("heartbeat")].toObject()[QStringLiteral("period_ms")].toDouble(), 100.0);
        QCOMPARE(n[QStringLiteral("emcy")]
                     .toObject()[QStringLiteral("list")]
                     .toArray()
                     .at(0)
                     .toObject()[QStringLiteral("code")]
                     .toInt(),
                 0x2310);
        QVERIFY(n[QStringLiteral("sdo")].toObject().contains(QStringLiteral("response_p99_ms")));
        QVERIFY(n[QStringLiteral("nmt")].toObject().contains(QStringLiteral("resets")));
        QVERIFY(o[QStringLiteral("pdos")].isArray());
        const QJsonObject bus = o[QStringLiteral("bus")].toObject();
        for (const char* k : {"load_avg_pct", "load_peak_pct", "load_over_time", "error_frames", "non_canopen_frames",
                              "sync", "rpdos_no_producer"})
            QVERIFY2(bus.contains(QLatin1String(k)), k);
    }
};

QTEST_GUILESS_MAIN(NetworkHealthTest)
#include "test_network_health.moc"
