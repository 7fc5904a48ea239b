// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/CsvReader.h"

#include "core/logio/CsvScan.h"

namespace coscope::logio {

namespace {
enum Column { Number, Time, Bus, Id, Ext, Rtr, Fd, Dir, Len, Data, Summary };
}

bool isCoScopeCsvHeader(std::string_view line) {
    return startsWithNoCase(trimmed(line), "number,time,bus,id,ext,rtr,fd,dir,len,data");
}

CsvReader::LineResult CsvReader::bad(const QString& message) {
    warn(lineNumber(), message);
    return LineResult::Bad;
}

bool CsvReader::readHeader() {
    std::string_view line;
    while (nextLine(line)) {
        if (trimmed(line).empty()) continue;
        if (isCoScopeCsvHeader(line)) return true;
        fail(QStringLiteral("not a CoScope CSV file: the first line is not \"number,time,bus,id,...\""));
        return false;
    }
    return true;  // empty file: no frames
}

CsvReader::LineResult CsvReader::parseLine(std::string_view line, CanFrame& f) {
    if (trimmed(line).empty()) return LineResult::Skip;
    const CsvFields c(line, ',');
    if (c.size() < Data + 1) return bad(QStringLiteral("%1 columns, expected 11").arg(c.size()));
    if (c[Dir] == "gap") {
        noteGapComment(c[Summary]);
        return LineResult::Skip;
    }
    const auto ts = parseDecimalNs(c[Time], 1000000000);
    if (!ts) return bad(QStringLiteral("bad time %1").arg(quoted(c[Time])));
    f.timestampNs = *ts;
    f.bus = c[Bus].empty() ? busIndex("can0") : busIndex(c[Bus]);
    std::string_view id = c[Id];
    if (startsWithNoCase(id, "0x")) id.remove_prefix(2);
    const auto v = parseHex(id);
    if (!v || *v > 0x1FFFFFFFU) return bad(QStringLiteral("bad identifier %1").arg(quoted(c[Id])));
    f.id = *v;
    auto flag = [&](Column col, uint8_t bit) {
        if (c[col] == "1") f.flags |= bit;
        return c[col] == "0" || c[col] == "1";
    };
    if (!flag(Ext, CanFrame::Extended) || !flag(Rtr, CanFrame::Remote) || !flag(Fd, CanFrame::Fd))
        return bad(QStringLiteral("ext, rtr and fd must be 0 or 1"));
    if (!f.isExtended() && f.id > 0x7FF) return bad(QStringLiteral("11-bit identifier above 7FF"));
    if (c[Dir] == "tx") f.flags |= CanFrame::Tx;
    else if (c[Dir] == "error") f.flags |= CanFrame::Error;
    else if (c[Dir] != "rx") return bad(QStringLiteral("direction %1 is not rx, tx or error").arg(quoted(c[Dir])));
    const auto len = parseDec(c[Len]);
    if (!len || *len > (f.isFd() ? 64u : 8u) || (f.isRemote() && *len > 8))
        return bad(QStringLiteral("bad length %1").arg(quoted(c[Len])));
    f.len = uint8_t(*len);
    Tokens bytes(c[Data]);
    const int carried = f.payloadSize();
    for (int i = 0; i < carried; ++i) {
        const auto b = parseHexByte(bytes.next());
        if (!b)
            return bad(
                QStringLiteral("length %1 but data byte %2 is missing or not hexadecimal").arg(carried).arg(i + 1));
        f.data[size_t(i)] = *b;
    }
    if (!bytes.atEnd()) return bad(QStringLiteral("more data bytes than the length %1").arg(carried));
    return LineResult::Frame;
}

}  // namespace coscope::logio
