// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/KvaserText.h"

#include "core/logio/CsvScan.h"

namespace coscope::logio {

bool isKvaserHeader(std::string_view line) {
    Tokens t(line);
    return equalsNoCase(t.next(), "chn") && equalsNoCase(t.next(), "identifier") && equalsNoCase(t.next(), "flg");
}

KvaserReader::LineResult KvaserReader::bad(const QString& message) {
    warn(lineNumber(), message);
    return LineResult::Bad;
}

KvaserReader::LineResult KvaserReader::parseLine(std::string_view line, CanFrame& f) {
    line = trimmed(line);
    if (line.empty() || isKvaserHeader(line) || startsWithNoCase(line, "logging")) return LineResult::Skip;
    Tokens tok(line);
    const auto chn = parseDec(tok.next());
    if (!chn) return bad(QStringLiteral("expected a channel number"));
    f.bus = busChannel(std::min<uint32_t>(*chn, 254) + 1);  // channel 0 is can0
    const std::string_view idText = tok.next();
    const auto id = parseHex(idText);
    if (!id || *id > 0x1FFFFFFFU) return bad(QStringLiteral("bad identifier %1").arg(quoted(idText)));
    f.id = *id;
    if (idText.size() > 4 && *id > 0x7FF) f.flags |= CanFrame::Extended;
    // Flags: letters before the DLC.
    std::string_view t = tok.next();
    while (!t.empty() && !(t.front() >= '0' && t.front() <= '9')) {
        if (equalsNoCase(t, "x")) f.flags |= CanFrame::Extended;
        else if (equalsNoCase(t, "r")) f.flags |= CanFrame::Remote;
        else if (startsWithNoCase(t, "errorframe") || equalsNoCase(t, "err")) f.flags |= CanFrame::Error;
        else if (equalsNoCase(t, "f") || equalsNoCase(t, "fdf")) f.flags |= CanFrame::Fd;
        else if (equalsNoCase(t, "b") || equalsNoCase(t, "brs")) f.flags |= CanFrame::Fd | CanFrame::BitRateSwitch;
        t = tok.next();
    }
    if (f.isError()) {
        // "ErrorFrame  29.095270 R": no DLC, no data.
        f.id = 0;
        f.flags &= CanFrame::Error;
        const auto ts = parseDecimalNs(t, 1000000000);
        if (!ts) return bad(QStringLiteral("bad time %1").arg(quoted(t)));
        f.timestampNs = *ts;
        return LineResult::Frame;
    }
    if (!f.isExtended() && f.id > 0x7FF) return bad(QStringLiteral("11-bit identifier above 7FF"));
    const auto dlc = parseDec(t);
    if (!dlc || *dlc > 64 || (*dlc > 8 && !f.isFd() && !isValidFdLength(int(*dlc))))
        return bad(QStringLiteral("bad DLC %1").arg(quoted(t)));
    if (*dlc > 8) {
        if (f.isRemote() || !isValidFdLength(int(*dlc))) return bad(QStringLiteral("bad DLC %1").arg(quoted(t)));
        f.flags |= CanFrame::Fd;
    }
    f.len = uint8_t(*dlc);
    for (int i = 0; i < f.payloadSize(); ++i) {
        const std::string_view b = tok.next();
        const auto v = parseHexByte(b);
        if (!v)
            return bad(QStringLiteral("DLC %1 but data byte %2 is missing or not hexadecimal").arg(f.len).arg(i + 1));
        f.data[size_t(i)] = *v;
    }
    const std::string_view timeText = tok.next();
    const auto ts = parseDecimalNs(timeText, 1000000000);
    if (!ts) return bad(QStringLiteral("bad time %1").arg(quoted(timeText)));
    f.timestampNs = *ts;
    const std::string_view dir = tok.next();
    if (equalsNoCase(dir, "t")) f.flags |= CanFrame::Tx;
    else if (!dir.empty() && !equalsNoCase(dir, "r"))
        return bad(QStringLiteral("direction %1 is not R or T").arg(quoted(dir)));
    return LineResult::Frame;
}

}  // namespace coscope::logio
