// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QHash>
#include <QString>

#include <deque>
#include <mutex>

namespace coscope::od {

// The same text, held for the rest of the process and handed out as raw data: copying and
// dropping the result never touches a reference count (two atomic operations per copy), for
// names that dissection copies frame after frame (PDO signal names and units, dictionary
// names). The texts are few (names of dictionary objects), so keeping them all costs little.
inline QString permanentText(const QString& s) {
    if (s.isEmpty()) return s;
    static std::mutex mutex;
    static std::deque<QString> kept;      // never changed once stored: raw data stays valid
    static QHash<QString, qsizetype> at;  // text -> index in `kept`
    std::lock_guard lock(mutex);
    auto it = at.constFind(s);
    if (it == at.cend()) {
        kept.push_back(QString(s.constData(), s.size()));  // a copy of our own, never shared out
        it = at.insert(kept.back(), static_cast<qsizetype>(kept.size() - 1));
    }
    const QString& k = kept[static_cast<size_t>(*it)];
    return QString::fromRawData(k.constData(), k.size());
}

}  // namespace coscope::od
