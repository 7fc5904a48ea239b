// SPDX-License-Identifier: GPL-3.0-or-later
#include "eds/BundledDictionaries.h"

#include <QDir>
#include <QFileInfo>

namespace coscope::eds {

QStringList bundledDictionaryNames() {
    QStringList names;
    const auto entries =
        QDir(QStringLiteral(":/dictionaries")).entryInfoList({QStringLiteral("*.eds")}, QDir::Files, QDir::Name);
    for (const QFileInfo& fi : entries) names << fi.completeBaseName();
    return names;
}

QString bundledDictionaryPath(const QString& name) {
    const QString path = QStringLiteral(":/dictionaries/%1.eds").arg(name);
    return QFileInfo::exists(path) ? path : QString();
}

}  // namespace coscope::eds
