// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/trace/SignalBuffer.h"

#include <cstdint>
#include <vector>

namespace coscope::gui {

// Where a trace's line breaks (issue 37 item 7): no line across a stretch without samples longer
// than a few periods of the signal, which would draw a ramp that never happened (a capture gap,
// a drive that stopped sending). The period is the median interval between the points drawn;
// the gap must also span more than two columns of `columnNs`, so a zoomed-out view of dense
// samples (two points a column) stays one line.
// Returns the indexes i where the line breaks between points[i] and points[i + 1].
std::vector<size_t> plotGaps(const std::vector<SignalPoint>& points, int64_t columnNs);

// Intervals this many times the signal's period are a gap.
inline constexpr int kGapPeriods = 5;

}  // namespace coscope::gui
