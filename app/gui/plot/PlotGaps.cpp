// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/PlotGaps.h"

#include <algorithm>

namespace coscope::gui {

std::vector<size_t> plotGaps(const std::vector<SignalPoint>& points, int64_t columnNs) {
    std::vector<size_t> out;
    if (points.size() < 3) return out;
    std::vector<int64_t> steps;
    steps.reserve(points.size() - 1);
    for (size_t i = 1; i < points.size(); ++i)
        if (const int64_t d = points[i].timeNs - points[i - 1].timeNs; d > 0) steps.push_back(d);
    if (steps.empty()) return out;
    auto mid = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
    std::nth_element(steps.begin(), mid, steps.end());
    const int64_t threshold = std::max<int64_t>(*mid * kGapPeriods, columnNs * 5 / 2);
    for (size_t i = 1; i < points.size(); ++i)
        if (points[i].timeNs - points[i - 1].timeNs > threshold) out.push_back(i - 1);
    return out;
}

}  // namespace coscope::gui
