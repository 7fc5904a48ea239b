// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/plot/PlotSignal.h"

#include <QString>

#include <vector>

namespace coscope::gui {

// Writes the samples of `plotted` with t0 <= time <= t1 as CSV (RFC 4180): one row per trace
// frame that carried any of them, "time_s,frame" then one column per signal titled
// "label [unit]" with the scaled value (empty when that frame did not carry the signal).
// Times are seconds from `originNs`. Returns false with *error on a write failure.
bool writePlotCsv(const QString& path, const std::vector<PlotSignal>& plotted, int64_t t0, int64_t t1, int64_t originNs,
                  QString* error);

}  // namespace coscope::gui
