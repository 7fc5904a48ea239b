// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/CandumpLog.h"

#include "core/logio/TextScan.h"

#include <cstring>

namespace coscope::logio {

namespace {
constexpr uint32_t kCanErrFlag = 0x20000000U;  // linux/can.h CAN_ERR_FLAG
constexpr uint32_t kCanEffMask = 0x1FFFFFFFU;

// Identifier token: 3 hex digits = 11-bit, 8 digits = 29-bit (or error frame with CAN_ERR_FLAG).
bool parseId(std::string_view t, CanFrame& f, QString* why) {
    const auto v = parseHex(t);
    if (!v) {
        *why =
            QStringLiteral("identifier '%1' is not hexadecimal").arg(QLatin1StringView(t.data(), qsizetype(t.size())));
        return false;
    }
    if (t.size() > 3) {
        if (*v & kCanErrFlag) {
            f.flags |= CanFrame::Error;
            f.id = *v & kCanEffMask & ~kCanErrFlag;
        } else {
            if (*v > kCanEffMask) {
                *why = QStringLiteral("29-bit identifier above 1FFFFFFF");
                return false;
            }
            f.flags |= CanFrame::Extended;
            f.id = *v;
        }
    } else {
        if (*v > 0x7FF) {
            *why = QStringLiteral("11-bit identifier above 7FF");
            return false;
        }
        f.id = *v;
    }
    return true;
}
}  // namespace

CandumpReader::LineResult CandumpReader::bad(const QString& message) {
    warn(lineNumber(), message);
    return LineResult::Bad;
}

// candump -L's own line, "(1700000000.123456) can0 123#11223344" (can-utils log.c: seconds,
// a fraction, one space, the interface, one space, the frame, nothing after it), read in one
// pass: it is nearly every line of a log, and the general path below tokenises it three times.
// Anything else in the line (FD "##", remote "R", "." separators, a direction, an 8-digit id
// with the error flag, a fault) returns false with `f` untouched and takes the general path,
// which reads the lines taken here as the same frame.
bool CandumpReader::parsePlainLogLine(std::string_view line, CanFrame& f) {
    const char* p = line.data();
    const char* const end = p + line.size();
    if (p == end || *p++ != '(') return false;
    int64_t seconds = 0;
    const char* start = p;
    // At most 11 digits are read (more fail below), so the value cannot overflow.
    while (p < end && p - start <= 10 && unsigned(*p - '0') < 10) seconds = seconds * 10 + (*p++ - '0');
    // Below INT64_MAX / 1e9 - 1 s, so that seconds and fraction add up without overflow.
    if (p == start || p - start > 10 || seconds >= INT64_MAX / 1'000'000'000 || p == end || *p++ != '.') return false;
    int64_t fraction = 0;
    start = p;
    while (p < end && p - start <= 9 && unsigned(*p - '0') < 10) fraction = fraction * 10 + (*p++ - '0');
    const auto fractionDigits = p - start;
    if (fractionDigits == 0 || fractionDigits > 9 || end - p < 2 || p[0] != ')' || p[1] != ' ') return false;
    static constexpr int64_t kScale[10] = {1'000'000'000, 100'000'000, 10'000'000, 1'000'000, 100'000,
                                           10'000,        1'000,       100,        10,        1};
    p += 2;
    start = p;
    while (p < end && !isSpace(*p)) ++p;
    if (p == start || end - p < 2 || *p != ' ') return false;
    const std::string_view iface(start, size_t(p - start));
    start = ++p;
    uint32_t id = 0;
    for (int d; p < end && (d = hexDigit(*p)) >= 0; ++p) id = (id << 4) | uint32_t(d);
    const auto idDigits = p - start;
    if (p == end || *p++ != '#') return false;
    const bool extended = idDigits == 8;
    if (extended ? (id > kCanEffMask || (id & kCanErrFlag)) : (idDigits != 3 || id > 0x7FF)) return false;
    if (end - p > 16 || (end - p) % 2) return false;
    uint64_t data = 0;  // byte i at bits 8i: one 8-byte store (a memcpy of n bytes was a third of the time)
    unsigned n = 0;
    for (; p < end; p += 2, ++n) {
        const int hi = hexDigit(p[0]), lo = hexDigit(p[1]);
        if ((hi | lo) < 0) return false;
        data |= uint64_t((hi << 4) | lo) << (8 * n);
    }
    f.id = id;
    if (extended) f.flags |= CanFrame::Extended;
    f.len = static_cast<uint8_t>(n);
    for (unsigned i = 0; i < 8; ++i) f.data[i] = static_cast<uint8_t>(data >> (8 * i));
    f.timestampNs = seconds * 1'000'000'000 + fraction * kScale[fractionDigits];
    f.bus = busIndex(iface);
    return true;
}

CandumpReader::LineResult CandumpReader::parseLine(std::string_view line, CanFrame& f) {
    if (parsePlainLogLine(line, f)) return LineResult::Frame;
    line = trimmed(line);
    if (line.empty() || line.front() == '#' || line.front() == ';') return LineResult::Skip;
    Tokens tokens(line);
    if (line.front() == '(') {
        const size_t close = line.find(')');
        if (close == std::string_view::npos) return bad(QStringLiteral("timestamp without ')'"));
        const auto ts = parseDecimalNs(line.substr(1, close - 1), 1000000000);
        if (!ts)
            return bad(
                QStringLiteral("bad timestamp '%1'").arg(QLatin1StringView(line.data() + 1, qsizetype(close - 1))));
        f.timestampNs = *ts;
        tokens = Tokens(line.substr(close + 1));
    }
    const std::string_view iface = tokens.next();
    if (iface.empty()) return bad(QStringLiteral("missing interface name"));
    const Tokens afterIface = tokens;
    const std::string_view second = tokens.next();  // one scan of the token, not peek() then next()
    if (std::memchr(second.data(), '#', second.size())) {
        f.bus = busIndex(iface);
        return parseLogForm(second, tokens, f);
    }
    if (second.empty())
        return bad(QStringLiteral("expected an identifier after '%1'")
                       .arg(QLatin1StringView(iface.data(), qsizetype(iface.size()))));
    tokens = afterIface;
    f.bus = busIndex(iface);
    return parseTextForm(tokens, f);
}

CandumpReader::LineResult CandumpReader::parseLogForm(std::string_view p, Tokens& rest, CanFrame& f) {
    const size_t hash = p.find('#');
    QString why;
    if (!parseId(p.substr(0, hash), f, &why)) return bad(why);
    std::string_view d = p.substr(hash + 1);
    size_t maxLen = 8;
    if (!d.empty() && d.front() == '#') {  // FD: ##<flags><data>
        if (d.size() < 2) return bad(QStringLiteral("CAN FD frame needs a flags digit after ##"));
        const int fl = hexDigit(d[1]);
        if (fl < 0) return bad(QStringLiteral("CAN FD flags digit is not hexadecimal"));
        f.flags |= CanFrame::Fd;
        if (fl & 1) f.flags |= CanFrame::BitRateSwitch;
        if (fl & 2) f.flags |= CanFrame::ErrorState;
        d.remove_prefix(2);
        maxLen = 64;
    } else if (!d.empty() && (d.front() == 'R' || d.front() == 'r')) {
        f.flags |= CanFrame::Remote;
        d.remove_prefix(1);
        if (!d.empty()) {
            const int dlc = hexDigit(d.front());
            if (dlc < 0 || dlc > 8) return bad(QStringLiteral("remote frame length must be 0-8"));
            f.len = static_cast<uint8_t>(dlc);
        }
        d = {};
    }
    size_t n = 0;
    for (size_t i = 0; i < d.size();) {
        if (d[i] == '.') {
            ++i;
            continue;
        }
        if (d[i] == '_') break;  // len8_dlc suffix "_9": the payload ends here
        if (i + 1 >= d.size()) return bad(QStringLiteral("odd number of hex digits in data"));
        const int hi = hexDigit(d[i]), lo = hexDigit(d[i + 1]);
        if (hi < 0 || lo < 0) return bad(QStringLiteral("data is not hexadecimal"));
        if (n >= maxLen) return bad(QStringLiteral("more than %1 data bytes").arg(maxLen));
        f.data[n++] = static_cast<uint8_t>((hi << 4) | lo);
        i += 2;
    }
    if (!f.isRemote()) {
        // FD lengths that are not DLC lengths (e.g. 23) do occur in real candump files: kept.
        f.len = static_cast<uint8_t>(n);
    }
    const std::string_view dir = rest.next();
    if (dir == "T") f.flags |= CanFrame::Tx;
    else if (!dir.empty() && dir != "R") return bad(QStringLiteral("unexpected text after the frame"));
    return LineResult::Frame;
}

CandumpReader::LineResult CandumpReader::parseTextForm(Tokens& tokens, CanFrame& f) {
    std::string_view t = tokens.next();
    if (t == "TX" || t == "RX") {  // candump -x: "TX - -" / "RX B E"
        if (t == "TX") f.flags |= CanFrame::Tx;
        for (int i = 0; i < 2 && tokens.peek().size() == 1; ++i) {
            const std::string_view m = tokens.next();
            if (m == "B") f.flags |= CanFrame::BitRateSwitch;
            if (m == "E") f.flags |= CanFrame::ErrorState;
        }
        t = tokens.next();
    }
    QString why;
    if (!parseId(t, f, &why)) return bad(why);
    const std::string_view lenTok = tokens.next();
    if (lenTok.size() < 3 || lenTok.front() != '[' || lenTok.back() != ']')
        return bad(QStringLiteral("expected [LEN] after the identifier"));
    const std::string_view digits = lenTok.substr(1, lenTok.size() - 2);
    const auto len = parseDec(digits);
    if (!len || *len > 64)
        return bad(QStringLiteral("bad length '%1'").arg(QLatin1StringView(lenTok.data(), qsizetype(lenTok.size()))));
    // candump prints FD lengths with two digits ("[08]", lib.c), classic ones with one.
    // Odd FD lengths such as [23] occur in real files (older kernels/tools): kept as they are.
    if (digits.size() == 2 || *len > 8) f.flags |= CanFrame::Fd;
    f.len = static_cast<uint8_t>(*len);
    if (f.flags & (CanFrame::BitRateSwitch | CanFrame::ErrorState)) f.flags |= CanFrame::Fd;
    if (tokens.peek() == "remote") {
        f.flags |= CanFrame::Remote;
        return LineResult::Frame;
    }
    for (uint32_t i = 0; i < *len; ++i) {
        const std::string_view b = tokens.next();
        const auto v = parseHexByte(b);
        if (!v) {
            if (b.empty()) return bad(QStringLiteral("%1 data bytes announced, %2 found").arg(*len).arg(i));
            return bad(QStringLiteral("data byte %1 is not hexadecimal").arg(i + 1));
        }
        f.data[i] = *v;
    }
    // Anything after the data is candump's annotation (ASCII dump with -a, "ERRORFRAME"...).
    return LineResult::Frame;
}

void CandumpWriter::writeFrame(const CanFrame& frame, const QString&) {
    out().append(formatCandumpL(frame, busName(frame.bus)).toLatin1());
    out().append('\n');
}

}  // namespace coscope::logio
