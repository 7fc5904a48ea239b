// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "dissectors/HealthReport.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>

namespace coscope::dissect {

// The network health report as `coscope-cli stats --format json` writes it (DESIGN.md
// "Contracts"): {findings, nodes, pdos, bus}; every figure of HealthReport.
QJsonObject healthJson(const HealthReport& r);
// Text: the verdict, the findings (own traffic apart), each seen node's story, then per-node tables, PDOs and the bus with a load sparkline (or a table
// of at most 60 rows); `perSecond` appends the load of every second.
QByteArray healthText(const HealthReport& r, bool perSecond);
// One self-contained HTML page (inline CSS and SVG, no external assets).
QByteArray healthHtml(const HealthReport& r, const QString& title);
// "frames 1234, 1250, … (+40)": the first `shown` frame numbers (the trace's No., index + 1).
QString healthFrames(const Occurrences& at, int shown);
// "3 times, 12.000 s .. 80.100 s; frames 1234, 1250, 1300": when and where a finding happened.
QString healthWhere(const HealthFinding& f, int64_t startNs);
// The top of a bus-load chart's scale for a peak load: the smallest of 1, 2, 5, 10, 20, 25, 50,
// 75 and 100 % above it (with a 5 % margin); 100 % for a bus at or over capacity.
double loadScaleTopPct(double peakPct);
// Unicode block sparkline of the load buckets ("▁▂▅█"), scaled to 100 %.
QString loadSparkline(const HealthReport& r);

}  // namespace coscope::dissect
