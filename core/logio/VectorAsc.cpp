// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/VectorAsc.h"

#include "core/logio/CaptureGapText.h"
#include "core/logio/TextScan.h"

#include <QTimeZone>

#include <cstdio>

namespace coscope::logio {

namespace {
const char* const kMonths[] = {"jan", "feb", "mar", "apr", "may", "jun", "jul", "aug", "sep", "oct", "nov", "dec"};
const char* const kWeekdays[] = {"Mon", "Tue", "Wed", "Thu", "Fri", "Sat", "Sun"};
const char* const kMonthNames[] = {"Jan", "Feb", "Mar", "Apr", "May", "Jun", "Jul", "Aug", "Sep", "Oct", "Nov", "Dec"};

int monthOf(std::string_view t) {
    if (t.size() < 3) return 0;
    const std::string_view m = t.substr(0, 3);
    for (int i = 0; i < 12; ++i)
        if (equalsNoCase(m, kMonths[i])) return i + 1;
    // German abbreviations CANoe writes on German Windows.
    if (equalsNoCase(m, "mrz") || startsWithNoCase(t, "m\xc3\xa4r") || startsWithNoCase(t, "m\xe4r")) return 3;
    if (equalsNoCase(m, "mai")) return 5;
    if (equalsNoCase(m, "okt")) return 10;
    if (equalsNoCase(m, "dez")) return 12;
    return 0;
}
}  // namespace

QDateTime parseAscDate(std::string_view text) {
    Tokens tokens(text);
    int year = 0, month = 0, day = 0, h = -1, m = 0, s = 0, ms = 0;
    bool pm = false, am = false;
    for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next()) {
        if (t.find(':') != std::string_view::npos) {
            int parts[3] = {0, 0, 0};
            int idx = 0;
            size_t i = 0;
            for (; i < t.size() && t[i] != '.'; ++i) {
                if (t[i] == ':') {
                    if (++idx > 2) break;
                    continue;
                }
                if (t[i] < '0' || t[i] > '9') return {};
                if (parts[idx] > 9999) return {};  // no clock field has that many digits (and no int overflow)
                parts[idx] = parts[idx] * 10 + (t[i] - '0');
            }
            h = parts[0], m = parts[1], s = parts[2];
            if (i < t.size() && t[i] == '.') {
                int scale = 100;
                for (++i; i < t.size() && scale; ++i, scale /= 10) ms += (t[i] - '0') * scale;
            }
        } else if (equalsNoCase(t, "pm")) {
            pm = true;
        } else if (equalsNoCase(t, "am")) {
            am = true;
        } else if (auto v = parseDec(t)) {
            if (t.size() == 4) year = int(*v);
            else if (t.size() <= 2) day = int(*v);
        } else if (int mo = monthOf(t)) {
            if (!month) month = mo;
        }
    }
    if (h < 0 || year < 1900 || year > 2200 || !month || !day) return {};
    if (pm && h < 12) h += 12;
    if (am && h == 12) h = 0;
    QDateTime dt(QDate(year, month, day), QTime(h, m, s, ms));
    return dt.isValid() ? dt : QDateTime();
}

QByteArray formatAscDate(const QDateTime& t) {
    // python-can's FORMAT_DATE "%a %b %d %I:%M:%S.mmm %p %Y"; English names regardless of locale.
    const QDate d = t.date();
    const QTime tm = t.time();
    int h12 = tm.hour() % 12;
    if (h12 == 0) h12 = 12;
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s %s %02d %02d:%02d:%02d.%03d %s %04d", kWeekdays[d.dayOfWeek() - 1],
                  kMonthNames[d.month() - 1], d.day(), h12, tm.minute(), tm.second(), tm.msec(),
                  tm.hour() < 12 ? "AM" : "PM", d.year());
    return QByteArray(buf);
}

AscReader::LineResult AscReader::bad(const QString& message) {
    warn(lineNumber(), message);
    return LineResult::Bad;
}

bool AscReader::parseId(std::string_view t, CanFrame& f) const {
    if (!t.empty() && (t.back() == 'x' || t.back() == 'X')) {
        f.flags |= CanFrame::Extended;
        t.remove_suffix(1);
    }
    const auto v = hex_ ? parseHex(t) : parseDec(t);
    if (!v) return false;
    if (*v > (f.isExtended() ? 0x1FFFFFFFU : 0x7FFU)) {
        if (*v > 0x1FFFFFFFU) return false;
        f.flags |= CanFrame::Extended;  // an 11-bit overflow can only be a 29-bit id without 'x'
    }
    f.id = *v;
    return true;
}

bool AscReader::parseByte(std::string_view t, uint8_t& out) const {
    if (hex_) {
        const auto v = parseHex(t);
        if (!v || *v > 0xFF || t.size() > 2) return false;
        out = uint8_t(*v);
    } else {
        const auto v = parseDec(t);
        if (!v || *v > 0xFF) return false;
        out = uint8_t(*v);
    }
    return true;
}

AscReader::LineResult AscReader::parseLine(std::string_view line, CanFrame& f) {
    line = trimmed(line);
    if (line.empty()) return LineResult::Skip;
    if (line.substr(0, 2) == "//") {
        noteGapComment(line.substr(2));
        return LineResult::Skip;
    }
    const char c0 = line.front();
    if (!(c0 >= '0' && c0 <= '9')) {
        Tokens tokens(line);
        const std::string_view key = tokens.next();
        if (equalsNoCase(key, "date")) {
            const QDateTime dt = parseAscDate(tokens.rest());
            if (!dt.isValid()) return bad(QStringLiteral("cannot read the date; times are relative to the start"));
            if (!start_.isValid()) {
                start_ = dt;
                startNs_ = dt.toMSecsSinceEpoch() * 1000000;
            }
        } else if (equalsNoCase(key, "base")) {
            for (std::string_view t = tokens.next(); !t.empty(); t = tokens.next()) {
                if (equalsNoCase(t, "hex")) hex_ = true;
                else if (equalsNoCase(t, "dec")) hex_ = false;
                else if (equalsNoCase(t, "relative")) relative_ = true;
                else if (equalsNoCase(t, "absolute")) relative_ = false;
            }
        } else if (equalsNoCase(key, "begin") && equalsNoCase(tokens.next(), "triggerblock")) {
            // The trigger block's time is the start of the measurement the times refer to.
            const QDateTime dt = parseAscDate(tokens.rest());
            if (dt.isValid()) {
                start_ = dt;
                startNs_ = dt.toMSecsSinceEpoch() * 1000000;
            }
            lastNs_ = 0;
        }
        return LineResult::Skip;  // End Triggerblock, "internal events logged", other keywords
    }

    Tokens tokens(line);
    const std::string_view tsTok = tokens.next();
    const auto ts = parseDecimalNs(tsTok, 1000000000);
    if (!ts) return LineResult::Skip;  // not an event line
    const int64_t rel = relative_ ? addNs(lastNs_, *ts) : *ts;
    lastNs_ = rel;
    f.timestampNs = addNs(startNs_, rel);

    const std::string_view chTok = tokens.next();
    if (chTok == "CANFD") return parseCanFd(tokens, f);
    const auto ch = parseDec(chTok);
    if (!ch) return LineResult::Skip;  // "CAN 1 Status:...", "Start of measurement", ...
    const std::string_view what = tokens.next();
    if (equalsNoCase(what, "ErrorFrame")) {
        f.bus = busChannel(*ch);
        f.flags |= CanFrame::Error;
        return LineResult::Frame;
    }
    const std::string_view dir = tokens.next();
    const bool isRx = dir == "Rx", isTx = dir == "Tx";
    if (!isRx && !isTx) return LineResult::Skip;  // Statistic:, J1939TP, other events
    if (!parseId(what, f))
        return bad(QStringLiteral("bad identifier '%1'").arg(QLatin1StringView(what.data(), qsizetype(what.size()))));
    f.bus = busChannel(*ch);
    if (isTx) f.flags |= CanFrame::Tx;
    const std::string_view type = tokens.next();
    if (type == "r" || type == "R") {
        f.flags |= CanFrame::Remote;
        if (const auto dlc = hexDigit(tokens.peek().size() == 1 ? tokens.peek()[0] : 'x'); dlc >= 0 && dlc <= 8)
            f.len = uint8_t(dlc);
        return LineResult::Frame;
    }
    if (type != "d" && type != "D") return bad(QStringLiteral("expected 'd' or 'r' after the direction"));
    const std::string_view dlcTok = tokens.next();
    const auto dlc = dlcTok.size() == 1 ? std::optional<uint32_t>(hexDigit(dlcTok[0])) : std::nullopt;
    if (!dlc || int(*dlc) < 0)
        return bad(QStringLiteral("bad DLC '%1'").arg(QLatin1StringView(dlcTok.data(), qsizetype(dlcTok.size()))));
    // DLC 9..15 on classic CAN still carries 8 bytes (ISO 11898-1).
    f.len = uint8_t(std::min<uint32_t>(*dlc, 8));
    for (int i = 0; i < f.len; ++i) {
        const std::string_view b = tokens.next();
        if (!parseByte(b, f.data[size_t(i)]))
            return bad(b.empty() ? QStringLiteral("DLC %1 but only %2 data bytes").arg(f.len).arg(i)
                                 : QStringLiteral("data byte %1 is not valid").arg(i + 1));
    }
    return LineResult::Frame;
}

AscReader::LineResult AscReader::parseCanFd(Tokens& tokens, CanFrame& f) {
    const auto ch = parseDec(tokens.next());
    if (!ch) return bad(QStringLiteral("CANFD line without a channel number"));
    f.bus = busChannel(*ch);
    const std::string_view dir = tokens.next();
    if (dir == "Tx") f.flags |= CanFrame::Tx;
    else if (dir != "Rx") return bad(QStringLiteral("CANFD line: expected Rx or Tx"));
    const std::string_view idTok = tokens.next();
    if (equalsNoCase(idTok, "ErrorFrame")) {
        f.flags |= CanFrame::Error;
        return LineResult::Frame;
    }
    if (!parseId(idTok, f))
        return bad(QStringLiteral("bad identifier '%1'").arg(QLatin1StringView(idTok.data(), qsizetype(idTok.size()))));
    std::string_view brs = tokens.next();
    if (brs != "0" && brs != "1") brs = tokens.next();  // a symbolic name came first
    const std::string_view esi = tokens.next();
    const std::string_view dlcTok = tokens.next();
    const auto dataLen = parseDec(tokens.next());
    if ((brs != "0" && brs != "1") || (esi != "0" && esi != "1") || dlcTok.size() != 1 || hexDigit(dlcTok[0]) < 0 ||
        !dataLen || *dataLen > 64)
        return bad(QStringLiteral("CANFD line: expected BRS ESI DLC LENGTH"));
    f.flags |= CanFrame::Fd;
    if (brs == "1") f.flags |= CanFrame::BitRateSwitch;
    if (esi == "1") f.flags |= CanFrame::ErrorState;
    f.len = uint8_t(*dataLen);
    for (uint32_t i = 0; i < *dataLen; ++i) {
        const std::string_view b = tokens.next();
        if (!parseByte(b, f.data[i])) return bad(QStringLiteral("CANFD data byte %1 is not valid").arg(i + 1));
    }
    // A CANFD line with length 0 but a DLC is a remote frame of classic CAN (as python-can reads
    // it); the flags column after the data is not reliable enough across writers to decide more.
    if (*dataLen == 0 && hexDigit(dlcTok[0]) > 0) {
        f.flags &= uint8_t(~(CanFrame::Fd | CanFrame::BitRateSwitch | CanFrame::ErrorState));
        f.flags |= CanFrame::Remote;
        f.len = uint8_t(std::min(hexDigit(dlcTok[0]), 8));
        return LineResult::Frame;
    }
    if (f.isFd() && !isValidFdLength(f.len)) return bad(QStringLiteral("%1 bytes is not a CAN FD length").arg(f.len));
    if (!f.isFd() && f.len > 8) return bad(QStringLiteral("classic frame with more than 8 bytes"));
    return LineResult::Frame;
}

// ---- writer

void AscWriter::writeHeader(const CanFrame* first) {
    const int64_t firstNs = first ? first->timestampNs : 0;
    const int64_t ms = firstNs >= 0 ? firstNs / 1000000 : -((-firstNs + 999999) / 1000000);
    startNs_ = ms * 1000000;
    const QByteArray date = formatAscDate(QDateTime::fromMSecsSinceEpoch(ms));
    out() += "date " + date + "\n";
    out() += "base hex  timestamps absolute\n";
    out() += "internal events logged\n";
    out() += "// version 9.0.0\n";
    out() += "Begin Triggerblock " + date + "\n";
    out() += "   0.000000 Start of measurement\n";
}

void AscWriter::writeFrame(const CanFrame& f, const QString&) {
    const int64_t rel = std::max<int64_t>(0, f.timestampNs - startNs_);
    char ts[40];
    std::snprintf(ts, sizeof ts, "%11lld.%06lld ", static_cast<long long>(rel / 1000000000),
                  static_cast<long long>((rel % 1000000000) / 1000));
    QByteArray& o = out();
    o += ts;
    const int ch = f.bus + 1;
    if (f.isError()) {
        o += QByteArray::number(ch) + "  ErrorFrame\n";
        return;
    }
    QByteArray id;
    appendHex(id, f.id, 1);
    if (f.isExtended()) id += 'x';
    const char* dir = f.isTx() ? "Tx" : "Rx";
    if (f.isFd()) {
        const int dlc = f.len <= 8    ? f.len
                        : f.len <= 24 ? 9 + (f.len - 12) / 4
                        : f.len == 32 ? 13
                        : f.len == 48 ? 14
                                      : 15;
        uint32_t flags = 0x1000;
        if (f.flags & CanFrame::BitRateSwitch) flags |= 0x2000;
        if (f.flags & CanFrame::ErrorState) flags |= 0x4000;
        o += "CANFD " + QByteArray::number(ch).rightJustified(3) + ' ' + QByteArray(dir).leftJustified(4) + ' ' +
             id.rightJustified(8) + "  " + QByteArray(32, ' ') + ' ' +
             ((f.flags & CanFrame::BitRateSwitch) ? '1' : '0') + ' ' + ((f.flags & CanFrame::ErrorState) ? '1' : '0') +
             ' ';
        appendHex(o, uint32_t(dlc), 1);
        o += ' ' + QByteArray::number(f.len).rightJustified(2);
        for (int i = 0; i < f.len; ++i) {
            o += ' ';
            appendHex2(o, f.data[size_t(i)]);
        }
        o += "        0    0 ";
        QByteArray fl;
        appendHex(fl, flags, 1);
        o += fl.rightJustified(8) + "        0        0        0        0        0\n";
        return;
    }
    o += QByteArray::number(ch) + "  " + id.leftJustified(15) + ' ' + QByteArray(dir).leftJustified(4) + ' ';
    o += f.isRemote() ? "r " : "d ";
    appendHex(o, f.len, 1);
    if (!f.isRemote())
        for (int i = 0; i < f.len; ++i) {
            o += ' ';
            appendHex2(o, f.data[size_t(i)]);
        }
    o += '\n';
}

void AscWriter::writeGap(int64_t lostNs, int64_t backNs) { out() += "// " + captureGapText(lostNs, backNs) + '\n'; }

void AscWriter::writeFooter() { out() += "End TriggerBlock\n"; }

}  // namespace coscope::logio
