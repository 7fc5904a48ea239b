// SPDX-License-Identifier: GPL-3.0-or-later
#include "eds/IniDocument.h"

namespace coscope::eds {

IniDocument IniDocument::parse(const QString& text, DiagnosticSink& sink) {
    IniDocument doc;
    int current = -1;
    int lineNo = 0;
    int keysOutside = 0;
    qsizetype pos = 0;
    const qsizetype n = text.size();
    while (pos <= n) {
        qsizetype end = text.indexOf(u'\n', pos);
        if (end < 0) end = n;
        ++lineNo;
        QStringView line = QStringView(text).mid(pos, end - pos).trimmed();  // also drops '\r'
        pos = end + 1;
        if (line.isEmpty() || line.front() == u';' || line.front() == u'#') {
            if (end == n) break;
            continue;
        }
        if (line.front() == u'[') {
            qsizetype close = line.indexOf(u']');
            QString name;
            if (close < 0) {
                name = line.mid(1).trimmed().toString();
                sink.warning(lineNo, QStringLiteral("section header [%1 has no closing ']'").arg(name));
            } else {
                name = line.mid(1, close - 1).trimmed().toString();
                const QStringView rest = line.mid(close + 1).trimmed();
                if (!rest.isEmpty() && rest.front() != u';' && rest.front() != u'#')
                    sink.warning(lineNo, QStringLiteral("text after section header [%1] ignored").arg(name));
            }
            const QString lower = name.toLower();
            auto it = doc.byName_.constFind(lower);
            if (it != doc.byName_.constEnd()) {
                current = *it;
                sink.warning(lineNo,
                             QStringLiteral(
                                 "section [%1] appears again (first at line %2); merged, first value of each key wins")
                                 .arg(name)
                                 .arg(doc.sections_[static_cast<size_t>(current)].line));
            } else {
                current = static_cast<int>(doc.sections_.size());
                doc.byName_.insert(lower, current);
                IniSection s;
                s.name = name;
                s.line = lineNo;
                doc.sections_.push_back(std::move(s));
            }
            if (end == n) break;
            continue;
        }
        const qsizetype eq = line.indexOf(u'=');
        if (eq <= 0) {
            sink.warning(lineNo, QStringLiteral("line is not KEY=VALUE; ignored"));
        } else if (current < 0) {
            if (++keysOutside == 1) sink.warning(lineNo, QStringLiteral("key outside any section; ignored"));
        } else {
            IniSection& s = doc.sections_[static_cast<size_t>(current)];
            IniEntry e{line.left(eq).trimmed().toString(), line.mid(eq + 1).trimmed().toString(), lineNo};
            const QString lower = e.key.toLower();
            auto it = s.byKey.constFind(lower);
            if (it != s.byKey.constEnd()) {
                sink.warning(lineNo,
                             QStringLiteral("duplicate key %1 in [%2] (first at line %3); the first value is used")
                                 .arg(e.key, s.name)
                                 .arg(s.entries[static_cast<size_t>(*it)].line));
            } else {
                s.byKey.insert(lower, static_cast<int>(s.entries.size()));
                s.entries.push_back(std::move(e));
            }
        }
        if (end == n) break;
    }
    return doc;
}

}  // namespace coscope::eds
