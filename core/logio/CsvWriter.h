// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/logio/LogWriter.h"

namespace coscope::logio {

// Decoded CSV (RFC 4180 quoting): number,time,bus,id,ext,rtr,fd,dir,len,data,summary.
// time in seconds with 6 decimals, id in hex with "0x", data as hex bytes separated by spaces;
// the summary comes from write(frame, summary) or the summary provider (the dissectors).
class CsvWriter : public LogWriter {
public:
    QString formatName() const override { return QStringLiteral("csv"); }

protected:
    void writeHeader(const CanFrame* first) override;
    void writeFrame(const CanFrame& frame, const QString& summary) override;
    bool wantsSummary() const override { return true; }
};

}  // namespace coscope::logio
