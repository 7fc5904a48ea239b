// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/logio/LogReader.h"

#include <array>

namespace coscope::logio {

// IXXAT MiniMon and canAnalyser text exports (.csv, .trc). The first line names the tool
// ("ASCII Trace IXXAT MiniMon V3  Version: 1.1.4.4533"), a few "Key: value" lines follow
// (Date, Start time, Stop time, Overruns, Baudrate), then a line of quoted column names, e.g.
// "Time","Identifier (hex)","Format","Flags","Data (hex)", and one frame per line:
// "00:30:06.866","184","Std","","00 06 00 16 75 EE 00 3C" (public MiniMon V3 exports quoted in
// lisr-pcx/can_trace_decoder and hilch/canopen-message-interpreter; SavvyCAN framefileio.cpp
// loadIXXATFile). The separator is ',' or ';' (localised exports). Remote frames have "Rtr" in
// Flags and "Remote request DLC = n" as data. Columns are found by their names, so canAnalyser
// exports with other columns (No, DLC, Dir, Bus) read too; times are "h:m:s.frac" or seconds,
// relative to the start of the recording.
class IxxatReader : public LineLogReader {
public:
    QString formatName() const override { return QStringLiteral("ixxat"); }

protected:
    bool readHeader() override;
    LineResult parseLine(std::string_view line, CanFrame& frame) override;

private:
    enum Col { Time, Id, Format, Flags, Dlc, Data, Dir, Bus, ColCount };
    LineResult bad(const QString& message);
    bool columnLine(std::string_view line);

    char sep_ = ',';
    std::array<int, ColCount> col_{};
    bool idDecimal_ = false;
};

bool isIxxatFirstLine(std::string_view line);

}  // namespace coscope::logio
