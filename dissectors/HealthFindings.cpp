// SPDX-License-Identifier: GPL-3.0-or-later
// The findings of a network health report: what a reviewer should look at first, in plain words.
#include "dissectors/NetworkHealth.h"

#include "core/canopen/Nmt.h"

#include <QDateTime>

#include <algorithm>

namespace coscope::dissect {

QString severityName(int severity) {
    switch (severity) {
    case HealthFinding::Critical: return QStringLiteral("critical");
    case HealthFinding::Error: return QStringLiteral("error");
    case HealthFinding::Warning: return QStringLiteral("warning");
    default: return QStringLiteral("info");
    }
}

QString healthTime(int64_t ns, int64_t startNs) {
    // Timestamps after 2000-01-01 are wall-clock time (live captures, most logs).
    if (ns > 946684800LL * 1000000000LL) return QDateTime::fromMSecsSinceEpoch(ns / 1000000).toString(QStringLiteral("HH:mm:ss"));
    return QStringLiteral("%1 s").arg(static_cast<double>(ns - startNs) / 1e9, 0, 'f', 3);
}

namespace {
QString ms(double v) {
    if (v >= 10000) return QString::number(v / 1000, 'f', 1) + QStringLiteral(" s");
    return QString::number(v, 'f', v < 10 ? 1 : 0) + QStringLiteral(" ms");
}
QString hx(uint32_t v, int width) { return QStringLiteral("%1h").arg(v, width, 16, QLatin1Char('0')).toUpper().replace(u'H', u'h'); }
QString times(uint64_t n) { return n == 1 ? QStringLiteral("once") : QStringLiteral("%1 times").arg(n); }
// Thresholds for what is worth a line (not CiA figures: what commissioning engineers flag).
constexpr double kSlowSdoP99Ms = 50;
constexpr double kLoadPeakPct = 70, kLoadAvgPct = 50;
constexpr double kJitterShare = 0.2;  // jitter over 20 % of the period
}  // namespace

std::vector<HealthFinding> healthFindings(const HealthReport& r) {
    std::vector<HealthFinding> out;
    auto add = [&](int sev, const char* kind, int node, QString text, int64_t t = 0, bool hasTime = false) {
        out.push_back({sev, QString::fromLatin1(kind), node, t, hasTime, std::move(text)});
    };
    const bool severalBuses = std::any_of(r.nodes.begin(), r.nodes.end(), [](const NodeHealth& n) { return n.bus != 0; });
    for (const NodeHealth& n : r.nodes) {
        const QString who = severalBuses ? QStringLiteral("node %1 (bus %2)").arg(n.node).arg(n.bus) : QStringLiteral("node %1").arg(n.node);
        if (n.resets) add(HealthFinding::Critical, "reset", n.node, QStringLiteral("%1 rebooted %2 (boot-up without an NMT reset)").arg(who, times(n.resets)));
        if (n.silentNow)
            add(HealthFinding::Critical, "heartbeat_stopped", n.node,
                QStringLiteral("%1 %2 stopped: nothing for %3 (period %4)%5")
                    .arg(who, n.errorControl, ms(n.silentForMs), ms(n.expectedPeriodMs), n.heartbeatDisabled ? QStringLiteral(", 1017h was set to 0") : QString()),
                r.endNs - static_cast<int64_t>(n.silentForMs * 1e6), true);
        const uint64_t pastTimeouts = n.timeouts - (n.silentNow ? 1 : 0);
        if (pastTimeouts)
            add(HealthFinding::Error, "heartbeat_timeout", n.node,
                QStringLiteral("%1 %2 lost %3 (longest gap %4, period %5)").arg(who, n.errorControl, times(pastTimeouts), ms(n.longestGapMs), ms(n.expectedPeriodMs)));
        for (size_t i = 0, shown = 0; i < n.emcyList.size(); ++i) {
            const EmcyEntry& e = n.emcyList[i];
            if (e.reset) continue;
            if (++shown > 3) {
                add(HealthFinding::Error, "emcy", n.node, QStringLiteral("%1 more EMCY from %2").arg(n.emcys - n.emcyResets - 3).arg(who));
                break;
            }
            QString text = QStringLiteral("EMCY %1 %2").arg(hx(e.code, 4), e.text.toLower());
            if (!e.vendor.isEmpty()) text += QStringLiteral(" (%1)").arg(e.vendor);
            add(HealthFinding::Error, "emcy", n.node, QStringLiteral("%1 from %2 at %3").arg(text, who, healthTime(e.timeNs, r.startNs)), e.timeNs, true);
        }
        if (n.sdoTimeouts) add(HealthFinding::Error, "sdo_timeout", n.node, QStringLiteral("%1 left %2 SDO request%3 unanswered").arg(who).arg(n.sdoTimeouts).arg(n.sdoTimeouts == 1 ? "" : "s"));
        for (const AbortCount& a : n.sdoAborts)
            add(HealthFinding::Warning, "sdo_abort", n.node,
                QStringLiteral("%1 aborted SDO %2 with %3 %4").arg(who, times(a.count), hx(a.code, 8), a.text));
        if (n.sdoResponses && n.sdoRtP99Ms > kSlowSdoP99Ms)
            add(HealthFinding::Warning, "sdo_slow", n.node, QStringLiteral("%1 answered SDO in %2 p99 (max %3)").arg(who, ms(n.sdoRtP99Ms), ms(n.sdoRtMaxMs)));
        if (n.late)
            add(HealthFinding::Warning, "heartbeat_late", n.node,
                QStringLiteral("%1 %2 late %3 (over 1.5x the %4 period)").arg(who, n.errorControl, times(n.late), ms(n.expectedPeriodMs)));
    }
    const BusHealth& b = r.bus;
    if (b.errorFrames) add(HealthFinding::Error, "error_frames", -1, QStringLiteral("%1 CAN error frame%2").arg(b.errorFrames).arg(b.errorFrames == 1 ? "" : "s"));
    if (b.syncMissing)
        add(HealthFinding::Warning, "sync_missing", -1, QStringLiteral("%1 SYNC cycle%2 missing (period %3)").arg(b.syncMissing).arg(b.syncMissing == 1 ? "" : "s").arg(ms(b.syncPeriodMs)));
    if (b.loadPeakPct > kLoadPeakPct || b.loadAvgPct > kLoadAvgPct)
        add(HealthFinding::Warning, "bus_load", -1,
            QStringLiteral("bus load peaks at %1 % (average %2 %) at %3 bit/s").arg(b.loadPeakPct, 0, 'f', 1).arg(b.loadAvgPct, 0, 'f', 1).arg(b.bitRate));
    for (const PdoHealth& p : r.pdos) {
        if (!p.consumerSeen)
            add(HealthFinding::Warning, "rpdo_no_consumer", p.node, QStringLiteral("%1 (%2) sent to node %3, which never answers").arg(p.service, hx(p.cobId, 3)).arg(p.node));
        if (p.cyclic && p.frames > 10 && p.periodAvgMs > 0 && p.jitterMs > kJitterShare * p.periodAvgMs)
            add(HealthFinding::Info, "pdo_jitter", p.node,
                QStringLiteral("%1 of node %2 (%3) every %4 jitters by %5").arg(p.service).arg(p.node).arg(hx(p.cobId, 3), ms(p.periodAvgMs), ms(p.jitterMs)));
    }
    for (const RpdoNoProducer& p : b.rpdosNoProducer)
        add(HealthFinding::Info, "rpdo_no_producer", p.node, QStringLiteral("RPDO%1 of node %2 (%3) is valid but nobody sends it").arg(p.number).arg(p.node).arg(hx(p.cobId, 3)));
    if (!b.silentAddressed.empty())
        add(HealthFinding::Info, "silent_addressed", -1,
            QStringLiteral("%1 node-ID%2 (%3..%4) got an SDO request and never answered: a network scan, or devices missing")
                .arg(b.silentAddressed.size()).arg(b.silentAddressed.size() == 1 ? "" : "s").arg(b.silentAddressed.front()).arg(b.silentAddressed.back()));
    if (b.nonCanopen) add(HealthFinding::Info, "non_canopen", -1, QStringLiteral("%1 frame%2 not CANopen").arg(b.nonCanopen).arg(b.nonCanopen == 1 ? " is" : "s are"));
    std::stable_sort(out.begin(), out.end(), [](const HealthFinding& a, const HealthFinding& c) { return a.severity > c.severity; });
    return out;
}

}  // namespace coscope::dissect
