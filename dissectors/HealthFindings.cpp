// SPDX-License-Identifier: GPL-3.0-or-later
// The findings of a network health report: what a reviewer should look at first, in plain words.
#include "dissectors/NetworkHealth.h"

#include "core/canopen/Nmt.h"
#include "dissectors/HealthRules.h"

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
    if (ns > 946684800LL * 1000000000LL)
        return QDateTime::fromMSecsSinceEpoch(ns / 1000000).toString(QStringLiteral("HH:mm:ss"));
    return QStringLiteral("%1 s").arg(static_cast<double>(ns - startNs) / 1e9, 0, 'f', 3);
}

namespace {
QString ms(double v) {
    if (v >= 10000) return QString::number(v / 1000, 'f', 1) + QStringLiteral(" s");
    return QString::number(v, 'f', v < 10 ? 1 : 0) + QStringLiteral(" ms");
}
QString hx(uint32_t v, int width) {
    return QStringLiteral("%1h").arg(v, width, 16, QLatin1Char('0')).toUpper().replace(u'H', u'h');
}
QString times(uint64_t n) { return n == 1 ? QStringLiteral("once") : QStringLiteral("%1 times").arg(n); }
// Thresholds for what is worth a line (not CiA figures: what commissioning engineers flag).
constexpr double kSlowSdoP99Ms = 50;
constexpr double kLoadPeakPct = 70, kLoadAvgPct = 50;
constexpr double kJitterShare = 0.2;  // jitter over 20 % of the period
}  // namespace

std::vector<HealthFinding> healthFindings(const HealthReport& r) {
    std::vector<HealthFinding> out;
    // One finding of `rule` (HealthRules.cpp): its sentences filled with `args`; `text` the
    // one-line headline the lists show.
    auto add = [&](const char* rule, int node, QString text, QStringList args, const Occurrences& at, bool own = false,
                   const char* kind = nullptr) {
        const HealthRule* hr = healthRule(QString::fromLatin1(rule));
        HealthFinding f;
        f.severity = own ? HealthFinding::Info : hr->severity;
        f.kind = QString::fromLatin1(kind ? kind : rule);
        f.node = node;
        f.hasTime = at.count > 0;
        f.timeNs = at.firstNs;
        f.text = std::move(text);
        f.rule = QString::fromLatin1(rule);
        f.what = fillRule(QString::fromUtf8(hr->what), args);
        f.why = fillRule(QString::fromUtf8(hr->why), args);
        f.check = fillRule(QString::fromUtf8(hr->check), args);
        f.args = std::move(args);
        f.at = at;
        f.own = own;
        out.push_back(std::move(f));
    };
    auto num = [](uint64_t v) { return QString::number(v); };
    const bool severalBuses =
        std::any_of(r.nodes.begin(), r.nodes.end(), [](const NodeHealth& n) { return n.bus != 0; });
    for (const NodeHealth& n : r.nodes) {
        const QString who = severalBuses ? QStringLiteral("node %1 (bus %2)").arg(n.node).arg(n.bus)
                                         : QStringLiteral("node %1").arg(n.node);
        const QString id = num(static_cast<uint64_t>(n.node));
        if (n.resets)
            add("nmt.reset", n.node,
                QStringLiteral("%1 rebooted %2 (boot-up without an NMT reset)").arg(who, times(n.resets)),
                {id, num(n.resets)}, n.resetAt, false, "reset");
        if (n.silentNow) {
            Occurrences last;
            last.add(n.lastBeatNs, n.lastBeatFrame);
            add("heartbeat.stopped", n.node,
                QStringLiteral("%1 %2 stopped: nothing for %3 (period %4)%5")
                    .arg(who, n.errorControl, ms(n.silentForMs), ms(n.expectedPeriodMs),
                         n.heartbeatDisabled ? QStringLiteral(", 1017h was set to 0") : QString()),
                {id, n.errorControl, ms(n.silentForMs), ms(n.expectedPeriodMs)}, last, false, "heartbeat_stopped");
        }
        const uint64_t pastTimeouts = n.timeouts - (n.silentNow ? 1 : 0);
        if (pastTimeouts)
            add("heartbeat.lost", n.node,
                QStringLiteral("%1 %2 lost %3 (longest gap %4, period %5)")
                    .arg(who, n.errorControl, times(pastTimeouts), ms(n.longestGapMs), ms(n.expectedPeriodMs)),
                {id, n.errorControl, num(pastTimeouts), ms(n.longestGapMs), ms(n.expectedPeriodMs)}, n.lostAt, false,
                "heartbeat_timeout");
        // EMCY per code: how often, when, with the vendor's alarm text where the dictionary has one.
        std::vector<std::pair<uint16_t, Occurrences>> codes;
        std::vector<QString> codeText, headline;
        for (const EmcyEntry& e : n.emcyList) {
            if (e.reset) continue;
            auto it = std::find_if(codes.begin(), codes.end(), [&](const auto& c) { return c.first == e.code; });
            if (it == codes.end()) {
                codes.push_back({e.code, {}});
                codeText.push_back(e.vendor.isEmpty() ? e.text : QStringLiteral("%1; %2").arg(e.text, e.vendor));
                headline.push_back(QStringLiteral("EMCY %1 %2").arg(hx(e.code, 4), e.text.toLower()) +
                                   (e.vendor.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(e.vendor)));
                it = codes.end() - 1;
            }
            it->second.add(e.timeNs, e.frame);
        }
        for (size_t i = 0; i < codes.size(); ++i) {
            const auto& [code, at] = codes[i];
            const QString c = hx(code, 4);
            add("emcy.fault", n.node,
                QStringLiteral("%1 from %2 at %3").arg(headline[i], who, healthTime(at.firstNs, r.startNs)),
                {id, c, codeText[i], num(at.count)}, at, false, "emcy");
        }
        const uint64_t otherTimeouts = n.sdoTimeouts - n.ownSdoTimeouts;
        if (otherTimeouts)
            add("sdo.timeout", n.node,
                QStringLiteral("%1 left %2 SDO request%3 unanswered")
                    .arg(who)
                    .arg(otherTimeouts)
                    .arg(otherTimeouts == 1 ? "" : "s"),
                {id, num(otherTimeouts)}, n.sdoTimeoutAt, false, "sdo_timeout");
        if (n.ownSdoTimeouts)
            add("coscope.sdo_timeout", n.node,
                QStringLiteral("%1 did not answer %2 SDO request%3 CoScope sent")
                    .arg(who)
                    .arg(n.ownSdoTimeouts)
                    .arg(n.ownSdoTimeouts == 1 ? "" : "s"),
                {id, num(n.ownSdoTimeouts)}, n.ownSdoTimeoutAt, true);
        for (const AbortCount& a : n.sdoAborts) {
            if (a.own)
                add("coscope.sdo_abort", n.node,
                    QStringLiteral("%1 aborted SDO CoScope sent %2 with %3 %4")
                        .arg(who, times(a.count), hx(a.code, 8), a.text),
                    {id, hx(a.code, 8), a.text, num(a.count)}, a.at, true);
            else
                add("sdo.abort", n.node,
                    QStringLiteral("%1 aborted SDO %2 with %3 %4").arg(who, times(a.count), hx(a.code, 8), a.text),
                    {id, hx(a.code, 8), a.text, num(a.count)}, a.at, false, "sdo_abort");
        }
        if (n.sdoResponses && n.sdoRtP99Ms > kSlowSdoP99Ms)
            add("sdo.slow", n.node,
                QStringLiteral("%1 answered SDO in %2 p99 (max %3)").arg(who, ms(n.sdoRtP99Ms), ms(n.sdoRtMaxMs)),
                {id, ms(n.sdoRtP99Ms), ms(n.sdoRtMaxMs)}, n.slowSdoAt, false, "sdo_slow");
        if (n.late)
            add("heartbeat.late", n.node,
                QStringLiteral("%1 %2 late %3 (over 1.5x the %4 period)")
                    .arg(who, n.errorControl, times(n.late), ms(n.expectedPeriodMs)),
                {id, n.errorControl, num(n.late), ms(n.expectedPeriodMs)}, n.lateAt, false, "heartbeat_late");
    }
    const BusHealth& b = r.bus;
    for (const BusHealth::Unanswered& u : b.unanswered)
        if (u.timeouts)
            add("sdo.timeout", u.node,
                QStringLiteral("node %1 left %2 SDO request%3 unanswered")
                    .arg(u.node)
                    .arg(u.timeouts)
                    .arg(u.timeouts == 1 ? "" : "s"),
                {QString::number(u.node), num(u.timeouts)}, u.at, false, "sdo_timeout");
    if (b.errorFrames)
        add("bus.error_frames", -1,
            QStringLiteral("%1 CAN error frame%2").arg(b.errorFrames).arg(b.errorFrames == 1 ? "" : "s"),
            {num(b.errorFrames)}, b.errorFrameAt, false, "error_frames");
    if (b.syncMissing)
        add("sync.missing", -1,
            QStringLiteral("%1 SYNC cycle%2 missing (period %3)")
                .arg(b.syncMissing)
                .arg(b.syncMissing == 1 ? "" : "s")
                .arg(ms(b.syncPeriodMs)),
            {num(b.syncMissing), ms(b.syncPeriodMs)}, b.syncMissingAt, false, "sync_missing");
    if (b.loadPeakPct > kLoadPeakPct || b.loadAvgPct > kLoadAvgPct) {
        Occurrences peak;  // a time, no frame
        peak.count = 1;
        peak.firstNs = peak.lastNs = r.startNs + static_cast<int64_t>(b.peakAtS * 1e9);
        add("bus.load", -1,
            QStringLiteral("bus load peaks at %1 % (average %2 %) at %3 bit/s")
                .arg(b.loadPeakPct, 0, 'f', 1)
                .arg(b.loadAvgPct, 0, 'f', 1)
                .arg(b.bitRate),
            {QString::number(b.loadPeakPct, 'f', 1), QString::number(b.loadAvgPct, 'f', 1), QString::number(b.bitRate)},
            peak, false, "bus_load");
    }
    for (const PdoHealth& p : r.pdos) {
        Occurrences first;
        first.add(p.firstNs, p.firstFrame);
        if (!p.consumerSeen)
            add("pdo.no_consumer", p.node,
                QStringLiteral("%1 (%2) sent to node %3, which never answers")
                    .arg(p.service, hx(p.cobId, 3))
                    .arg(p.node),
                {p.service, hx(p.cobId, 3), QString::number(p.node)}, first, false, "rpdo_no_consumer");
        if (p.cyclic && p.frames > 10 && p.periodAvgMs > 0 && p.jitterMs > kJitterShare * p.periodAvgMs)
            add("pdo.jitter", p.node,
                QStringLiteral("%1 of node %2 (%3) every %4 jitters by %5")
                    .arg(p.service)
                    .arg(p.node)
                    .arg(hx(p.cobId, 3), ms(p.periodAvgMs), ms(p.jitterMs)),
                {p.service, QString::number(p.node), hx(p.cobId, 3), ms(p.periodAvgMs), ms(p.jitterMs)}, p.irregularAt,
                false, "pdo_jitter");
    }
    for (const RpdoNoProducer& p : b.rpdosNoProducer)
        add("pdo.no_producer", p.node,
            QStringLiteral("RPDO%1 of node %2 (%3) is valid but nobody sends it")
                .arg(p.number)
                .arg(p.node)
                .arg(hx(p.cobId, 3)),
            {QString::number(p.number), QString::number(p.node), hx(p.cobId, 3)}, {}, false, "rpdo_no_producer");
    auto ids = [&](const std::vector<int>& v) {
        return QStringList{num(v.size()), QString::number(v.front()), QString::number(v.back())};
    };
    if (!b.silentAddressed.empty())
        add("sdo.silent_nodes", -1,
            QStringLiteral(
                "%1 node-ID%2 (%3..%4) got an SDO request and never answered: a network scan, or devices missing")
                .arg(b.silentAddressed.size())
                .arg(b.silentAddressed.size() == 1 ? "" : "s")
                .arg(b.silentAddressed.front())
                .arg(b.silentAddressed.back()),
            ids(b.silentAddressed), b.silentAt, false, "silent_addressed");
    if (!b.ownSilentAddressed.empty()) {
        const QStringList a = ids(b.ownSilentAddressed);
        add("coscope.scan", -1, fillRule(QString::fromUtf8(healthRule(QStringLiteral("coscope.scan"))->what), a), a,
            b.ownSilentAt, true);
    }
    if (b.nonCanopen)
        add("bus.not_canopen", -1,
            QStringLiteral("%1 frame%2 not CANopen").arg(b.nonCanopen).arg(b.nonCanopen == 1 ? " is" : "s are"),
            {num(b.nonCanopen)}, b.notCanopenAt, false, "non_canopen");
    // Worst first; CoScope's own traffic after everything else.
    std::stable_sort(out.begin(), out.end(), [](const HealthFinding& a, const HealthFinding& c) {
        return a.own != c.own ? c.own : a.severity > c.severity;
    });
    return out;
}

QString healthVerdict(const std::vector<HealthFinding>& findings) {
    uint64_t n[4] = {0, 0, 0, 0};
    for (const HealthFinding& f : findings)
        if (!f.own) ++n[std::clamp(f.severity, 0, 3)];
    if (!n[HealthFinding::Critical] && !n[HealthFinding::Error] && !n[HealthFinding::Warning])
        return QStringLiteral("No problems found");
    QStringList parts;
    auto part = [&](uint64_t c, const char* one, const char* many) {
        if (c) parts << QStringLiteral("%1 %2").arg(c).arg(QLatin1String(c == 1 ? one : many));
    };
    part(n[HealthFinding::Critical], "critical", "critical");
    part(n[HealthFinding::Error], "error", "errors");
    part(n[HealthFinding::Warning], "warning", "warnings");
    return QStringLiteral("Problems found: %1").arg(parts.join(QStringLiteral(", ")));
}

}  // namespace coscope::dissect
