// SPDX-License-Identifier: GPL-3.0-or-later
// The network health report as text (`coscope-cli stats`): findings, per-node tables, PDOs, bus.
#include "dissectors/HealthOutput.h"
#include "dissectors/NetworkHealth.h"

#include "core/canopen/Nmt.h"

#include <algorithm>
#include <cstdio>

namespace coscope::dissect {

QString loadSparkline(const HealthReport& r) {
    static const char16_t bars[] = u"▁▂▃▄▅▆▇█";
    QString s;
    for (const LoadBucket& b : r.bus.loadOverTime) s += QChar(bars[std::clamp(static_cast<int>(b.avgPct / 100.0 * 8.0), 0, 7)]);
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

QByteArray healthText(const HealthReport& r, bool perSecond) {
    Out o;
    o.o.append("Findings:\n");
    if (r.findings.empty()) o.o.append("  no problems found\n");
    for (const HealthFinding& f : r.findings) o.put("  [%s] %s\n", qPrintable(severityName(f.severity)), f.text.toUtf8().constData());

    o.o.append("\nHeartbeat / guarding and NMT per node:\n");
    o.put("  %-5s %-16s %-9s %7s %24s %10s %5s %8s %8s %6s %5s\n", "node", "state", "kind", "beats", "period min/avg/max ms", "expected", "late", "timeouts", "boot-ups", "resets", "NMT");
    for (const NodeHealth& n : r.nodes) {
        char period[64] = "-";
        if (n.beats > 1) std::snprintf(period, sizeof period, "%.1f/%.1f/%.1f", n.periodMinMs, n.periodAvgMs, n.periodMaxMs);
        char expected[48] = "-";
        if (n.expectedPeriodMs > 0) std::snprintf(expected, sizeof expected, "%.0f %s", n.expectedPeriodMs, n.periodSource == QLatin1String("1017h") ? "1017h" : "obs");
        o.put("  %-5d %-16s %-9s %7llu %24s %10s %5llu %8llu %8llu %6llu %5llu\n", n.node, state(n.state).constData(), c(n.errorControl).constData(), u(n.beats), period, expected,
              u(n.late), u(n.timeouts), u(n.bootUps), u(n.resets), u(n.nmtCommands));
    }
    bool anyChange = false;
    for (const NodeHealth& n : r.nodes) {
        const size_t shown = std::min<size_t>(n.nmtChanges.size(), 10);
        for (size_t i = 0; i < shown; ++i) {
            if (!anyChange) o.o.append("\nNMT state changes (first 10 per node):\n");
            anyChange = true;
            const NmtChange& ch = n.nmtChanges[i];
            o.put("  node %-3d %12s  %s -> %s  (%s)\n", n.node, qPrintable(healthTime(ch.timeNs, r.startNs)), state(ch.from).constData(), state(ch.to).constData(), qPrintable(ch.cause));
        }
    }

    o.o.append("\nSDO per node:\n");
    o.put("  %-5s %9s %6s %7s %6s %8s %8s %30s\n", "node", "transfers", "ok", "aborted", "failed", "requests", "timeouts", "response min/avg/p99/max ms");
    for (const NodeHealth& n : r.nodes) {
        if (!n.sdoRequests && !n.sdoTransfers) continue;
        char rt[80] = "-";
        if (n.sdoResponses) std::snprintf(rt, sizeof rt, "%.2f/%.2f/%.2f/%.2f", n.sdoRtMinMs, n.sdoRtAvgMs, n.sdoRtP99Ms, n.sdoRtMaxMs);
        o.put("  %-5d %9llu %6llu %7llu %6llu %8llu %8llu %30s\n", n.node, u(n.sdoTransfers), u(n.sdoOk), u(n.sdoAborted), u(n.sdoFailed), u(n.sdoRequests), u(n.sdoTimeouts), rt);
        for (const AbortCount& a : n.sdoAborts) o.put("        abort 0x%08X x%llu  %s\n", a.code, u(a.count), qPrintable(a.text));
    }

    o.o.append("\nEMCY per node:\n");
    bool anyEmcy = false;
    for (const NodeHealth& n : r.nodes) {
        if (!n.emcys) continue;
        anyEmcy = true;
        o.put("  node %-3d %llu EMCY, %llu error resets\n", n.node, u(n.emcys), u(n.emcyResets));
        for (size_t i = 0; i < std::min<size_t>(n.emcyList.size(), 20); ++i) {
            const EmcyEntry& e = n.emcyList[i];
            o.put("    %12s  %04Xh reg %02Xh  %s%s%s\n", qPrintable(healthTime(e.timeNs, r.startNs)), e.code, e.reg, e.text.toUtf8().constData(),
                  e.vendor.isEmpty() ? "" : "  ", e.vendor.toUtf8().constData());
        }
    }
    if (!anyEmcy) o.o.append("  (none)\n");

    o.o.append("\nPDOs per COB-ID:\n");
    o.put("  %-7s %-6s %-5s %9s %9s %24s %10s\n", "COB-ID", "PDO", "node", "frames", "rate Hz", "period min/avg/max ms", "jitter ms");
    for (const PdoHealth& p : r.pdos) {
        char period[64] = "-";
        if (p.frames > 1) std::snprintf(period, sizeof period, "%.2f/%.2f/%.2f", p.periodMinMs, p.periodAvgMs, p.periodMaxMs);
        char jitter[32] = "event";  // no cycle: the intervals are the events'
        if (p.cyclic) std::snprintf(jitter, sizeof jitter, "%.3f", p.jitterMs);
        o.put("  0x%03X   %-6s %-5d %9llu %9.1f %24s %10s%s\n", p.cobId, qPrintable(p.service), p.node, u(p.frames), p.rateHz, period, jitter,
              p.consumerSeen ? "" : "  (consumer never seen)");
    }
    if (r.pdos.empty()) o.o.append("  (none)\n");
    const BusHealth& b = r.bus;
    for (const RpdoNoProducer& p : b.rpdosNoProducer) o.put("  RPDO%d of node %d (0x%03X): valid, no producer\n", p.number, p.node, p.cobId);

    o.put("\nBus (%d bit/s, estimated):\n", b.bitRate);
    o.put("  frames %llu over %.1f s, error frames %llu, not CANopen %llu\n", u(b.frames), b.durationS, u(b.errorFrames), u(b.nonCanopen));
    o.put("  load average %.1f %%, peak %.1f %% at %.0f s\n", b.loadAvgPct, b.loadPeakPct, b.peakAtS);
    if (!b.silentAddressed.empty())
        o.put("  %zu node-IDs addressed by SDO never answered (%d..%d)\n", b.silentAddressed.size(), b.silentAddressed.front(), b.silentAddressed.back());
    if (b.syncs) o.put("  SYNC %llu, period %.3f ms (%s), missing cycles %llu\n", u(b.syncs), b.syncPeriodMs, c(b.syncPeriodSource).constData(), u(b.syncMissing));
    if (!b.loadOverTime.empty()) {
        o.put("  load over time (%zu buckets of %.0f s, 0..100 %%): %s\n", b.loadOverTime.size(), b.loadOverTime.front().seconds, loadSparkline(r).toUtf8().constData());
        o.o.append("  from s     avg %    peak %\n");
        for (const LoadBucket& l : b.loadOverTime) o.put("  %6.0f   %6.1f   %6.1f\n", l.startS, l.avgPct, l.peakPct);
    }
    if (perSecond) {
        o.o.append("\nBus load per second:\n");
        for (size_t i = 0; i < b.perSecondPct.size(); ++i) o.put("  second %6zu  %5.1f %%\n", i, b.perSecondPct[i]);
    }
    return o.o;
}

}  // namespace coscope::dissect
