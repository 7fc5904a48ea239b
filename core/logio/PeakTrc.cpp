// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/PeakTrc.h"

#include <linux/can/error.h>

#include <algorithm>
#include <iterator>

#include "core/logio/CaptureGapText.h"

#include <QDateTime>

#include <cstdio>

namespace coscope::logio {

namespace {
constexpr int64_t kNsPerDay = 86400LL * 1000000000LL;
constexpr int64_t kOleEpochDays = 25569;  // 1899-12-30 .. 1970-01-01

// Offset of local time from UTC in ns at (roughly) the given local time.
int64_t localOffsetNs(int64_t utcNs) {
    const QDateTime dt = QDateTime::fromMSecsSinceEpoch(utcNs / 1000000);
    return int64_t(dt.offsetFromUtc()) * 1000000000LL;
}

}  // namespace

std::optional<int64_t> oleDateToNs(std::string_view t) {
    t = trimmed(t);
    const size_t dot = t.find('.');
    const auto days = parseDec(t.substr(0, dot));
    if (!days || *days > 100000) return std::nullopt;  // beyond year 2173: not a trace start
    __int128 localNs = __int128(*days) * kNsPerDay;
    if (dot != std::string_view::npos) {
        __int128 num = 0, den = 1;
        for (size_t i = dot + 1; i < t.size() && den < __int128(1000000000000000000LL); ++i) {
            if (t[i] < '0' || t[i] > '9') return std::nullopt;
            num = num * 10 + (t[i] - '0');
            den *= 10;
        }
        localNs += (num * kNsPerDay + den / 2) / den;
    }
    int64_t local = int64_t(localNs) - kOleEpochDays * kNsPerDay;
    local = (local + 500) / 1000 * 1000;  // the decimal day fraction: microsecond resolution
    return local - localOffsetNs(local);
}

QByteArray nsToOleDate(int64_t ns) {
    const int64_t local = ns + localOffsetNs(ns) + kOleEpochDays * kNsPerDay;
    const int64_t days = local / kNsPerDay;
    const __int128 rem = local % kNsPerDay;
    __int128 frac = rem * __int128(1000000000000000LL) / kNsPerDay;  // 15 decimals
    char digits[16];
    for (int i = 14; i >= 0; --i) {
        digits[i] = char('0' + int(frac % 10));
        frac /= 10;
    }
    digits[15] = 0;
    return QByteArray::number(days) + '.' + digits;
}

TrcReader::LineResult TrcReader::bad(const QString& message) {
    warn(lineNumber(), message);
    return LineResult::Bad;
}

bool TrcReader::parseId(std::string_view t, CanFrame& f) {
    const auto v = parseHex(t);
    if (!v || *v > 0x1FFFFFFFU) return false;
    f.id = *v;
    if (t.size() > 4 || *v > 0x7FF) f.flags |= CanFrame::Extended;
    return true;
}

TrcReader::LineResult TrcReader::readData(Tokens& tokens, CanFrame& f, uint32_t len) {
    if (len > (f.isFd() ? 64u : 8u)) return bad(QStringLiteral("length %1 is too long").arg(len));
    if (f.isFd() && !isValidFdLength(int(len))) return bad(QStringLiteral("%1 bytes is not a CAN FD length").arg(len));
    f.len = uint8_t(len);
    if (tokens.peek() == "RTR") {
        f.flags |= CanFrame::Remote;
        return LineResult::Frame;
    }
    if (f.isRemote() || f.isError()) return LineResult::Frame;
    for (uint32_t i = 0; i < len; ++i) {
        const std::string_view b = tokens.next();
        const auto v = parseHexByte(b);
        if (!v)
            return bad(b.empty() ? QStringLiteral("length %1 but only %2 data bytes").arg(len).arg(i)
                                 : QStringLiteral("data byte %1 is not hexadecimal").arg(i + 1));
        f.data[i] = *v;
    }
    return LineResult::Frame;
}

// An "error warning" record (PEAK CAN TRC File Format, version 1.0 "Error Warnings"; 1.1 to 1.3
// type "Warng"): ID FFFFFFFF, length 4, the driver's status as four bytes, most significant
// first, then its name ("00 00 00 08 ------BUSHEAVY"). Kept as the SocketCAN error frame the
// state means (linux/can/error.h), so the trace and the Events show it as they show a
// controller's report, instead of dropping it. Status bits of the PCAN drivers of that time
// (SJA1000 controllers): 01h transmit queue full, 02h/40h receive overrun, 04h BUSLIGHT (an
// error counter reached the warning limit), 08h BUSHEAVY (error passive), 10h BUSOFF.
TrcReader::LineResult TrcReader::readStatus(Tokens& tokens, CanFrame& f) {
    const auto len = parseDec(tokens.next());
    if (!len || *len != 4) return bad(QStringLiteral("an error warning needs length 4"));
    uint32_t status = 0;
    for (int i = 0; i < 4; ++i) {
        const auto b = parseHexByte(tokens.next());
        if (!b) return bad(QStringLiteral("error warning byte %1 is not hexadecimal").arg(i + 1));
        status = status << 8 | *b;
    }
    f.flags = CanFrame::Error;
    f.len = 8;
    std::fill(std::begin(f.data), std::end(f.data), uint8_t(0));
    if (status & 0x10) {
        f.id = CAN_ERR_BUSOFF;
        return LineResult::Frame;
    }
    f.id = CAN_ERR_CRTL;
    if (status & 0x08) f.data[1] |= CAN_ERR_CRTL_RX_PASSIVE | CAN_ERR_CRTL_TX_PASSIVE;
    else if (status & 0x04) f.data[1] |= CAN_ERR_CRTL_RX_WARNING | CAN_ERR_CRTL_TX_WARNING;
    if (status & 0x42) f.data[1] |= CAN_ERR_CRTL_RX_OVERFLOW;
    if (status & 0x01) f.data[1] |= CAN_ERR_CRTL_TX_OVERFLOW;
    if (status == 0) f.data[1] = CAN_ERR_CRTL_ACTIVE;  // "OK": back to error active
    return LineResult::Frame;
}

TrcReader::LineResult TrcReader::parseLine(std::string_view line, CanFrame& f) {
    line = trimmed(line);
    if (line.empty()) return LineResult::Skip;
    if (line.front() == ';') {
        if (line.substr(0, 14) == ";$FILEVERSION=") {
            const std::string_view v = trimmed(line.substr(14));
            const size_t dot = v.find('.');
            const auto ma = parseDec(v.substr(0, dot));
            const auto mi = dot == std::string_view::npos ? std::optional<uint32_t>(0) : parseDec(v.substr(dot + 1));
            if (!ma || !mi || *ma < 1 || *ma > 2) return bad(QStringLiteral("unknown file version"));
            major_ = int(*ma);
            minor_ = int(*mi);
            versionSeen_ = true;
        } else if (line.substr(0, 12) == ";$STARTTIME=") {
            const auto ns = oleDateToNs(line.substr(12));
            if (!ns) return bad(QStringLiteral("cannot read $STARTTIME; times are relative to the start"));
            startNs_ = *ns;
        } else if (line.substr(0, 10) == ";$COLUMNS=") {
            columns_.clear();
            for (char c : line.substr(10))
                if (c != ',' && !isSpace(c)) columns_ += c;
        } else {
            noteGapComment(line.substr(1));
        }
        return LineResult::Skip;
    }
    Tokens tokens(line);
    return major_ >= 2 ? parseV2(tokens, f) : parseV1(tokens, f);
}

TrcReader::LineResult TrcReader::parseV1(Tokens& tokens, CanFrame& f) {
    std::string_view num = tokens.next();
    if (num.empty() || num.back() != ')') return bad(QStringLiteral("expected a message number 'N)'"));
    const auto ts = parseDecimalNs(tokens.next(), 1000000);
    if (!ts) return bad(QStringLiteral("bad time offset"));
    f.timestampNs = addNs(startNs_, *ts);
    f.bus = busChannel(1);
    std::string_view t = tokens.next();
    if (minor_ >= 2) {  // 1.2+: bus number column
        const auto bus = parseDec(t);
        if (!bus) return bad(QStringLiteral("expected a bus number"));
        f.bus = busChannel(*bus);
        t = tokens.next();
    }
    if (minor_ >= 1) {  // 1.1+: message type column
        if (t == "Tx") f.flags |= CanFrame::Tx;
        else if (t == "Error") f.flags |= CanFrame::Error;
        else if (t == "Warng") {
            tokens.next();                            // ID FFFFFFFF
            if (tokens.peek() == "-") tokens.next();  // 1.3 reserved column
            return readStatus(tokens, f);
        } else if (t != "Rx") return LineResult::Skip;  // Overrun, ... other records
        t = tokens.next();
    }
    if (t == "FFFFFFFF" && minor_ == 0) return readStatus(tokens, f);  // 1.0 error warning
    if (!parseId(t, f))
        return bad(QStringLiteral("bad identifier '%1'").arg(QLatin1StringView(t.data(), qsizetype(t.size()))));
    if (tokens.peek() == "-") tokens.next();  // 1.3 reserved column
    const auto len = parseDec(tokens.next());
    if (!len) return bad(QStringLiteral("bad data length"));
    return readData(tokens, f, *len);
}

TrcReader::LineResult TrcReader::parseV2(Tokens& tokens, CanFrame& f) {
    const std::string_view cols = columns_.empty()
                                      ? (minor_ == 0 ? std::string_view("NOTIdlD") : std::string_view("NOTBIdRLD"))
                                      : std::string_view(columns_);
    f.bus = busChannel(1);
    std::string_view type;
    int dlc = -1;
    int len = -1;
    for (char c : cols) {
        if (c == 'D') break;  // the data is the rest of the line
        const std::string_view t = tokens.next();
        if (t.empty()) return bad(QStringLiteral("line ends before column '%1'").arg(QLatin1Char(c)));
        switch (c) {
        case 'O': {
            const auto ts = parseDecimalNs(t, 1000000);
            if (!ts) return bad(QStringLiteral("bad time offset"));
            f.timestampNs = addNs(startNs_, *ts);
            break;
        }
        case 'T':
            type = t;
            if (type == "ER") f.flags |= CanFrame::Error;
            else if (type == "RR") f.flags |= CanFrame::Remote;
            else if (type == "FD" || type == "FB" || type == "FE" || type == "BI") {
                f.flags |= CanFrame::Fd;
                if (type == "FB" || type == "BI") f.flags |= CanFrame::BitRateSwitch;
                if (type == "FE" || type == "BI") f.flags |= CanFrame::ErrorState;
            } else if (type != "DT") {
                return LineResult::Skip;  // ST status, EC error counters, EV events
            }
            break;
        case 'B': {
            const auto bus = parseDec(t);
            if (!bus) return bad(QStringLiteral("bad bus number"));
            f.bus = busChannel(*bus);
            break;
        }
        case 'I':
            if (f.isError() && t == "-") break;
            if (!parseId(t, f))
                return bad(QStringLiteral("bad identifier '%1'").arg(QLatin1StringView(t.data(), qsizetype(t.size()))));
            break;
        case 'd':
            if (t == "Tx") f.flags |= CanFrame::Tx;
            break;
        case 'L': {
            const auto v = parseDec(t);
            if (!v || *v > 15) return bad(QStringLiteral("bad DLC"));
            dlc = int(*v);
            break;
        }
        case 'l': {
            const auto v = parseDec(t);
            if (!v || *v > 64) return bad(QStringLiteral("bad data length"));
            len = int(*v);
            break;
        }
        default: break;  // N number, R reserved, unknown columns
        }
    }
    if (type.empty()) return bad(QStringLiteral("no message type column"));
    if (f.isError()) {
        f.id = 0;
        f.len = 0;
        return LineResult::Frame;
    }
    if (len < 0) len = f.isFd() ? fdDlcToLength(dlc) : std::min(dlc, 8);
    if (len < 0) return bad(QStringLiteral("no data length"));
    if (f.isRemote()) {
        f.len = uint8_t(std::min(len, 8));
        return LineResult::Frame;
    }
    return readData(tokens, f, uint32_t(len));
}

// ---- writer

void TrcWriter::writeHeader(const CanFrame* first) {
    const int64_t firstNs = first ? first->timestampNs : 0;
    startNs_ = (firstNs >= 0 ? firstNs / 1000000 : -((-firstNs + 999999) / 1000000)) * 1000000;
    QByteArray& o = out();
    o += ";$FILEVERSION=2.1\r\n";
    o += ";$STARTTIME=" + nsToOleDate(startNs_) + "\r\n";
    o += ";$COLUMNS=N,O,T,B,I,d,R,L,D\r\n";
    o += ";\r\n";
    o += ";   Start time: " +
         QDateTime::fromMSecsSinceEpoch(startNs_ / 1000000)
             .toString(QStringLiteral("dd.MM.yyyy hh:mm:ss.zzz"))
             .toLatin1() +
         "\r\n";
    o += ";   Generated by CoScope\r\n";
    o += ";-------------------------------------------------------------------------------\r\n";
    o += ";   Message   Time    Type    ID     Rx/Tx\r\n";
    o += ";   Number    Offset  |  Bus  [hex]  |  Reserved\r\n";
    o += ";   |         [ms]    |  |    |      |  |  Data Length Code\r\n";
    o += ";   |         |       |  |    |      |  |  |    Data [hex] ...\r\n";
    o += ";   |         |       |  |    |      |  |  |    |\r\n";
    o += ";---+-- ------+------ +- +- --+----- +- +- +--- +- -- -- -- -- -- -- --\r\n";
}

void TrcWriter::writeGap(int64_t lostNs, int64_t backNs) { out() += "; " + captureGapText(lostNs, backNs) + "\r\n"; }

void TrcWriter::writeFrame(const CanFrame& f, const QString&) {
    const int64_t rel = f.timestampNs - startNs_;
    char head[64];
    const long long relUs = static_cast<long long>(rel / 1000);
    std::snprintf(head, sizeof head, "%7llu %9lld.%03lld ", static_cast<unsigned long long>(frameNumber()),
                  relUs / 1000, (relUs < 0 ? -relUs : relUs) % 1000);
    QByteArray& o = out();
    o += head;
    const char* type = "DT";
    if (f.isError()) type = "ER";
    else if (f.isRemote()) type = "RR";
    else if (f.isFd()) {
        const bool brs = f.flags & CanFrame::BitRateSwitch, esi = f.flags & CanFrame::ErrorState;
        type = brs && esi ? "BI" : brs ? "FB" : esi ? "FE" : "FD";
    }
    o += type;
    o += ' ' + QByteArray::number(f.bus + 1).rightJustified(2) + ' ';
    QByteArray id;
    if (f.isError()) id = "-";
    else appendHex(id, f.id, f.isExtended() ? 8 : 4);
    o += id.rightJustified(8) + (f.isTx() ? " Tx" : " Rx") + " -  ";
    const int dlc = f.isError() ? 0 : f.isFd() ? fdLengthToDlc(f.len) : f.len;
    o += QByteArray::number(dlc).leftJustified(4);
    if (!f.isRemote() && !f.isError())
        for (int i = 0; i < f.len; ++i) {
            o += ' ';
            appendHex2(o, f.data[size_t(i)]);
        }
    o += "\r\n";
}

}  // namespace coscope::logio
