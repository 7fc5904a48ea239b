// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/logio/LogWriter.h"

namespace coscope::logio {

// Decoded CSV (RFC 4180 quoting): number,time,bus,id,ext,rtr,fd,dir,len,data,summary.
// time in seconds with 6 decimals, id in hex with "0x", data as hex bytes separated by spaces;
// the summary comes from write(frame, summary) or the summary provider (the dissectors).
// A gap of the capture is a row of its own before the first frame after it: number, bus, id,
// ext, rtr, fd, len and data empty, time = when the adapter was lost, dir "gap", the summary in
// CaptureGapText.h's wording. CSV has no comment lines; a row keeps every line at 11 columns, so
// spreadsheets and csv modules read the file as before and can filter the gap rows by dir.
class CsvWriter : public LogWriter {
public:
    QString formatName() const override { return QStringLiteral("csv"); }
    bool keepsGaps() const override { return true; }

protected:
    void writeHeader(const CanFrame* first) override;
    void writeFrame(const CanFrame& frame, const QString& summary) override;
    void writeGap(int64_t lostNs, int64_t backNs) override;
    bool wantsSummary() const override { return true; }
};

}  // namespace coscope::logio
