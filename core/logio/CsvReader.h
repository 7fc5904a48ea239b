// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/logio/LogReader.h"

namespace coscope::logio {

// CoScope's own CSV, as CsvWriter writes it (CsvWriter.h): the header
// "number,time,bus,id,ext,rtr,fd,dir,len,data,summary", time in seconds, id in hex with 0x,
// data as hex bytes separated by spaces. The summary column is not read back, except in a
// "gap" row (CsvWriter.h): a gap of the capture before the next frame.
class CsvReader : public LineLogReader {
public:
    QString formatName() const override { return QStringLiteral("csv"); }

protected:
    bool readHeader() override;
    LineResult parseLine(std::string_view line, CanFrame& frame) override;

private:
    LineResult bad(const QString& message);
};

// True when `line` is the header line CsvWriter writes.
bool isCoScopeCsvHeader(std::string_view line);

}  // namespace coscope::logio
