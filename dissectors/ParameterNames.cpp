// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/ParameterNames.h"

#include <QDir>
#include <QFile>
#include <QHash>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

#include <mutex>

namespace coscope::dissect {

namespace {

using Names = QHash<QString, QJsonObject>;  // "P3-00" -> {"zh_TW": …, "zh_CN": …}

Names loadAll() {
    Names names;
    const QDir dir(QStringLiteral(":/dictionaries"));
    for (const QString& file : dir.entryList({QStringLiteral("*.json")}, QDir::Files)) {
        QFile f(dir.filePath(file));
        if (!f.open(QIODevice::ReadOnly)) continue;
        const QJsonObject p = QJsonDocument::fromJson(f.readAll()).object().value(QStringLiteral("parameterNames")).toObject();
        for (auto it = p.begin(); it != p.end(); ++it) names.insert(it.key(), it.value().toObject());
    }
    return names;
}

const Names& all() {
    static std::once_flag once;
    static Names names;
    std::call_once(once, [] { names = loadAll(); });
    return names;
}

}  // namespace

QString localParameterName(const QString& edsName, const QString& lang) {
    if (lang != u"zh_TW" && lang != u"zh_CN") return edsName;
    // "P3-00 ADR Node-ID …" (Delta: code, mnemonic in capitals, text) or "H02-00 Control mode …".
    static const QRegularExpression code(QStringLiteral(R"(^((?:P\d-\d\d|H[0-9A-F]{2}-\d\d)(?: [A-Z][A-Z0-9]+(?= ))?) )"));
    const QRegularExpressionMatch m = code.match(edsName);
    if (!m.hasMatch()) return edsName;
    const QString key = edsName.left(edsName.indexOf(u' '));
    const auto it = all().constFind(key);
    if (it == all().constEnd()) return edsName;
    const QString zh = it->value(lang).toString();
    return zh.isEmpty() ? edsName : m.captured(1) + u' ' + zh;
}

}  // namespace coscope::dissect
