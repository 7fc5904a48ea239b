// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/logio/LogReader.h"

namespace coscope::logio {

// SavvyCAN's native "GVRET" CSV (SavvyCAN framefileio.cpp saveNativeCSVFile/loadNativeCSVFile):
// header "Time Stamp,ID,Extended,Dir,Bus,LEN,D1,D2,...", then lines like
// "39747828,000005EB,false,Rx,0,8,E8,45,85,4B,4A,28,36,69," with the time stamp in
// microseconds, the id in hex, Extended true/false, Dir Rx/Tx, Bus from 0, LEN bytes in hex.
// Version 1 files (older SavvyCAN) have no Dir column; the header says which. SavvyCAN pads
// the data columns to 8 with "00" and ends lines with a comma; only LEN bytes are read.
class GvretCsvReader : public LineLogReader {
public:
    QString formatName() const override { return QStringLiteral("gvret"); }

protected:
    bool readHeader() override;
    LineResult parseLine(std::string_view line, CanFrame& frame) override;

private:
    LineResult bad(const QString& message);
    bool hasDir_ = true;
};

// True for a GVRET header line ("Time Stamp,ID,Extended,...").
bool isGvretHeader(std::string_view line);

}  // namespace coscope::logio
