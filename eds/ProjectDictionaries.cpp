// SPDX-License-Identifier: GPL-3.0-or-later
#include "eds/ProjectDictionaries.h"

#include "eds/DictionaryLibrary.h"

#include <QDir>
#include <QFileInfo>

namespace coscope::eds {

project::DictionaryResolver projectDictionaryResolver(const QString& projectFolder) {
    return [projectFolder](const project::ProjectNode& node, QString* error) -> std::optional<od::ObjectDictionary> {
        if (node.dictionary.isEmpty()) {
            if (error) *error = QStringLiteral("node %1 has no dictionary in the project").arg(node.id);
            return std::nullopt;
        }
        QString ref = node.dictionary;
        const QFileInfo file(QDir(projectFolder.isEmpty() ? QDir::currentPath() : projectFolder), ref);
        if (file.exists()) ref = file.absoluteFilePath();
        QString why;
        const auto dict = DictionaryLibrary::shared().loadShared(ref, nullptr, &why);
        if (!dict) {
            if (error) *error = QStringLiteral("node %1: dictionary '%2': %3").arg(node.id).arg(node.dictionary, why);
            return std::nullopt;
        }
        return *dict;
    };
}

}  // namespace coscope::eds
