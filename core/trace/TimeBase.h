// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstdint>

namespace coscope {

// One time base for a trace (DESIGN.md "Time"; issue 37 item 3): the trace, the events, the
// findings, the plot and the exports show a frame's time either as seconds since the trace's
// first frame, or as the wall clock. A trace has a wall clock when its timestamps are Unix time:
// live captures, and logs whose format carries the recording's start (the readers add it: PEAK
// TRC $STARTTIME, ASC "date", BLF and MF4 headers) or absolute stamps (candump -L, pcapng,
// IXXAT); a log of bare relative stamps has none and shows relative seconds in either mode.
struct TimeBase {
    enum class Mode { Relative, WallClock };
    // Timestamps after 1990-01-01 are Unix time.
    static constexpr int64_t kWallClockFromNs = 631152000LL * 1'000'000'000LL;

    int64_t originNs = 0;  // the first frame's timestamp
    Mode mode = Mode::Relative;

    bool hasWallClock() const { return originNs > kWallClockFromNs; }
    // The mode in effect: the wall clock only where the trace has one.
    Mode shown() const { return mode == Mode::WallClock && hasWallClock() ? Mode::WallClock : Mode::Relative; }
    // A time in the mode shown: "12.345678" (seconds since the first frame), or the local wall
    // clock "14:03:12.345678" (with `withDate`, "2026-11-28 14:03:12.345678").
    QString text(int64_t ns, bool withDate = false) const;
    // The same to the millisecond, with its unit: "12.346 s" or "14:03:12.346".
    QString shortText(int64_t ns) const;
    // Seconds since the first frame.
    double seconds(int64_t ns) const { return double(ns - originNs) / 1e9; }
};

}  // namespace coscope
