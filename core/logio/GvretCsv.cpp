// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/GvretCsv.h"

#include "core/logio/CsvScan.h"

namespace coscope::logio {

bool isGvretHeader(std::string_view line) { return startsWithNoCase(trimmed(line), "time stamp,id,extended,"); }

GvretCsvReader::LineResult GvretCsvReader::bad(const QString& message) {
    warn(lineNumber(), message);
    return LineResult::Bad;
}

bool GvretCsvReader::readHeader() {
    std::string_view line;
    while (nextLine(line)) {
        if (trimmed(line).empty()) continue;
        if (!isGvretHeader(line)) {
            fail(QStringLiteral("not a SavvyCAN GVRET CSV file: the first line is not \"Time Stamp,ID,Extended,...\""));
            return false;
        }
        // SavvyCAN: version 2 adds "Dir" after "Extended" (framefileio.cpp isNativeCSVFile).
        const CsvFields c(line, ',');
        hasDir_ = equalsNoCase(c[3], "dir");
        return true;
    }
    return true;
}

GvretCsvReader::LineResult GvretCsvReader::parseLine(std::string_view line, CanFrame& f) {
    if (trimmed(line).empty()) return LineResult::Skip;
    const CsvFields c(line, ',');
    const size_t busCol = hasDir_ ? 4 : 3;
    const size_t lenCol = busCol + 1;
    if (c.size() < lenCol + 1)
        return bad(QStringLiteral("%1 columns, expected at least %2").arg(c.size()).arg(lenCol + 1));
    const auto ts = parseDecimalNs(c[0], 1000);  // microseconds
    if (!ts) return bad(QStringLiteral("bad time stamp %1").arg(quoted(c[0])));
    f.timestampNs = *ts;
    std::string_view id = c[1];
    if (startsWithNoCase(id, "0x")) id.remove_prefix(2);
    const auto v = parseHex(id);
    if (!v || *v > 0x1FFFFFFFU) return bad(QStringLiteral("bad identifier %1").arg(quoted(c[1])));
    f.id = *v;
    if (equalsNoCase(c[2], "true") || c[2] == "1") f.flags |= CanFrame::Extended;
    else if (!equalsNoCase(c[2], "false") && c[2] != "0")
        return bad(QStringLiteral("Extended must be true or false, not %1").arg(quoted(c[2])));
    if (f.id > 0x7FF) f.flags |= CanFrame::Extended;  // SavvyCAN does the same for files that forget the flag
    if (hasDir_) {
        if (equalsNoCase(c[3], "tx")) f.flags |= CanFrame::Tx;
        else if (!equalsNoCase(c[3], "rx"))
            return bad(QStringLiteral("Dir must be Rx or Tx, not %1").arg(quoted(c[3])));
    }
    const auto bus = parseDec(c[busCol]);
    if (!bus) return bad(QStringLiteral("bad bus number %1").arg(quoted(c[busCol])));
    f.bus = busChannel(std::min<uint32_t>(*bus, 255) + 1);  // bus 0 is can0
    const auto len = parseDec(c[lenCol]);
    if (!len || *len > 64 || (*len > 8 && !isValidFdLength(int(*len))))
        return bad(QStringLiteral("bad length %1").arg(quoted(c[lenCol])));
    if (*len > 8) f.flags |= CanFrame::Fd;
    f.len = uint8_t(*len);
    for (uint32_t i = 0; i < *len; ++i) {
        const std::string_view t = c[lenCol + 1 + i];
        const auto b = t.size() <= 2 ? parseHex(t) : std::nullopt;
        if (!b)
            return bad(t.empty() ? QStringLiteral("LEN %1 but only %2 data bytes").arg(*len).arg(i)
                                 : QStringLiteral("data byte %1 is not hexadecimal").arg(i + 1));
        f.data[i] = uint8_t(*b);
    }
    return LineResult::Frame;
}

}  // namespace coscope::logio
