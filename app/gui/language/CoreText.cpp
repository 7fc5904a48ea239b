// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/language/CoreText.h"

#include "app/gui/language/CoreTextLists.h"
#include "app/gui/language/Language.h"

#include <QCoreApplication>
#include <QHash>
#include <QRegularExpression>

#include <algorithm>
#include <vector>

namespace coscope::gui {

namespace {

// A listed text with placeholders, as an anchored expression: each %N becomes a lazy group.
struct Pattern {
    const char* source = nullptr;
    QRegularExpression re;
    std::vector<int> argOrder;  // group g holds %argOrder[g-1]
    qsizetype literal = 0;      // letters outside the placeholders: longer patterns are tried first
    bool suffix = false;        // from coretext::suffixes(): tried before the others
};

constexpr qsizetype kPrefixKey = 3;  // patterns are bucketed by the first characters of their text

// A shape (coretext::shapes()): "%1" + separator + "%2" + tail, e.g. "%1 (%2)".
struct Shape {
    const char* source = nullptr;
    QString head, separator, tail;  // the literals before %1, between %1 and %2, after %2
};

struct Patterns {
    std::vector<Pattern> all;
    QHash<QString, std::vector<size_t>> byPrefix;  // literal prefix (kPrefixKey chars) -> patterns
    std::vector<size_t> open;                      // patterns whose literal prefix is shorter
    std::vector<size_t> suffixes;                  // coretext::suffixes(), tried first
    QHash<QString, const char*> folded;            // lower-case text -> listed text without placeholders
    std::vector<Shape> shapes;

    Patterns() {
        static const QRegularExpression placeholder(QStringLiteral("%([1-9])"));
        for (const char* text : coretext::shapes()) {
            const QString s = QString::fromUtf8(text);
            const qsizetype one = s.indexOf(QLatin1String("%1")), two = s.indexOf(QLatin1String("%2"));
            shapes.push_back({text, s.left(one), s.mid(one + 2, two - one - 2), s.mid(two + 2)});
        }
        std::vector<std::span<const char* const>> lists(coretext::all().begin(), coretext::all().end());
        lists.push_back(coretext::suffixes());
        for (auto list : lists) {
            const bool suffix = list.data() == coretext::suffixes().data();
            for (const char* text : list) {
                const QString s = QString::fromUtf8(text);
                if (!s.contains(placeholder)) {
                    folded.insert(s.toLower(), text);
                    continue;
                }
                Pattern p;
                p.source = text;
                p.suffix = suffix;
                QString re;
                qsizetype at = 0;
                auto it = placeholder.globalMatch(s);
                while (it.hasNext()) {
                    const auto m = it.next();
                    const QString lit = s.mid(at, m.capturedStart() - at);
                    re += QRegularExpression::escape(lit);
                    p.literal += lit.size();
                    re += QStringLiteral("(.*?)");
                    p.argOrder.push_back(m.captured(1).toInt());
                    at = m.capturedEnd();
                }
                const QString tail = s.mid(at);
                re += QRegularExpression::escape(tail);
                p.literal += tail.size();
                p.re = QRegularExpression(QRegularExpression::anchoredPattern(re),
                                          QRegularExpression::DotMatchesEverythingOption);
                p.re.optimize();
                all.push_back(std::move(p));
            }
        }
        std::stable_sort(all.begin(), all.end(),
                         [](const Pattern& a, const Pattern& b) { return a.literal > b.literal; });
        for (size_t i = 0; i < all.size(); ++i) {
            const QString s = QString::fromUtf8(all[i].source);
            const qsizetype firstArg = s.indexOf(u'%');
            if (all[i].suffix) suffixes.push_back(i);
            else if (firstArg >= kPrefixKey) byPrefix[s.left(kPrefixKey)].push_back(i);
            else open.push_back(i);
        }
    }
};

const Patterns& patterns() {
    static const Patterns p;
    return p;
}

// `translated` with each %N replaced by values[N-1] in one pass (a value may contain '%').
QString fill(const QString& translated, const std::vector<QString>& values) {
    QString out;
    out.reserve(translated.size() + 32);
    for (qsizetype i = 0; i < translated.size(); ++i) {
        const QChar c = translated.at(i);
        if (c == u'%' && i + 1 < translated.size() && translated.at(i + 1).isDigit()) {
            const int n = translated.at(i + 1).digitValue();
            if (n >= 1 && static_cast<size_t>(n) <= values.size()) {
                out += values[static_cast<size_t>(n - 1)];
                ++i;
                continue;
            }
        }
        out += c;
    }
    return out;
}

QString lookUp(const QString& english, int depth, qsizetype* covered = nullptr);

// `english` as a list joined by `join` (one of coretext::joins(): "a; b", "a, b"): the items'
// translations joined the UI language's way; empty when no item is translated, or when one is
// not translated in full and `partial` is false. *covered = the letters translated. An item may
// be a list of the other kind, so the cost stays linear.
QString byList(const QString& english, int depth, const char* join, bool partial, qsizetype* covered) {
    *covered = 0;
    const QString source = QString::fromUtf8(join);
    const QString separator = source.mid(2, source.size() - 4);  // "%1" + separator + "%2"
    if (!english.contains(separator)) return {};
    QStringList items = english.split(separator);
    for (QString& item : items) {
        qsizetype c = 0;
        const QString translated = lookUp(item, depth + 1, &c);
        if (!partial && (item.isEmpty() || c < item.size())) return {};
        *covered += c;
        item = translated;
    }
    if (*covered == 0) return {};
    const QString translatedJoin = QCoreApplication::translate("CoreText", join);
    return items.join(translatedJoin.mid(2, translatedJoin.size() - 4));
}

// `english` in one of the shapes ("0650h (Switch on disabled)", "0x5530 Data storage error
// (EEPROM)", "generic error (AL555 …)"): the shape's translation with both parts looked up. Of
// the shapes and the places of their separator, the one whose translated parts cover the most
// of the text wins (the last place on a tie: an annotation closes the text); `english` as it is
// when no part is translated. *covered = the letters translated.
QString byShape(const QString& english, int depth, qsizetype* covered) {
    qsizetype best = 0;
    const Shape* bestShape = nullptr;
    std::vector<QString> parts;
    for (const Shape& sh : patterns().shapes) {
        if (!english.startsWith(sh.head) || !english.endsWith(sh.tail)) continue;
        const QString inner = english.mid(sh.head.size(), english.size() - sh.head.size() - sh.tail.size());
        for (qsizetype at = inner.lastIndexOf(sh.separator); at > 0; at = inner.lastIndexOf(sh.separator, at - 1)) {
            const QString one = inner.left(at), two = inner.mid(at + sh.separator.size());
            if (two.isEmpty()) continue;
            qsizetype c1 = 0, c2 = 0;
            QString oneT = lookUp(one, depth + 1, &c1), twoT = lookUp(two, depth + 1, &c2);
            if (c1 + c2 > best) best = c1 + c2, bestShape = &sh, parts = {std::move(oneT), std::move(twoT)};
        }
    }
    if (covered) *covered = best;
    return bestShape ? fill(QCoreApplication::translate("CoreText", bestShape->source), parts) : english;
}

QString lookUp(const QString& english, int depth, qsizetype* covered) {
    if (covered) *covered = english.size();
    if (english.isEmpty()) return english;
    const QByteArray key = english.toUtf8();
    QString direct = QCoreApplication::translate("CoreText", key.constData());
    if (direct != english) return direct;
    if (covered) *covered = 0;
    if (depth > 3) return english;
    const Patterns& ps = patterns();
    if (covered) *covered = english.size();
    // The health report writes EMCY texts in lower case ("generic error"): the listed text's translation.
    if (const auto it = ps.folded.constFind(english.toLower());
        it != ps.folded.constEnd() && english != QString::fromUtf8(*it))
        return QCoreApplication::translate("CoreText", *it);
    auto tryOne = [&](size_t i, QString* out) {
        const Pattern& p = ps.all[i];
        const auto m = p.re.match(english);
        if (!m.hasMatch()) return false;
        const QString translated = QCoreApplication::translate("CoreText", p.source);
        if (translated == QString::fromUtf8(p.source)) return false;
        std::vector<QString> values(9);
        for (size_t g = 0; g < p.argOrder.size(); ++g)
            values[static_cast<size_t>(p.argOrder[g] - 1)] = lookUp(m.captured(static_cast<int>(g + 1)), depth + 1);
        *out = fill(translated, values);
        return true;
    };
    // A "; " list first (the problems of a CAN error frame): a pattern would take the rest of
    // the list as its last value.
    const auto joins = coretext::joins();
    qsizetype listCovered = 0;
    if (QString list = byList(english, depth, joins[0], false, &listCovered); !list.isEmpty()) return list;
    QString out;
    for (size_t i : ps.suffixes)
        if (tryOne(i, &out)) return out;
    // Both lists are sorted longest-literal first; the bucket's patterns are the more specific.
    if (const auto it = ps.byPrefix.constFind(english.left(kPrefixKey)); it != ps.byPrefix.constEnd())
        for (size_t i : *it)
            if (tryOne(i, &out)) return out;
    for (size_t i : ps.open)
        if (tryOne(i, &out)) return out;
    // A ", " list (the signals of a PDO, "Statusword = 0637h (Operation enabled), Position …"):
    // at once when each item is translated in full; else the list or the shape that translates
    // more ("0x2311 Current, device output side" is a code and one name, not a list).
    QString list = byList(english, depth, joins[1], true, &listCovered);
    if (!list.isEmpty() && listCovered == english.size() - english.count(QLatin1String(", ")) * 2) return list;
    qsizetype shapeCovered = 0;
    QString shaped = byShape(english, depth, &shapeCovered);
    if (!list.isEmpty() && listCovered > shapeCovered) {
        if (covered) *covered = listCovered;
        return list;
    }
    if (covered) *covered = shapeCovered;
    return shaped;
}

}  // namespace

namespace coretext {
std::span<const std::span<const char* const>> all() {
    static const std::span<const char* const> lists[] = {names(), wizards(), trace(), details(), bus(), homing()};
    return lists;
}
}  // namespace coretext

QString coreText(const QString& english) {
    if (language::current() == u"en") return english;
    return lookUp(english, 0);
}

QString coreLines(const QString& english) {
    if (language::current() == u"en") return english;
    QStringList lines = english.split(u'\n');
    for (QString& line : lines) {
        const QString whole = lookUp(line, 0);
        if (whole != line || !line.contains(QLatin1String("; "))) {
            line = whole;
            continue;
        }
        QStringList parts = line.split(QStringLiteral("; "));
        for (QString& part : parts) part = lookUp(part, 0);
        line = parts.join(QStringLiteral("; "));
    }
    return lines.join(u'\n');
}

QString coreJoined(const QString& english, const QString& separator) {
    if (language::current() == u"en") return english;
    QString whole = lookUp(english, 0);
    if (whole != english) return whole;
    QStringList parts = english.split(separator);
    for (QString& part : parts) part = lookUp(part, 0);
    return parts.join(separator);
}

}  // namespace coscope::gui
