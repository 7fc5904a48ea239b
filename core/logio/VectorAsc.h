// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/logio/LogReader.h"
#include "core/logio/LogWriter.h"
#include "core/logio/TextScan.h"

#include <QDateTime>

namespace coscope::logio {

// Vector ASCII logging format (CANoe/CANalyzer .asc). Facts from Vector's "CAN ASCII logging
// format" description and python-can's asc.py: header "date ...", "base hex|dec",
// "timestamps absolute|relative", "Begin Triggerblock"/"End TriggerBlock" (any case);
// classic lines "<t> <ch> <id>[x] <Rx|Tx> d <dlc> <bytes>", remote "r [dlc]", "<t> <ch> ErrorFrame",
// "<t> CANFD <ch> <Rx|Tx> <id>[x] [name] <brs> <esi> <dlc> <len> <bytes> ... <flags> ...".
// Channels are numbered from 1. Other events (statistics, chip status, J1939TP) are skipped.
// A comment line "// " in CaptureGapText.h's wording is a gap of the capture before the next frame.
class AscReader : public LineLogReader {
public:
    QString formatName() const override { return QStringLiteral("asc"); }
    // Start of the measurement from the header (invalid when the file has none).
    QDateTime startTime() const { return start_; }

protected:
    LineResult parseLine(std::string_view line, CanFrame& frame) override;

private:
    LineResult bad(const QString& message);
    LineResult parseCanFd(Tokens& tokens, CanFrame& frame);
    bool parseId(std::string_view t, CanFrame& frame) const;
    bool parseByte(std::string_view t, uint8_t& out) const;

    QDateTime start_;
    int64_t startNs_ = 0;
    int64_t lastNs_ = 0;
    bool hex_ = true;
    bool relative_ = false;
};

// Parses an ASC date such as "Sam Sep 30 15:06:13.191 2017" or "Mon Jan 01 03:04:05.678 PM 2024"
// (local time, English or German month names). Invalid QDateTime when it cannot.
QDateTime parseAscDate(std::string_view text);
QByteArray formatAscDate(const QDateTime& time);

// Writes .asc in the form CANalyzer and python-can read: base hex, absolute timestamps relative
// to the "Begin Triggerblock" time (the first frame's time, to the millisecond). A gap of the
// capture is a comment line "// <CaptureGapText.h wording>" before the first frame after it
// (CANalyzer and python-can skip "//" lines in the trigger block).
class AscWriter : public LogWriter {
public:
    QString formatName() const override { return QStringLiteral("asc"); }
    bool keepsGaps() const override { return true; }

protected:
    void writeHeader(const CanFrame* first) override;
    void writeFrame(const CanFrame& frame, const QString& summary) override;
    void writeFooter() override;
    void writeGap(int64_t lostNs, int64_t backNs) override;

private:
    int64_t startNs_ = 0;
};

}  // namespace coscope::logio
