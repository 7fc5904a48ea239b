// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "dissectors/HealthReport.h"

#include <QImage>
#include <QString>

namespace coscope::gui {

// The Health report for a ticket (issue 37 item 8), the same page `coscope-cli stats --format
// html` writes (dissect::healthHtml: verdict, findings with what / why / check and the frame
// numbers they rest on, node stories, tables, bus load):
// - HTML: that page, self-contained;
// - PDF (A4): that page laid out by Qt's rich text, the bus load chart as `loadChart` (an SVG
//   is not drawn there).
// False and `error` (the file and why) when it cannot be written; an older file is kept then.
bool writeHealthHtml(const QString& path, const dissect::HealthReport& report, const QString& title, QString* error);
bool writeHealthPdf(const QString& path, const dissect::HealthReport& report, const QString& title,
                    const QImage& loadChart, QString* error);

}  // namespace coscope::gui
