// SPDX-License-Identifier: GPL-3.0-or-later
// The network health report as one self-contained HTML page: inline CSS, tables and an inline SVG
// of the bus load over time; nothing fetched, so it can be attached to a ticket.
#include "dissectors/HealthOutput.h"
#include "dissectors/NetworkHealth.h"

#include "core/canopen/Nmt.h"

#include <algorithm>

namespace coscope::dissect {

namespace {
QString esc(const QString& s) { return s.toHtmlEscaped(); }
QString svgNumber(double v, int decimals = 1) { return QString::number(v, 'f', decimals); }
QString st(int s) { return s < 0 ? QStringLiteral("-") : canopen::nmtStateName(static_cast<uint8_t>(s)); }
QString hexId(uint32_t v, int w) {
    return QStringLiteral("%1h").arg(v, w, 16, QLatin1Char('0')).toUpper().replace(u'H', u'h');
}

}  // namespace

double loadScaleTopPct(double peakPct) {
    for (double top : {1.0, 2.0, 5.0, 10.0, 20.0, 25.0, 50.0, 75.0})
        if (peakPct * 1.05 <= top) return top;
    return 100.0;
}

namespace {

// The load over time: one bar per second (or per bucket when long), peak line per bucket.
QString loadSvg(const BusHealth& b) {
    const int w = 720, h = 180, left = 40, bottom = 24, top = 8;
    const int plotW = w - left - 8, plotH = h - top - bottom;
    QString s = QStringLiteral(
                    "<svg xmlns='http://www.w3.org/2000/svg' width='%1' height='%2' viewBox='0 0 %1 %2' role='img' "
                    "aria-label='bus load over time'>")
                    .arg(w)
                    .arg(h);
    s += QStringLiteral("<rect x='%1' y='%2' width='%3' height='%4' fill='#fafafa' stroke='#ccc'/>")
             .arg(left)
             .arg(top)
             .arg(plotW)
             .arg(plotH);
    // Scaled to the data (issue 37 item 7): a 3 % load fills a 5 % chart, not the bottom line of 100 %.
    const double full = loadScaleTopPct(b.loadPeakPct);
    for (int q = 1; q <= 4; ++q) {
        const double pct = full * q / 4.0;
        const double y = top + plotH * (1.0 - pct / full);
        s += QStringLiteral(
                 "<line x1='%1' x2='%2' y1='%3' y2='%3' stroke='#e0e0e0'/><text x='%4' y='%5' font-size='10' "
                 "text-anchor='end' fill='#666'>%6 %</text>")
                 .arg(left)
                 .arg(left + plotW)
                 .arg(svgNumber(y))
                 .arg(left - 4)
                 .arg(svgNumber(y + 3))
                 .arg(QString::number(pct, 'g', 3));
    }
    const auto& buckets = b.loadOverTime;
    if (!buckets.empty()) {
        const double bw = static_cast<double>(plotW) / static_cast<double>(buckets.size());
        QString peak;
        for (size_t i = 0; i < buckets.size(); ++i) {
            const double avg = std::min(full, buckets[i].avgPct), pk = std::min(full, buckets[i].peakPct);
            const double x = left + bw * static_cast<double>(i);
            const double y = top + plotH * (1.0 - avg / full);
            s +=
                QStringLiteral(
                    "<rect x='%1' y='%2' width='%3' height='%4' fill='%5'><title>%6 s: %7 % (peak %8 %)</title></rect>")
                    .arg(svgNumber(x + 0.5))
                    .arg(svgNumber(y))
                    .arg(svgNumber(std::max(1.0, bw - 1.0)))
                    .arg(svgNumber(top + plotH - y))
                    .arg(avg > 70   ? QStringLiteral("#d9534f")
                         : avg > 50 ? QStringLiteral("#f0ad4e")
                                    : QStringLiteral("#4a90d9"))
                    .arg(svgNumber(buckets[i].startS, 0), svgNumber(avg), svgNumber(pk));
            peak += QStringLiteral("%1%2,%3 %4,%3")
                        .arg(i ? QStringLiteral(" ") : QString())
                        .arg(svgNumber(x))
                        .arg(svgNumber(top + plotH * (1.0 - pk / full)))
                        .arg(svgNumber(x + bw));
        }
        s += QStringLiteral("<polyline points='%1' fill='none' stroke='#333' stroke-width='1' stroke-dasharray='3,2'/>")
                 .arg(peak);
        const double endS = buckets.back().startS + buckets.back().seconds;
        s += QStringLiteral(
                 "<text x='%1' y='%2' font-size='10' fill='#666'>0 s</text><text x='%3' y='%2' font-size='10' "
                 "text-anchor='end' fill='#666'>%4 s</text>")
                 .arg(left)
                 .arg(h - 8)
                 .arg(left + plotW)
                 .arg(svgNumber(endS, 0));
    }
    s += QStringLiteral("</svg>");
    return s;
}

QString row(std::initializer_list<QString> cells) {
    QString s = QStringLiteral("<tr>");
    for (const QString& c : cells) s += QStringLiteral("<td>%1</td>").arg(c);
    return s + QStringLiteral("</tr>\n");
}
QString head(std::initializer_list<const char*> cells) {
    QString s = QStringLiteral("<tr>");
    for (const char* c : cells) s += QStringLiteral("<th>%1</th>").arg(QString::fromUtf8(c));
    return s + QStringLiteral("</tr>\n");
}
}  // namespace

QByteArray healthHtml(const HealthReport& r, const QString& title) {
    QString h;
    h += QStringLiteral("<!DOCTYPE html>\n<html lang='en'><head><meta charset='utf-8'><title>%1</title>\n<style>\n")
             .arg(esc(title));
    h += QStringLiteral(
        "body{font-family:system-ui,sans-serif;margin:24px;color:#222;max-width:1000px}h1{font-size:20px}h2{font-size:"
        "16px;margin-top:24px;border-bottom:1px solid #ddd}"
        "table{border-collapse:collapse;font-size:13px;margin:8px 0}td,th{border:1px solid #ddd;padding:3px "
        "8px;text-align:right}th{background:#f2f2f2}"
        "td:first-child,th:first-child{text-align:left}.f li{margin:3px "
        "0}.critical{color:#b00020;font-weight:bold}.error{color:#c0392b}.warning{color:#b8860b}.info{color:#555}"
        ".fr{font-family:monospace;color:#1a5fb4}.verdict{font-size:16px}h3{font-size:14px;margin:12px 0 "
        "4px}.story{font-size:13px}"
        ".sev{display:inline-block;width:70px;font-size:11px;text-transform:uppercase}.muted{color:#777;font-size:12px}"
        "\n</style></head><body>\n");
    const BusHealth& b = r.bus;
    h += QStringLiteral("<h1>%1</h1>\n<p class='muted'>%2 frames over %3 s at %4 bit/s</p>\n")
             .arg(esc(title))
             .arg(b.frames)
             .arg(svgNumber(b.durationS))
             .arg(b.bitRate);
    h += QStringLiteral("<p class='verdict'><b>%1</b></p>\n").arg(esc(r.verdict));
    // Each finding: what, why, what to check, and where, every frame number visible (the
    // trace's No.), so a reviewer finds them in CoScope or any tool that numbers frames.
    int shown = 0;  // findings written: each frame reference has its own id, f<finding>-<n>
    auto finding = [&](const HealthFinding& f) {
        QString frames;
        ++shown;
        for (size_t i = 0; i < f.at.frames.size() && i < 50; ++i)
            frames += QStringLiteral("%1<a class='fr' id='f%2-%3'>#%4</a>")
                          .arg(i ? QStringLiteral(", ") : QString())
                          .arg(shown)
                          .arg(i)
                          .arg(f.at.frames[i] + 1);
        if (f.at.count > std::min<uint64_t>(f.at.frames.size(), 50))
            frames += QStringLiteral(", … (+%1)").arg(f.at.count - std::min<uint64_t>(f.at.frames.size(), 50));
        QString when;
        if (f.at.count)
            when = f.at.count == 1 ? QStringLiteral("once, at %1").arg(healthTime(f.at.firstNs, r.startNs))
                                   : QStringLiteral("%1 times, %2 .. %3")
                                         .arg(f.at.count)
                                         .arg(healthTime(f.at.firstNs, r.startNs), healthTime(f.at.lastNs, r.startNs));
        h += QStringLiteral(
                 "<li class='%1'><span class='sev'>%1</span><b>%2</b>%3 %4<br><span class='muted'>%5%6</span><br>Why: "
                 "%7<br>Check: %8</li>\n")
                 .arg(severityName(f.severity), esc(f.rule),
                      f.node >= 0 ? QStringLiteral(", node %1:").arg(f.node) : QStringLiteral(":"), esc(f.what),
                      esc(when),
                      frames.isEmpty()
                          ? QString()
                          : (f.at.count == 1 ? QStringLiteral("; frame ") : QStringLiteral("; frames ")) + frames,
                      esc(f.why), esc(f.check));
    };
    h += QStringLiteral("<h2>Findings</h2>\n<ul class='f'>\n");
    bool any = false, anyOwn = false;
    for (const HealthFinding& f : r.findings) {
        (f.own ? anyOwn : any) = true;
        if (!f.own) finding(f);
    }
    if (!any) h += QStringLiteral("<li class='info'>No problems found</li>\n");
    h += QStringLiteral("</ul>\n");
    if (anyOwn) {
        h += QStringLiteral("<h2>CoScope's own traffic (info, not counted)</h2>\n<ul class='f'>\n");
        for (const HealthFinding& f : r.findings)
            if (f.own) finding(f);
        h += QStringLiteral("</ul>\n");
    }
    h += QStringLiteral("<h2>Nodes</h2>\n");
    for (const NodeHealth& n : r.nodes) {
        h += QStringLiteral("<h3>Node %1: %2</h3>\n<ul class='story'>\n").arg(n.node).arg(esc(n.outcome));
        for (const StoryEntry& e : n.story)
            h += QStringLiteral("<li>%1 <a class='fr'>#%2</a> %3</li>\n")
                     .arg(healthTime(e.timeNs, r.startNs))
                     .arg(e.frame + 1)
                     .arg(esc(e.text));
        if (n.storyMore) h += QStringLiteral("<li class='muted'>… %1 more</li>\n").arg(n.storyMore);
        h += QStringLiteral("</ul>\n");
    }
    h += QStringLiteral(
             "<h2>Bus load</h2>\n<p>average %1 %, peak %2 % at %3 s; error frames %4; frames not CANopen %5</p>\n")
             .arg(svgNumber(b.loadAvgPct), svgNumber(b.loadPeakPct), svgNumber(b.peakAtS, 0))
             .arg(b.errorFrames)
             .arg(b.nonCanopen);
    h += loadSvg(b);
    if (b.syncs)
        h += QStringLiteral("<p>SYNC: %1 frames, period %2 ms (%3), %4 cycles missing</p>\n")
                 .arg(b.syncs)
                 .arg(svgNumber(b.syncPeriodMs, 3), esc(b.syncPeriodSource))
                 .arg(b.syncMissing);

    h += QStringLiteral("<h2>Heartbeat and NMT</h2>\n<table>\n");
    h += head({"node", "state", "kind", "beats", "period min / avg / max ms", "expected ms", "late", "timeouts",
               "boot-ups", "resets", "NMT commands"});
    for (const NodeHealth& n : r.nodes)
        h += row({QString::number(n.node), esc(st(n.state)),
                  n.errorControl.isEmpty() ? QStringLiteral("-") : n.errorControl, QString::number(n.beats),
                  n.beats > 1 ? QStringLiteral("%1 / %2 / %3")
                                    .arg(svgNumber(n.periodMinMs), svgNumber(n.periodAvgMs), svgNumber(n.periodMaxMs))
                              : QStringLiteral("-"),
                  n.expectedPeriodMs > 0
                      ? QStringLiteral("%1 (%2)").arg(svgNumber(n.expectedPeriodMs, 0), n.periodSource)
                      : QStringLiteral("-"),
                  QString::number(n.late), QString::number(n.timeouts), QString::number(n.bootUps),
                  QString::number(n.resets), QString::number(n.nmtCommands)});
    h += QStringLiteral("</table>\n<h2>SDO</h2>\n<table>\n");
    h += head({"node", "transfers", "ok", "aborted", "timeouts", "response min / avg / p99 / max ms", "aborts"});
    for (const NodeHealth& n : r.nodes) {
        if (!n.sdoRequests && !n.sdoTransfers) continue;
        QStringList aborts;
        for (const AbortCount& a : n.sdoAborts)
            aborts << QStringLiteral("%1 ×%2 %3").arg(hexId(a.code, 8)).arg(a.count).arg(esc(a.text));
        h += row({QString::number(n.node), QString::number(n.sdoTransfers), QString::number(n.sdoOk),
                  QString::number(n.sdoAborted), QString::number(n.sdoTimeouts),
                  n.sdoResponses ? QStringLiteral("%1 / %2 / %3 / %4")
                                       .arg(svgNumber(n.sdoRtMinMs, 2), svgNumber(n.sdoRtAvgMs, 2),
                                            svgNumber(n.sdoRtP99Ms, 2), svgNumber(n.sdoRtMaxMs, 2))
                                 : QStringLiteral("-"),
                  aborts.isEmpty() ? QStringLiteral("-") : aborts.join(QStringLiteral("<br>"))});
    }
    h += QStringLiteral("</table>\n<h2>EMCY</h2>\n<table>\n");
    h += head({"node", "time", "code", "register", "text", "vendor"});
    for (const NodeHealth& n : r.nodes)
        for (size_t i = 0; i < std::min<size_t>(n.emcyList.size(), 200); ++i) {
            const EmcyEntry& e = n.emcyList[i];
            h += row({QString::number(n.node), healthTime(e.timeNs, r.startNs), hexId(e.code, 4), hexId(e.reg, 2),
                      esc(e.text), esc(e.vendor)});
        }
    h += QStringLiteral("</table>\n<h2>PDOs</h2>\n<table>\n");
    h += head({"COB-ID", "PDO", "node", "frames", "rate Hz", "period min / avg / max ms", "jitter ms"});
    for (const PdoHealth& p : r.pdos)
        h += row({hexId(p.cobId, 3), p.service + (p.consumerSeen ? QString() : QStringLiteral(" (no consumer)")),
                  QString::number(p.node), QString::number(p.frames), svgNumber(p.rateHz),
                  p.frames > 1
                      ? QStringLiteral("%1 / %2 / %3")
                            .arg(svgNumber(p.periodMinMs, 2), svgNumber(p.periodAvgMs, 2), svgNumber(p.periodMaxMs, 2))
                      : QStringLiteral("-"),
                  p.cyclic ? svgNumber(p.jitterMs, 3) : QStringLiteral("event")});
    h += QStringLiteral(
        "</table>\n<p class='muted'>Generated by CoScope. Load is estimated from frame lengths (nominal bit "
        "stuffing).</p>\n</body></html>\n");
    return h.toUtf8();
}

}  // namespace coscope::dissect
