// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/logio/LogReader.h"
#include "core/logio/LogWriter.h"
#include "core/logio/TextScan.h"

namespace coscope::logio {

// can-utils candump output (candump.c, lib.c):
//  - log files (-l/-L): "(1700000000.123456) can0 123#DEADBEEF", optional " R"/" T" direction,
//    FD "123##1AABB" (flags digit: 1 BRS, 2 ESI), remote "123#R", error frames as 8-digit ids
//    with CAN_ERR_FLAG 0x20000000 (linux/can.h);
//  - default text: "  can0  123   [8]  11 22 ..", FD lengths as "[12]"/"[03]", "remote request",
//    optionally preceded by "(timestamp)" (-t) and followed by "ERRORFRAME".
class CandumpReader : public LineLogReader {
public:
    QString formatName() const override { return QStringLiteral("candump"); }

protected:
    LineResult parseLine(std::string_view line, CanFrame& frame) override;

private:
    bool parsePlainLogLine(std::string_view line, CanFrame& frame);
    LineResult parseLogForm(std::string_view payload, Tokens& rest, CanFrame& frame);
    LineResult parseTextForm(Tokens& tokens, CanFrame& frame);
    LineResult bad(const QString& message);
};

// Writes candump -L log files (replayable with canplayer).
class CandumpWriter : public LogWriter {
public:
    QString formatName() const override { return QStringLiteral("candump"); }

protected:
    void writeHeader(const CanFrame*) override {}
    void writeFrame(const CanFrame& frame, const QString& summary) override;
};

}  // namespace coscope::logio
