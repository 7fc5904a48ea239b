// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/DictionaryCatalog.h"

#include "eds/DictionaryLibrary.h"

#include "eds/BundledDictionaries.h"
#include "eds/EdsReader.h"

#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <spdlog/spdlog.h>

#include <mutex>
#include <vector>

namespace coscope::dissect::catalog {

namespace {

std::mutex& mutex() {
    static std::mutex m;
    return m;
}

struct IdentityRule {
    QString name;
    std::optional<uint32_t> vendor;
    std::vector<uint32_t> products;
    uint16_t stringIndex = 0;
    QString stringValue;
};

std::optional<uint32_t> hexNumber(const QJsonValue& v) {
    if (!v.isString()) return std::nullopt;
    bool ok = false;
    const uint32_t n = v.toString().toUInt(&ok, 0);
    return ok ? std::optional<uint32_t>(n) : std::nullopt;
}

const std::vector<IdentityRule>& identityRules() {
    static const std::vector<IdentityRule> rules = [] {
        std::vector<IdentityRule> out;
        for (const QString& name : eds::bundledDictionaryNames()) {
            QFile f(QStringLiteral(":/dictionaries/%1.json").arg(name));
            if (!f.open(QIODevice::ReadOnly)) continue;
            const QJsonObject id = QJsonDocument::fromJson(f.readAll()).object().value(QStringLiteral("identity")).toObject();
            if (id.value(QStringLiteral("placeholder")).toBool()) continue;
            IdentityRule r;
            r.name = name;
            r.vendor = hexNumber(id.value(QStringLiteral("vendorId")));
            if (auto p = hexNumber(id.value(QStringLiteral("productCode")))) r.products.push_back(*p);
            for (const QJsonValue& v : id.value(QStringLiteral("variants")).toArray())
                if (auto p = hexNumber(v.toObject().value(QStringLiteral("productCode")))) r.products.push_back(*p);
            for (const char* key : {"softwareVersion", "deviceName"}) {
                const QJsonObject s = id.value(QLatin1String(key)).toObject();
                if (s.isEmpty()) continue;
                r.stringIndex = static_cast<uint16_t>(s.value(QStringLiteral("object")).toString().left(4).toUInt(nullptr, 16));
                r.stringValue = s.value(QStringLiteral("value")).toString();
            }
            out.push_back(r);
        }
        return out;
    }();
    return rules;
}

}  // namespace

DictionaryPtr bundled(const QString& name, QString* error) {
    static QHash<QString, DictionaryPtr> cache;
    std::lock_guard lock(mutex());
    if (auto it = cache.constFind(name); it != cache.constEnd()) return *it;
    const QString path = eds::bundledDictionaryPath(name);
    if (path.isEmpty()) {
        if (error) *error = QStringLiteral("unknown dictionary '%1' (bundled: %2)").arg(name, eds::bundledDictionaryNames().join(QStringLiteral(", ")));
        return nullptr;
    }
    eds::ReadResult r = eds::DictionaryLibrary::loadFile(path);  // with its units sidecar
    if (!r.usable) {
        if (error) *error = QStringLiteral("bundled dictionary '%1' is not readable").arg(name);
        return nullptr;
    }
    auto d = std::make_shared<const od::ObjectDictionary>(std::move(r.dictionary));
    cache.insert(name, d);
    return d;
}

DictionaryPtr fromFile(const QString& path, QString* error) {
    if (!QFileInfo::exists(path)) {
        if (error) *error = QStringLiteral("%1: no such file").arg(path);
        return nullptr;
    }
    eds::ReadResult r = eds::DictionaryLibrary::loadFile(path);  // with its units sidecar
    for (const auto& d : r.diagnostics)
        if (d.severity == eds::Diagnostic::Severity::Error) spdlog::warn("{}", d.toString().toStdString());
    if (!r.usable) {
        if (error) *error = QStringLiteral("%1: not a usable EDS/DCF/XDD file").arg(path);
        return nullptr;
    }
    return std::make_shared<const od::ObjectDictionary>(std::move(r.dictionary));
}

DictionaryPtr load(const QString& nameOrFile, QString* name, QString* error) {
    if (!eds::bundledDictionaryPath(nameOrFile).isEmpty()) {
        if (name) *name = nameOrFile;
        return bundled(nameOrFile, error);
    }
    if (QFileInfo::exists(nameOrFile)) {
        if (name) *name = QFileInfo(nameOrFile).completeBaseName();
        return fromFile(nameOrFile, error);
    }
    if (error)
        *error = QStringLiteral("'%1' is neither a bundled dictionary (%2) nor a file").arg(nameOrFile, eds::bundledDictionaryNames().join(QStringLiteral(", ")));
    return nullptr;
}

QString matchIdentity(uint32_t vendorId, uint32_t productCode) {
    for (const IdentityRule& r : identityRules()) {
        if (!r.vendor || *r.vendor != vendorId) continue;
        for (uint32_t p : r.products)
            if (p == productCode) return r.name;
    }
    return {};
}

QString matchStringObject(uint16_t index, const QString& value) {
    const QString v = value.trimmed();
    for (const IdentityRule& r : identityRules())
        if (r.stringIndex == index && !r.stringValue.isEmpty() && v.startsWith(r.stringValue, Qt::CaseInsensitive)) return r.name;
    return {};
}

QString alarmTableFor(const QString& dictionaryName) {
    if (dictionaryName.isEmpty()) return {};
    return QFile::exists(QStringLiteral(":/alarms/%1.json").arg(dictionaryName)) ? dictionaryName : QString();
}

}  // namespace coscope::dissect::catalog
