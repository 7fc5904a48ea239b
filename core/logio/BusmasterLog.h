// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/logio/LogReader.h"

namespace coscope::logio {

// BUSMASTER CAN logs (.log), versions 1.x to 3.x. The header is a block of "***...***" lines
// (BUSMASTER sources, LogObjectCAN.cpp CAN_LOG_* strings): "***BUSMASTER Ver 3.2.2***",
// "***START DATE AND TIME d:m:yyyy h:m:s:ms***", "***HEX***" or "***DEC***" (number base of
// identifiers and data bytes), "***SYSTEM MODE***" (time of day), "***ABSOLUTE MODE***" (time
// since the start) or "***RELATIVE MODE***" (time since the previous frame), and the column
// line "***<Time><Tx/Rx><Channel><CAN ID><Type><DLC><DataBytes>***". Frame lines are
// "11:49:12:9420 Rx 1 0x023 s 1 40": time h:m:s:tttt in 1/10 ms, channel from 1, type
// s/x (11/29-bit) with an r suffix for remote frames (SavvyCAN framefileio.cpp loadLogFile).
class BusmasterReader : public LineLogReader {
public:
    QString formatName() const override { return QStringLiteral("busmaster"); }
    enum class TimeMode { System, Absolute, Relative };
    TimeMode timeMode() const { return mode_; }
    bool decimal() const { return decimal_; }

protected:
    LineResult parseLine(std::string_view line, CanFrame& frame) override;

private:
    LineResult bad(const QString& message);
    void headerLine(std::string_view text);
    bool parseNumber(std::string_view t, uint32_t& v, bool isId) const;

    TimeMode mode_ = TimeMode::System;
    bool decimal_ = false;
    int64_t startNs_ = 0;      // START DATE AND TIME, local time, as ns since the epoch
    int64_t midnightNs_ = 0;   // the start date's midnight (system mode)
    int64_t lastTimeNs_ = -1;  // last time column (system mode: to see midnight pass)
    int64_t dayOffsetNs_ = 0;
    int64_t relativeNs_ = 0;
};

}  // namespace coscope::logio
