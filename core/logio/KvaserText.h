// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/logio/LogReader.h"

namespace coscope::logio {

// Kvaser CanKing / Memorator (kvlogconvert "plain text") exports, hexadecimal mode. A header
// line "Chn Identifier Flg   DLC  D0...1...2...3...4...5...6..D7       Time     Dir", then
// " 0    0000014B         1  00                                1675.570498 T":
// channel from 0, id in hex, flags (X extended, R remote), DLC, data bytes in hex, time in
// seconds, R/T direction; error frames read "0  00000000  ErrorFrame  29.095270 R" (layout
// from SavvyCAN framefileio.cpp loadKvaserFile and public CanKing samples quoted in test
// suites on GitHub). "Logging started/stopped" lines are skipped.
class KvaserReader : public LineLogReader {
public:
    QString formatName() const override { return QStringLiteral("kvaser"); }

protected:
    LineResult parseLine(std::string_view line, CanFrame& frame) override;

private:
    LineResult bad(const QString& message);
};

bool isKvaserHeader(std::string_view line);

}  // namespace coscope::logio
