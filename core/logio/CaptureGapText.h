// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>

#include <cstdint>
#include <string_view>

namespace coscope::logio {

// The fixed wording of a gap in a live capture (issue 16 "Lost adapter") that the writers put in
// a log, and that our readers turn back into a CaptureGap:
//
//   CoScope: gap in the capture before this frame: the adapter was lost for 2.5 s, frames in
//   between are missing (lost_ns=1700000001000000000 back_ns=1700000003500000000)
//
// (one line). lost_ns/back_ns are the times the adapter was lost and back, in nanoseconds since
// the Unix epoch (UTC), the clock of the frames' timestamps. Where it goes per format:
//   pcapng      the comment (opt_comment) of the first packet after the gap;
//   Vector ASC  a comment line "// <wording>" before the first frame after the gap;
//   PEAK TRC    a comment line "; <wording>" before that frame;
//   CSV         a row before that frame with dir "gap", time = lost time, the wording in the
//               summary column and the other columns empty (keeps every row at 11 columns).
// candump and BLF have no place for it (LogWriter::keepsGaps()).
QByteArray captureGapText(int64_t lostNs, int64_t backNs);
// True when `text` (surrounding blanks allowed) is in that wording; fills the times.
bool parseCaptureGapText(std::string_view text, int64_t* lostNs, int64_t* backNs);

}  // namespace coscope::logio
