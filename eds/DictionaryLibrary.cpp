// SPDX-License-Identifier: GPL-3.0-or-later
#include "eds/DictionaryLibrary.h"

#include "core/od/PermanentText.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>

#include <spdlog/spdlog.h>

#include <algorithm>
#include <mutex>

namespace coscope::eds {

namespace {

std::optional<std::uint32_t> hexNumber(const QJsonValue& v) {
    if (!v.isString()) return std::nullopt;
    bool ok = false;
    const std::uint32_t n = v.toString().toUInt(&ok, 0);
    return ok ? std::optional<std::uint32_t>(n) : std::nullopt;
}

QString sidecarPath(const QString& dictionaryPath) {
    const QFileInfo fi(dictionaryPath);
    return fi.path() + u'/' + fi.completeBaseName() + QStringLiteral(".json");
}

}  // namespace

const DictionaryLibrary& DictionaryLibrary::shared() {
    static const DictionaryLibrary library;
    return library;
}

DictionaryLibrary::DictionaryLibrary(const QString& userFolder)
    : userFolder_(userFolder.isEmpty() ? defaultUserFolder() : userFolder) {
    scan(QStringLiteral(":/dictionaries"), true);
    scan(userFolder_, false);
}

QString DictionaryLibrary::defaultUserFolder() {
    return QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) +
           QStringLiteral("/CoScope/dictionaries");
}

void DictionaryLibrary::scan(const QString& folder, bool bundled) {
    const QDir dir(folder);
    if (!dir.exists()) return;
    const auto files = dir.entryInfoList({QStringLiteral("*.eds"), QStringLiteral("*.dcf"), QStringLiteral("*.xdd"),
                                          QStringLiteral("*.EDS"), QStringLiteral("*.DCF"), QStringLiteral("*.XDD")},
                                         QDir::Files, QDir::Name);
    for (const QFileInfo& fi : files) {
        Entry e;
        e.name = fi.completeBaseName();
        e.path = fi.filePath();
        e.bundled = bundled;
        // Bundled dictionaries are usable (test_eds_library bundledNamesLoad): their identity is
        // read when first needed. A user's file is read now, and skipped when unusable.
        if (!bundled && !readIdentity(e)) {
            spdlog::warn("dictionary library: {} is not usable; skipped", e.path.toStdString());
            continue;
        }
        auto same = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& x) { return x.name == e.name; });
        if (same != entries_.end()) *same = e;  // user folder replaces bundled
        else entries_.push_back(e);
    }
}

void DictionaryLibrary::applyIdentity(Entry& e, const DocumentedIdentity& id) {
    e.vendorId = id.vendorId;
    e.productCode = id.productCode;
    e.revision = id.revision;
    e.deviceType = id.deviceType;
    e.deviceName = id.deviceName;
    readSidecarIdentity(e);
}

bool DictionaryLibrary::readIdentity(Entry& e) {
    const ReadResult r = readDictionaryFile(e.path);
    if (!r.usable) return false;
    applyIdentity(e, documentedIdentity(r.dictionary));
    return true;
}

void DictionaryLibrary::readBundledIdentities() const {
    std::call_once(*bundledIdentitiesRead_, [this] {
        for (Entry& e : entries_) {
            if (!e.bundled) continue;
            // The bundled files are usable (test_eds_library bundledNamesLoad): only the sections
            // that hold their identity are read.
            if (const auto id = readDocumentedIdentity(e.path)) applyIdentity(e, *id);
            else if (!readIdentity(e)) spdlog::warn("dictionary library: {} is not usable", e.path.toStdString());
        }
    });
}

// The sidecar's "identity": product variants, placeholder, and the string object (1008h or
// 100Ah) that names the device when 1018h is not documented.
void DictionaryLibrary::readSidecarIdentity(Entry& e) {
    QFile f(sidecarPath(e.path));
    if (!f.exists() || !f.open(QIODevice::ReadOnly)) return;
    const QJsonObject id = QJsonDocument::fromJson(f.readAll()).object().value(QStringLiteral("identity")).toObject();
    e.placeholder = id.value(QStringLiteral("placeholder")).toBool();
    for (const QJsonValue v : id.value(QStringLiteral("variants")).toArray())
        if (auto p = hexNumber(v.toObject().value(QStringLiteral("productCode")))) e.variantProducts.push_back(*p);
    if (auto t = hexNumber(id.value(QStringLiteral("deviceType")))) e.deviceType = t;
    for (const char* key : {"softwareVersion", "deviceName"}) {
        const QJsonObject s = id.value(QLatin1String(key)).toObject();
        if (s.isEmpty()) continue;
        e.stringIndex =
            static_cast<std::uint16_t>(s.value(QStringLiteral("object")).toString().left(4).toUInt(nullptr, 16));
        e.stringValue = s.value(QStringLiteral("value")).toString();
    }
}

QStringList DictionaryLibrary::names() const {
    QStringList n;
    for (const Entry& e : entries_) n << e.name;
    return n;
}

const DictionaryLibrary::Entry* DictionaryLibrary::find(const QString& name) const {
    for (const Entry& e : entries_)
        if (e.name.compare(name, Qt::CaseInsensitive) == 0) return &e;
    return nullptr;
}

ReadResult DictionaryLibrary::load(const QString& name) const {
    if (const Entry* e = find(name)) return loadFile(e->path);
    ReadResult r;
    r.diagnostics.push_back(
        {name, 0, Diagnostic::Severity::Error,
         QStringLiteral("no such file or dictionary (known: %1)").arg(names().join(QStringLiteral(", ")))});
    return r;
}

const DictionaryLibrary::Entry* DictionaryLibrary::findByIdentity(std::uint32_t vendorId, std::uint32_t productCode,
                                                                  std::optional<std::uint32_t> revision) const {
    if (vendorId == 0 && productCode == 0) return nullptr;  // no identity (see match())
    readBundledIdentities();
    const Entry* best = nullptr;
    int bestRank = -1;
    std::uint32_t bestRev = 0;
    for (const Entry& e : entries_) {
        const bool variant = e.vendorId == vendorId && std::find(e.variantProducts.begin(), e.variantProducts.end(),
                                                                 productCode) != e.variantProducts.end();
        if (e.vendorId != vendorId || (e.productCode != productCode && !variant)) continue;
        const std::uint32_t rev = e.revision.value_or(0);
        int rank = 0;
        if (revision && e.revision == revision) rank = 2;
        else if (revision && e.revision && (*e.revision >> 16) == (*revision >> 16)) rank = 1;
        const bool better = rank > bestRank || (rank == bestRank && rev > bestRev) ||
                            (rank == bestRank && rev == bestRev && best && best->bundled && !e.bundled);
        if (!best || better) {
            best = &e;
            bestRank = rank;
            bestRev = rev;
        }
    }
    return best;
}

const DictionaryLibrary::Entry* DictionaryLibrary::match(const DeviceIdentity& device) const {
    if (device.hasIdentity()) return findByIdentity(*device.vendorId, *device.productCode, device.revision);
    // No usable 1018h (CiA 301 §7.5.2.21 makes it mandatory, but AIMOTOR and DEXMART answer 0 or
    // abort): only what the device and the dictionary both document can tell them apart.
    auto startsWith = [](const std::optional<QString>& read, const QString& documented) {
        return read && !documented.isEmpty() &&
               read->trimmed().remove(QChar(0)).startsWith(documented, Qt::CaseInsensitive);
    };
    // The device type alone (many drives say 0192h) is evidence only once 1018h was read as 0/0.
    const int minimum = device.vendorId && device.productCode ? 2 : 4;
    readBundledIdentities();
    const Entry* best = nullptr;
    int bestScore = 0;
    bool tie = false;
    for (const Entry& e : entries_) {
        if (e.hasIdentity()) continue;  // a dictionary with an identity is matched by it only
        const QString documentedName = e.stringIndex == 0x1008 ? e.stringValue : e.deviceName;
        if (device.deviceName && !documentedName.isEmpty() && !startsWith(device.deviceName, documentedName)) continue;
        int score = 0;
        if (startsWith(device.deviceName, documentedName)) score += 4;
        if (e.stringIndex == 0x100A && startsWith(device.softwareVersion, e.stringValue)) score += 4;
        if (device.deviceType && e.deviceType && *device.deviceType == *e.deviceType) score += 2;
        if (score < minimum || score < bestScore) continue;
        tie = score == bestScore;
        best = &e;
        bestScore = score;
    }
    return tie ? nullptr : best;
}

DictionaryPtr DictionaryLibrary::loadShared(const QString& nameOrFile, QString* name, QString* error) const {
    static std::mutex mutex;
    static QHash<QString, DictionaryPtr> cache;  // by path: library dictionaries only
    const Entry* e = QFileInfo::exists(nameOrFile) && !nameOrFile.startsWith(u':') ? nullptr : find(nameOrFile);
    if (!e && !QFileInfo::exists(nameOrFile)) {
        if (error)
            *error = QStringLiteral("'%1' is neither a known dictionary (%2) nor a file")
                         .arg(nameOrFile, names().join(QStringLiteral(", ")));
        return nullptr;
    }
    const QString path = e ? e->path : nameOrFile;
    if (name) *name = e ? e->name : QFileInfo(nameOrFile).completeBaseName();
    std::lock_guard lock(mutex);
    if (e)
        if (auto it = cache.constFind(path); it != cache.constEnd()) return *it;
    ReadResult r = loadFile(path);  // with its units sidecar
    for (const auto& d : r.diagnostics)
        if (d.severity == Diagnostic::Severity::Error) spdlog::warn("{}", d.toString().toStdString());
    if (!r.usable) {
        if (error) *error = QStringLiteral("%1: not a usable EDS/DCF/XDD file").arg(path);
        return nullptr;
    }
    auto d = std::make_shared<const od::ObjectDictionary>(std::move(r.dictionary));
    if (e) cache.insert(path, d);
    return d;
}

void DictionaryLibrary::applyUnits(od::ObjectDictionary& od, const QByteArray& json, const QString& jsonName,
                                   Diagnostics& diagnostics) {
    QJsonParseError err{};
    const QJsonDocument doc = QJsonDocument::fromJson(json, &err);
    if (err.error != QJsonParseError::NoError || !doc.isObject()) {
        diagnostics.push_back({jsonName, 0, Diagnostic::Severity::Warning,
                               QStringLiteral("not a JSON object (%1 at offset %2); units ignored")
                                   .arg(err.errorString())
                                   .arg(err.offset)});
        return;
    }
    const QJsonObject units = doc.object().value(QStringLiteral("units")).toObject();
    for (auto it = units.begin(); it != units.end(); ++it) {
        const QString key = it.key();  // "6064:00" (hex index:sub)
        bool ok1 = false, ok2 = false;
        const uint index = key.section(u':', 0, 0).toUInt(&ok1, 16);
        const uint sub = key.section(u':', 1, 1).toUInt(&ok2, 16);
        od::SubObject* s = (ok1 && ok2 && index <= 0xFFFF && sub <= 0xFF)
                               ? od.entryForEdit(static_cast<std::uint16_t>(index), static_cast<std::uint8_t>(sub))
                               : nullptr;
        if (!s) {
            diagnostics.push_back({jsonName, 0, Diagnostic::Severity::Warning,
                                   QStringLiteral("units: '%1' is not an entry of the dictionary").arg(key)});
            continue;
        }
        const QJsonObject u = it.value().toObject();
        od::Unit unit;
        unit.text = u.value(QStringLiteral("unit")).toString();
        unit.factor = u.value(QStringLiteral("factor")).toDouble(1.0);
        s->unit = unit;
    }
}

ReadResult DictionaryLibrary::loadFile(const QString& path) {
    ReadResult r = readDictionaryFile(path);
    const QString sidecar = sidecarPath(path);
    QFile f(sidecar);
    if (r.usable && f.exists() && f.open(QIODevice::ReadOnly))
        applyUnits(r.dictionary, f.readAll(), sidecar, r.diagnostics);
    if (r.usable && path.startsWith(QLatin1String(":/dictionaries/")))
        r.dictionary.bundledName =
            od::permanentText(QFileInfo(path).completeBaseName());  // copied per frame (Dissection::namesFrom)
    return r;
}

ReadResult loadDictionaryByPathOrName(const QString& fileOrName) {
    if (QFileInfo::exists(fileOrName)) return DictionaryLibrary::loadFile(fileOrName);
    return DictionaryLibrary().load(fileOrName);
}

}  // namespace coscope::eds
