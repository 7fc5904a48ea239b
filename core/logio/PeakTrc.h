// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/logio/LogReader.h"
#include "core/logio/LogWriter.h"
#include "core/logio/TextScan.h"

namespace coscope::logio {

// PEAK-System trace files (.trc), versions 1.0 to 2.1, per PEAK's "PEAK CAN TRC File Format"
// document: ";$FILEVERSION=x.y", ";$STARTTIME=" (days since 1899-12-30, local time, OLE date),
// 1.x lines "N) offset-ms [bus] [Rx|Tx] ID [-] DLC data|RTR", 2.x lines in the order given by
// ";$COLUMNS=" (N number, O offset ms, T type, B bus, I id, d Rx/Tx, R reserved, L DLC,
// l length, D data). Types: DT data, FD/FB/FE/BI CAN FD (BRS/ESI), RR remote, ER error;
// status and event lines are skipped. Ids with more than 4 digits are 29-bit. A comment line
// "; " in CaptureGapText.h's wording is a gap of the capture before the next frame.
class TrcReader : public LineLogReader {
public:
    QString formatName() const override { return QStringLiteral("trc"); }
    int versionMajor() const { return major_; }
    int versionMinor() const { return minor_; }

protected:
    LineResult parseLine(std::string_view line, CanFrame& frame) override;

private:
    LineResult bad(const QString& message);
    LineResult parseV1(Tokens& tokens, CanFrame& frame);
    LineResult parseV2(Tokens& tokens, CanFrame& frame);
    bool parseId(std::string_view t, CanFrame& frame);
    LineResult readData(Tokens& tokens, CanFrame& frame, uint32_t len);
    LineResult readStatus(Tokens& tokens, CanFrame& frame);

    int major_ = 1;
    int minor_ = 0;
    bool versionSeen_ = false;
    std::string columns_;  // 2.x column letters
    int64_t startNs_ = 0;
};

// OLE automation date text ("44964.5725134375", local time) to nanoseconds since the Unix
// epoch (rounded to the microsecond), and back with 15 decimals.
std::optional<int64_t> oleDateToNs(std::string_view text);
QByteArray nsToOleDate(int64_t ns);

// Writes TRC version 2.1 (the version PCAN-View 5 writes). A gap of the capture is a comment
// line "; <CaptureGapText.h wording>" before the first frame after it (PEAK's format takes any
// line starting with ';' as a comment; python-can's TRCReader skips them too).
class TrcWriter : public LogWriter {
public:
    QString formatName() const override { return QStringLiteral("trc"); }
    bool keepsGaps() const override { return true; }

protected:
    void writeHeader(const CanFrame* first) override;
    void writeFrame(const CanFrame& frame, const QString& summary) override;
    void writeGap(int64_t lostNs, int64_t backNs) override;

private:
    int64_t startNs_ = 0;
};

}  // namespace coscope::logio
