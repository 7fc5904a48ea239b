// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/trace/TraceStore.h"

#include <cstdint>

namespace coscope {

// One value of a signal: when, what (the raw value as decoded, before any engineering scale)
// and which trace frame carried it.
struct SignalSample {
    int64_t timeNs = 0;
    double value = 0;
    FrameNo frame = 0;
};

// One vertex of a decimated trace (raw value, or 0/1 for a bit).
struct SignalPoint {
    int64_t timeNs = 0;
    double value = 0;
};

// Smallest and largest value of a stretch of samples.
struct SignalRange {
    double min = 0;
    double max = 0;
    bool valid = false;
};

}  // namespace coscope
