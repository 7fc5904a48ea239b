// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/SidecarNames.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>

#include <map>
#include <mutex>

namespace coscope::dissect {

const SidecarSections& sidecarSections(const QString& section) {
    static std::mutex mutex;
    static std::map<QString, SidecarSections> loaded;  // node-based: references stay valid
    std::lock_guard lock(mutex);
    if (const auto it = loaded.find(section); it != loaded.end()) return it->second;
    SidecarSections& sections = loaded[section];
    const QDir dir(QStringLiteral(":/dictionaries"));
    for (const QString& file : dir.entryList({QStringLiteral("*.json")}, QDir::Files)) {
        QFile f(dir.filePath(file));
        if (!f.open(QIODevice::ReadOnly)) continue;
        const QJsonObject o = QJsonDocument::fromJson(f.readAll()).object().value(section).toObject();
        SidecarSection& names = sections[file.chopped(5)];
        for (auto it = o.begin(); it != o.end(); ++it) names.insert(it.key(), it.value().toObject());
    }
    return sections;
}

}  // namespace coscope::dissect
