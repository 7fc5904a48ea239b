// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/od/NumberText.h"

#include <QStringList>

namespace coscope::od {

namespace {

std::optional<std::uint64_t> digits(QStringView s, int base) {
    if (s.isEmpty()) return std::nullopt;
    std::uint64_t v = 0;
    for (QChar c : s) {
        int d = -1;
        const char16_t u = c.unicode();
        if (u >= '0' && u <= '9') d = u - '0';
        else if (u >= 'a' && u <= 'f') d = u - 'a' + 10;
        else if (u >= 'A' && u <= 'F') d = u - 'A' + 10;
        if (d < 0 || d >= base) return std::nullopt;
        if (v > (UINT64_MAX - static_cast<std::uint64_t>(d)) / static_cast<std::uint64_t>(base))
            return std::nullopt;  // overflow
        v = v * static_cast<std::uint64_t>(base) + static_cast<std::uint64_t>(d);
    }
    return v;
}

}  // namespace

std::optional<ParsedInteger> parseIntegerText(const QString& text, TextStyle style) {
    QStringView s = QStringView(text).trimmed();
    ParsedInteger r;
    if (s.startsWith(u'-')) {
        r.negative = true;
        s = s.mid(1);
    } else if (s.startsWith(u'+')) {
        s = s.mid(1);
    }
    std::optional<std::uint64_t> v;
    if (s.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)) {
        v = digits(s.mid(2), 16);
        r.hex = true;
    } else if (style == TextStyle::Person && s.startsWith(QLatin1String("0b"), Qt::CaseInsensitive)) {
        v = digits(s.mid(2), 2);
    } else if (style != TextStyle::Eds && s.size() > 1 && (s.back() == u'h' || s.back() == u'H')) {
        v = digits(s.chopped(1), 16);  // CiA 301's way: "1Fh"
        r.hex = true;
    } else if (style == TextStyle::Eds && s.size() > 1 && s.front() == u'0') {
        v = digits(s.mid(1), 8);
        if (!v) v = digits(s, 10);
    } else {
        v = digits(s, 10);
    }
    if (!v) return std::nullopt;
    r.magnitude = *v;
    if (r.magnitude == 0) r.negative = false;
    return r;
}

bool containsNodeId(const QString& text) { return text.contains(QLatin1String("$NODEID"), Qt::CaseInsensitive); }

std::optional<std::uint64_t> evaluateNodeIdFormula(const QString& text, std::uint8_t nodeId) {
    QString s = text;
    s.remove(u' ');
    s.remove(u'\t');
    if (s.isEmpty()) return std::nullopt;
    std::uint64_t sum = 0;
    const QStringList terms = s.split(u'+');
    for (const QString& t : terms) {
        if (t.compare(QLatin1String("$NODEID"), Qt::CaseInsensitive) == 0) {
            sum += nodeId;
            continue;
        }
        const auto n = parseIntegerText(t, TextStyle::Eds);
        if (!n || n->negative) return std::nullopt;
        sum += n->magnitude;
    }
    return sum;
}

}  // namespace coscope::od
