// SPDX-License-Identifier: GPL-3.0-or-later
// The network health report as text (`coscope-cli stats`): findings, per-node tables, PDOs, bus.
#include "dissectors/HealthOutput.h"
#include "dissectors/NetworkHealth.h"

#include "core/canopen/Nmt.h"

#include <QSet>

#include <algorithm>
#include <cstdio>

namespace coscope::dissect {

QString loadSparkline(const HealthReport& r) {
    static const char16_t bars[] = u"▁▂▃▄▅▆▇█";
    QString s;
    for (const LoadBucket& b : r.bus.loadOverTime)
        s += QChar(bars[std::clamp(static_cast<int>(b.avgPct / 100.0 * 8.0), 0, 7)]);
    return s;
}

namespace {
struct Out {
    QByteArray o;
    char line[512];
    template <typename... A>
    void put(const char* fmt, A... args) {
        const int n = std::snprintf(line, sizeof line, fmt, args...);
        o.append(line, std::min<int>(n, sizeof line - 1));
    }
};
QByteArray c(const QString& s) { return s.isEmpty() ? QByteArray("-") : s.toUtf8(); }
unsigned long long u(uint64_t v) { return static_cast<unsigned long long>(v); }
QByteArray state(int s) { return s < 0 ? QByteArray("-") : canopen::nmtStateName(static_cast<uint8_t>(s)).toUtf8(); }
}  // namespace

QString healthFrames(const Occurrences& at, int shown) {
    if (at.frames.empty()) return {};
    QStringList l;
    for (size_t i = 0; i < std::min<size_t>(at.frames.size(), static_cast<size_t>(shown)); ++i)
        l << QString::number(at.frames[i] + 1);
    const uint64_t more = at.count - std::min<uint64_t>(at.count, static_cast<uint64_t>(l.size()));
    QString s = QStringLiteral("%1 %2").arg(at.count == 1 ? QStringLiteral("frame") : QStringLiteral("frames"),
                                            l.join(QStringLiteral(", ")));
    if (more) s += QStringLiteral(", … (+%1)").arg(more);
    return s;
}

QString healthWhere(const HealthFinding& f, int64_t startNs) {
    const Occurrences& at = f.at;
    if (!at.count) return {};
    QString s = at.count == 1 ? QStringLiteral("once, at %1").arg(healthTime(at.firstNs, startNs))
                              : QStringLiteral("%1 times, %2 .. %3")
                                    .arg(at.count)
                                    .arg(healthTime(at.firstNs, startNs), healthTime(at.lastNs, startNs));
    const QString frames = healthFrames(at, 5);
    if (!frames.isEmpty()) s += QStringLiteral("; ") + frames;
    return s;
}

QByteArray healthText(const HealthReport& r, bool perSecond) {
    Out o;
    // The verdict first (issue 37), then the findings with where they are, then each node's story.
    o.put("%s\n", r.verdict.toUtf8().constData());
    QSet<QString> explained;
    auto finding = [&](const HealthFinding& f) {
        o.put("  [%s] %s%s %s\n", qPrintable(severityName(f.severity)), qPrintable(f.rule),
              f.node >= 0 ? qPrintable(QStringLiteral(", node %1:").arg(f.node)) : ":", f.what.toUtf8().constData());
        const QString where = healthWhere(f, r.startNs);
        if (!where.isEmpty()) o.put("      %s\n", where.toUtf8().constData());
        // Why and what to check once per rule: the same words for every node.
        if (!explained.contains(f.rule))
            o.put("      Why: %s Check: %s\n", f.why.toUtf8().constData(), f.check.toUtf8().constData());
        explained << f.rule;
    };
    o.o.append("\nFindings:\n");
    bool any = false, anyOwn = false;
    for (const HealthFinding& f : r.findings) {
        if (f.own) {
            anyOwn = true;
            continue;
        }
        any = true;
        finding(f);
    }
    if (!any) o.o.append("  no problems found\n");
    if (anyOwn) {
        o.o.append("\nCoScope's own traffic (info, not counted in the verdict):\n");
        for (const HealthFinding& f : r.findings)
            if (f.own) finding(f);
    }

    o.o.append("\nNodes (only those seen):\n");
    if (r.nodes.empty()) o.o.append("  (none)\n");
    for (const NodeHealth& n : r.nodes) {
        QStringList facts;
        if (!n.errorControl.isEmpty())
            facts << QStringLiteral("%1 %2 ms").arg(n.errorControl).arg(n.expectedPeriodMs, 0, 'f', 0);
        if (n.state >= 0) facts << canopen::nmtStateName(static_cast<uint8_t>(n.state));
        o.put("  node %d: %s%s%s\n", n.node, qPrintable(facts.join(QStringLiteral(", "))), facts.isEmpty() ? "" : "; ",
              qPrintable(n.outcome));
        // At most 8 lines: all, or the first 4, how many left out, the last 3.
        const size_t all = n.story.size();
        const size_t head = all <= 8 ? all : 4, tail = all <= 8 ? 0 : 3;
        auto line = [&](const StoryEntry& e) {
            o.put("    %12s  #%-7llu %s\n", qPrintable(healthTime(e.timeNs, r.startNs)), u(e.frame + 1),
                  e.text.toUtf8().constData());
        };
        for (size_t i = 0; i < head; ++i) line(n.story[i]);
        const uint64_t leftOut = all - head - tail + n.storyMore;
        if (leftOut) o.put("    %12s  … %llu more\n", "", u(leftOut));
        for (size_t i = all - tail; i < all; ++i) line(n.story[i]);
    }

    o.o.append("\nHeartbeat / guarding and NMT per node:\n");
    o.put("  %-5s %-16s %-9s %7s %24s %10s %5s %8s %8s %6s %5s\n", "node", "state", "kind", "beats",
          "period min/avg/max ms", "expected", "late", "timeouts", "boot-ups", "resets", "NMT");
    for (const NodeHealth& n : r.nodes) {
        char period[64] = "-";
        if (n.beats > 1)
            std::snprintf(period, sizeof period, "%.1f/%.1f/%.1f", n.periodMinMs, n.periodAvgMs, n.periodMaxMs);
        char expected[48] = "-";
        if (n.expectedPeriodMs > 0)
            std::snprintf(expected, sizeof expected, "%.0f %s", n.expectedPeriodMs,
                          n.periodSource == QLatin1String("1017h") ? "1017h" : "obs");
        o.put("  %-5d %-16s %-9s %7llu %24s %10s %5llu %8llu %8llu %6llu %5llu\n", n.node, state(n.state).constData(),
              c(n.errorControl).constData(), u(n.beats), period, expected, u(n.late), u(n.timeouts), u(n.bootUps),
              u(n.resets), u(n.nmtCommands));
    }

    o.o.append("\nSDO per node:\n");
    o.put("  %-5s %9s %6s %7s %6s %8s %8s %30s\n", "node", "transfers", "ok", "aborted", "failed", "requests",
          "timeouts", "response min/avg/p99/max ms");
    for (const NodeHealth& n : r.nodes) {
        if (!n.sdoRequests && !n.sdoTransfers) continue;
        char rt[80] = "-";
        if (n.sdoResponses)
            std::snprintf(rt, sizeof rt, "%.2f/%.2f/%.2f/%.2f", n.sdoRtMinMs, n.sdoRtAvgMs, n.sdoRtP99Ms, n.sdoRtMaxMs);
        o.put("  %-5d %9llu %6llu %7llu %6llu %8llu %8llu %30s\n", n.node, u(n.sdoTransfers), u(n.sdoOk),
              u(n.sdoAborted), u(n.sdoFailed), u(n.sdoRequests), u(n.sdoTimeouts), rt);
    }

    o.o.append("\nPDOs per COB-ID:\n");
    o.put("  %-7s %-6s %-5s %9s %9s %24s %10s\n", "COB-ID", "PDO", "node", "frames", "rate Hz", "period min/avg/max ms",
          "jitter ms");
    for (const PdoHealth& p : r.pdos) {
        char period[64] = "-";
        if (p.frames > 1)
            std::snprintf(period, sizeof period, "%.2f/%.2f/%.2f", p.periodMinMs, p.periodAvgMs, p.periodMaxMs);
        char jitter[32] = "event";  // no cycle: the intervals are the events'
        if (p.cyclic) std::snprintf(jitter, sizeof jitter, "%.3f", p.jitterMs);
        o.put("  0x%03X   %-6s %-5d %9llu %9.1f %24s %10s%s\n", p.cobId, qPrintable(p.service), p.node, u(p.frames),
              p.rateHz, period, jitter, p.consumerSeen ? "" : "  (consumer never seen)");
    }
    if (r.pdos.empty()) o.o.append("  (none)\n");
    const BusHealth& b = r.bus;
    for (const RpdoNoProducer& p : b.rpdosNoProducer)
        o.put("  RPDO%d of node %d (0x%03X): valid, no producer\n", p.number, p.node, p.cobId);

    o.put("\nBus (%d bit/s, estimated):\n", b.bitRate);
    o.put("  frames %llu over %.1f s, error frames %llu, not CANopen %llu\n", u(b.frames), b.durationS,
          u(b.errorFrames), u(b.nonCanopen));
    o.put("  load average %.1f %%, peak %.1f %% at %.0f s\n", b.loadAvgPct, b.loadPeakPct, b.peakAtS);
    if (!b.silentAddressed.empty())
        o.put("  %zu node-IDs addressed by SDO never answered (%d..%d)\n", b.silentAddressed.size(),
              b.silentAddressed.front(), b.silentAddressed.back());
    if (!b.ownSilentAddressed.empty())
        o.put("  %zu node-IDs CoScope's scan asked never answered (%d..%d)\n", b.ownSilentAddressed.size(),
              b.ownSilentAddressed.front(), b.ownSilentAddressed.back());
    if (b.syncs)
        o.put("  SYNC %llu, period %.3f ms (%s), missing cycles %llu\n", u(b.syncs), b.syncPeriodMs,
              c(b.syncPeriodSource).constData(), u(b.syncMissing));
    if (!b.loadOverTime.empty()) {
        o.put("  load over time (%zu buckets of %.0f s, 0..100 %%): %s\n", b.loadOverTime.size(),
              b.loadOverTime.front().seconds, loadSparkline(r).toUtf8().constData());
    }
    if (perSecond) {
        o.o.append("\nBus load per second:\n");
        for (size_t i = 0; i < b.perSecondPct.size(); ++i) o.put("  second %6zu  %5.1f %%\n", i, b.perSecondPct[i]);
    }
    return o.o;
}

}  // namespace coscope::dissect
