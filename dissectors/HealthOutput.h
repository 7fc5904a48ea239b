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
// Text: findings first, then per-node tables, PDOs and the bus with a load sparkline (or a table
// of at most 60 rows); `perSecond` appends the load of every second.
QByteArray healthText(const HealthReport& r, bool perSecond);
// One self-contained HTML page (inline CSS and SVG, no external assets).
QByteArray healthHtml(const HealthReport& r, const QString& title);
// Unicode block sparkline of the load buckets ("▁▂▅█"), scaled to 100 %.
QString loadSparkline(const HealthReport& r);

}  // namespace coscope::dissect
