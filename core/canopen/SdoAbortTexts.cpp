// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/SdoAbortTexts.h"

#include "core/canopen/SdoAbort.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace coscope::canopen {

bool VendorAbortTable::load(const QByteArray& json, QString* error) {
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &pe);
    if (!doc.isObject()) {
        if (error)
            *error = QStringLiteral("alarm table is not a JSON object (%1 at offset %2)")
                         .arg(pe.errorString())
                         .arg(pe.offset);
        return false;
    }
    const QJsonObject root = doc.object();
    vendor_ = root.value(QStringLiteral("vendor")).toString();
    texts_.clear();
    for (const QJsonValue v : root.value(QStringLiteral("sdoAborts")).toArray()) {
        const QJsonObject o = v.toObject();
        bool ok = false;
        const uint32_t code = o.value(QStringLiteral("code")).toString().toUInt(&ok, 0);
        const QString text = o.value(QStringLiteral("text")).toString();
        if (ok && !text.isEmpty()) texts_.insert(code, text);
    }
    return true;
}

bool VendorAbortTable::loadDictionaryTable(const QString& dictionaryName, QString* error) {
    const QString path =
        dictionaryName.contains(u'/') ? dictionaryName : QStringLiteral(":/alarms/%1.json").arg(dictionaryName);
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        if (error) *error = QStringLiteral("no alarm table %1").arg(path);
        return false;
    }
    return load(f.readAll(), error);
}

std::optional<QString> VendorAbortTable::text(uint32_t code) const {
    auto it = texts_.constFind(code);
    if (it == texts_.constEnd()) return std::nullopt;
    return *it;
}

QString describeSdoAbort(uint32_t code, const VendorAbortTable* vendor) {
    QString text;
    if (vendor)
        if (auto t = vendor->text(code)) text = *t;
    if (text.isEmpty()) text = sdoAbortText(code);
    if (text.isEmpty()) text = QStringLiteral("Unknown abort code");
    return QStringLiteral("%1 (0x%2)").arg(text, QStringLiteral("%1").arg(code, 8, 16, QChar(u'0')).toUpper());
}

}  // namespace coscope::canopen
