// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/BusmasterLog.h"

#include "core/logio/CsvScan.h"

#include <QDateTime>

namespace coscope::logio {

namespace {
constexpr int64_t kNsPerMs = 1000000;
constexpr int64_t kNsPerDay = 86400LL * 1000 * kNsPerMs;

// "h:m:s:x" with up to `parts` numbers separated by ':'.
bool splitColon(std::string_view t, uint32_t* out, int parts) {
    for (int i = 0; i < parts; ++i) {
        const size_t colon = i + 1 < parts ? t.find(':') : std::string_view::npos;
        if (i + 1 < parts && colon == std::string_view::npos) return false;
        const auto v = parseDec(t.substr(0, colon));
        if (!v) return false;
        out[i] = *v;
        if (colon != std::string_view::npos) t.remove_prefix(colon + 1);
    }
    return true;
}
}  // namespace

BusmasterReader::LineResult BusmasterReader::bad(const QString& message) {
    warn(lineNumber(), message);
    return LineResult::Bad;
}

void BusmasterReader::headerLine(std::string_view t) {
    if (t == "HEX") decimal_ = false;
    else if (t == "DEC") decimal_ = true;
    else if (t == "SYSTEM MODE") mode_ = TimeMode::System;
    else if (t == "ABSOLUTE MODE") mode_ = TimeMode::Absolute;
    else if (t == "RELATIVE MODE") mode_ = TimeMode::Relative;
    else if (startsWithNoCase(t, "START DATE AND TIME ")) {
        // "d:m:yyyy h:m:s:ms" (SavvyCAN's sample "8:8:2014 11:49:7:965").
        Tokens tok(t.substr(20));
        uint32_t d[3], tm[4];
        const std::string_view dateText = tok.next(), timeText = tok.next();
        if (!splitColon(dateText, d, 3) || !splitColon(timeText, tm, 4)) {
            warn(lineNumber(), QStringLiteral("cannot read the start date; times are relative to midnight"));
            return;
        }
        const QDate date{int(d[2]), int(d[1]), int(d[0])};
        if (timeText.size() - timeText.rfind(':') - 1 >= 4) tm[3] /= 10;  // tenths of a millisecond
        const QTime time{int(tm[0]), int(tm[1]), int(tm[2]), int(tm[3])};
        if (!date.isValid() || !time.isValid() || d[2] < 1970 || d[2] > 2200) {
            warn(lineNumber(), QStringLiteral("start date or time out of range; times are relative to midnight"));
            return;
        }
        midnightNs_ = QDateTime(date, QTime(0, 0)).toMSecsSinceEpoch() * kNsPerMs;
        startNs_ = QDateTime(date, time).toMSecsSinceEpoch() * kNsPerMs;
        lastTimeNs_ = -1;
        dayOffsetNs_ = 0;
        relativeNs_ = startNs_;
    }
}

bool BusmasterReader::parseNumber(std::string_view t, uint32_t& v, bool isId) const {
    std::optional<uint32_t> r;
    if (startsWithNoCase(t, "0x")) r = parseHex(t.substr(2));
    else if (decimal_) r = t.size() <= 9 ? parseDec(t) : std::nullopt;
    else r = parseHex(t);
    if (!r || (!isId && *r > 255)) return false;
    v = *r;
    return true;
}

BusmasterReader::LineResult BusmasterReader::parseLine(std::string_view line, CanFrame& f) {
    line = trimmed(line);
    if (line.empty()) return LineResult::Skip;
    if (line.size() >= 6 && line.substr(0, 3) == "***" && line.substr(line.size() - 3) == "***") {
        headerLine(trimmed(line.substr(3, line.size() - 6)));
        return LineResult::Skip;
    }
    Tokens tok(line);
    const std::string_view timeText = tok.next();
    uint32_t tm[4];
    if (!splitColon(timeText, tm, 4) || tm[0] > 999999 || tm[1] > 59 || tm[2] > 59 || tm[3] > 9999)
        return bad(QStringLiteral("bad time %1, expected h:m:s:tttt").arg(quoted(timeText)));
    // The last field is milliseconds when it has up to three digits ("22:20:14:992", BUSMASTER
    // 3.x and SavvyCAN's export), tenths of a millisecond when it has four ("11:49:28:3010").
    const size_t lastColon = timeText.rfind(':');
    const bool tenths = timeText.size() - lastColon - 1 >= 4;
    if (!tenths && tm[3] > 999) return bad(QStringLiteral("bad time %1, expected h:m:s:ms").arg(quoted(timeText)));
    const int64_t timeNs =
        ((int64_t(tm[0]) * 60 + tm[1]) * 60 + tm[2]) * 1000 * kNsPerMs + int64_t(tm[3]) * (tenths ? 100000 : kNsPerMs);
    const std::string_view dir = tok.next();
    if (equalsNoCase(dir, "tx")) f.flags |= CanFrame::Tx;
    else if (!equalsNoCase(dir, "rx")) return bad(QStringLiteral("direction %1 is not Tx or Rx").arg(quoted(dir)));
    const auto channel = parseDec(tok.next());
    if (!channel) return bad(QStringLiteral("bad channel number"));
    f.bus = busChannel(*channel);
    const std::string_view idText = tok.next();
    uint32_t id = 0;
    if (!parseNumber(idText, id, true) || id > 0x1FFFFFFFU)
        return bad(QStringLiteral("bad identifier %1").arg(quoted(idText)));
    f.id = id;
    const std::string_view type = tok.next();
    if (equalsNoCase(type, "x") || equalsNoCase(type, "xr")) f.flags |= CanFrame::Extended;
    else if (!equalsNoCase(type, "s") && !equalsNoCase(type, "sr"))
        return bad(QStringLiteral("type %1 is not s, x, sr or xr").arg(quoted(type)));
    if (type.size() == 2) f.flags |= CanFrame::Remote;
    if (!f.isExtended() && f.id > 0x7FF) return bad(QStringLiteral("11-bit identifier above 7FF"));
    const auto dlc = parseDec(tok.next());
    if (!dlc || *dlc > 64 || (*dlc > 8 && (f.isRemote() || !isValidFdLength(int(*dlc)))))
        return bad(QStringLiteral("bad DLC"));
    if (*dlc > 8) f.flags |= CanFrame::Fd;
    f.len = uint8_t(*dlc);
    for (int i = 0; i < f.payloadSize(); ++i) {
        const std::string_view b = tok.next();
        uint32_t v = 0;
        if (!parseNumber(b, v, false))
            return bad(b.empty() ? QStringLiteral("DLC %1 but only %2 data bytes").arg(f.len).arg(i)
                                 : QStringLiteral("data byte %1 %2 is not a byte").arg(i + 1).arg(quoted(b)));
        f.data[size_t(i)] = uint8_t(v);
    }
    switch (mode_) {
    case TimeMode::System:
        // Time of day: a jump back by more than 12 h is midnight passing.
        if (lastTimeNs_ >= 0 && timeNs + kNsPerDay / 2 < lastTimeNs_) dayOffsetNs_ = addNs(dayOffsetNs_, kNsPerDay);
        lastTimeNs_ = timeNs;
        f.timestampNs = addNs(addNs(midnightNs_, dayOffsetNs_), timeNs);
        break;
    case TimeMode::Absolute: f.timestampNs = addNs(startNs_, timeNs); break;
    case TimeMode::Relative:
        relativeNs_ = addNs(relativeNs_, timeNs);
        f.timestampNs = relativeNs_;
        break;
    }
    return LineResult::Frame;
}

}  // namespace coscope::logio
