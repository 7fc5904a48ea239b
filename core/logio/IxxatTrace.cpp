// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/IxxatTrace.h"

#include "core/logio/CsvScan.h"

namespace coscope::logio {

bool isIxxatFirstLine(std::string_view line) { return containsNoCase(line.substr(0, 200), "IXXAT"); }

IxxatReader::LineResult IxxatReader::bad(const QString& message) {
    warn(lineNumber(), message);
    return LineResult::Bad;
}

// The column names line: a quoted "Time" and an identifier column.
bool IxxatReader::columnLine(std::string_view line) {
    if (!containsNoCase(line, "time") || !containsNoCase(line, "ident")) {
        if (!containsNoCase(line, "\"id")) return false;
    }
    const size_t comma = line.find(','), semi = line.find(';');
    sep_ = semi != std::string_view::npos && (comma == std::string_view::npos || semi < comma) ? ';' : ',';
    const CsvFields c(line, sep_);
    col_.fill(-1);
    for (size_t i = 0; i < c.size(); ++i) {
        const std::string_view n = c[i];
        auto set = [&](Col k) {
            if (col_[k] < 0) col_[k] = int(i);
        };
        if (containsNoCase(n, "time")) set(Time);
        else if (containsNoCase(n, "ident") || equalsNoCase(n.substr(0, 2), "id")) {
            set(Id);
            idDecimal_ = containsNoCase(n, "dec");
        } else if (containsNoCase(n, "format")) set(Format);
        else if (containsNoCase(n, "flag") || containsNoCase(n, "type") || containsNoCase(n, "state")) set(Flags);
        else if (containsNoCase(n, "dlc") || containsNoCase(n, "length")) set(Dlc);
        else if (containsNoCase(n, "data")) set(Data);
        else if (containsNoCase(n, "dir") || containsNoCase(n, "rx/tx")) set(Dir);
        else if (containsNoCase(n, "bus") || containsNoCase(n, "channel") || containsNoCase(n, "ctrl")) set(Bus);
    }
    return col_[Time] >= 0 && col_[Id] >= 0 && col_[Data] >= 0;
}

bool IxxatReader::readHeader() {
    std::string_view line;
    if (!nextLine(line)) return true;
    if (!isIxxatFirstLine(line)) {
        fail(QStringLiteral("not an IXXAT export: the first line does not name IXXAT"));
        return false;
    }
    for (int i = 0; i < 40 && nextLine(line); ++i)
        if (columnLine(line)) return true;
    fail(QStringLiteral(
        "IXXAT export without a column line (\"Time\",\"Identifier\",...,\"Data\") in its first 40 lines"));
    return false;
}

namespace {
// "h:m:s.frac", "m:s.frac" or "s.frac" to ns.
std::optional<int64_t> parseClock(std::string_view t) {
    int64_t minutes = 0;
    int parts = 0;
    for (size_t colon = t.find(':'); colon != std::string_view::npos; colon = t.find(':')) {
        const auto v = parseDec(t.substr(0, colon));
        if (!v || ++parts > 2 || *v > 1000000) return std::nullopt;
        minutes = parts == 1 ? *v : minutes * 60 + *v;  // "h:m:" or "m:"
        t.remove_prefix(colon + 1);
    }
    const auto sec = parseDecimalNs(t, 1000000000);
    if (!sec || *sec < 0) return std::nullopt;
    return addNs(minutes * 60 * 1000000000LL, *sec);
}
}  // namespace

IxxatReader::LineResult IxxatReader::parseLine(std::string_view line, CanFrame& f) {
    if (trimmed(line).empty()) return LineResult::Skip;
    const CsvFields c(line, sep_);
    auto field = [&](Col k) { return col_[k] < 0 ? std::string_view() : c[size_t(col_[k])]; };
    if (c.size() <= size_t(std::max({col_[Time], col_[Id], col_[Data]})))
        return bad(QStringLiteral("%1 columns, fewer than the header names").arg(c.size()));
    const auto ts = parseClock(field(Time));
    if (!ts) return bad(QStringLiteral("bad time %1").arg(quoted(field(Time))));
    f.timestampNs = *ts;
    std::string_view idText = field(Id);
    if (startsWithNoCase(idText, "0x")) idText.remove_prefix(2);
    else if (!idText.empty() && (idText.back() == 'h' || idText.back() == 'H')) idText.remove_suffix(1);
    const auto id = idDecimal_ ? parseDec(idText) : parseHex(idText);
    if (!id || *id > 0x1FFFFFFFU) return bad(QStringLiteral("bad identifier %1").arg(quoted(field(Id))));
    f.id = *id;
    const std::string_view format = field(Format);
    if (startsWithNoCase(format, "ext") || equalsNoCase(format, "x")) f.flags |= CanFrame::Extended;
    else if (!format.empty() && !startsWithNoCase(format, "std") && !equalsNoCase(format, "s"))
        return bad(QStringLiteral("format %1 is not Std or Ext").arg(quoted(format)));
    if (f.id > 0x7FF) f.flags |= CanFrame::Extended;
    const std::string_view flags = field(Flags);
    if (containsNoCase(flags, "rtr") || containsNoCase(flags, "remote")) f.flags |= CanFrame::Remote;
    if (containsNoCase(flags, "err")) f.flags |= CanFrame::Error;
    if (containsNoCase(flags, "tx") || equalsNoCase(field(Dir), "tx")) f.flags |= CanFrame::Tx;
    if (col_[Bus] >= 0) {
        const auto bus = parseDec(field(Bus));
        if (bus) f.bus = busChannel(std::min<uint32_t>(*bus, 255));
        else f.bus = busChannel(1);
    } else {
        f.bus = busChannel(1);
    }
    const std::string_view data = field(Data);
    int dlc = -1;
    if (col_[Dlc] >= 0 && !field(Dlc).empty()) {
        const auto v = parseDec(field(Dlc));
        if (!v || *v > 64) return bad(QStringLiteral("bad DLC %1").arg(quoted(field(Dlc))));
        dlc = int(*v);
    }
    if (containsNoCase(data, "remote request")) {  // "Remote request DLC = 4"
        f.flags |= CanFrame::Remote;
        const size_t eq = data.find('=');
        const auto v = eq == std::string_view::npos ? std::nullopt : parseDec(trimmed(data.substr(eq + 1)));
        if (v && *v <= 8) dlc = int(*v);
    }
    if (f.isRemote() || f.isError()) {
        f.len = uint8_t(std::clamp(dlc, 0, 8));
        if (f.isError()) f.id = 0;
        return LineResult::Frame;
    }
    Tokens bytes(data);
    int n = 0;
    for (std::string_view b = bytes.next(); !b.empty(); b = bytes.next()) {
        const auto v = parseHexByte(b);
        if (!v) return bad(QStringLiteral("data byte %1 %2 is not hexadecimal").arg(n + 1).arg(quoted(b)));
        if (n >= 64) return bad(QStringLiteral("more than 64 data bytes"));
        f.data[size_t(n++)] = *v;
    }
    if (dlc >= 0 && dlc != n) return bad(QStringLiteral("DLC %1 but %2 data bytes").arg(dlc).arg(n));
    if (n > 8) {
        if (!isValidFdLength(n)) return bad(QStringLiteral("%1 bytes is not a CAN FD length").arg(n));
        f.flags |= CanFrame::Fd;
    }
    f.len = uint8_t(n);
    return LineResult::Frame;
}

}  // namespace coscope::logio
