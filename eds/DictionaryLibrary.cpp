// SPDX-License-Identifier: GPL-3.0-or-later
#include "eds/DictionaryLibrary.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>

#include <spdlog/spdlog.h>

namespace coscope::eds {

DictionaryLibrary::DictionaryLibrary(const QString& userFolder) : userFolder_(userFolder.isEmpty() ? defaultUserFolder() : userFolder) {
    scan(QStringLiteral(":/dictionaries"), true);
    scan(userFolder_, false);
}

QString DictionaryLibrary::defaultUserFolder() {
    return QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) + QStringLiteral("/CoScope/dictionaries");
}

void DictionaryLibrary::scan(const QString& folder, bool bundled) {
    const QDir dir(folder);
    if (!dir.exists()) return;
    const auto files = dir.entryInfoList({QStringLiteral("*.eds"), QStringLiteral("*.dcf"), QStringLiteral("*.xdd"), QStringLiteral("*.EDS"),
                                          QStringLiteral("*.DCF"), QStringLiteral("*.XDD")},
                                         QDir::Files, QDir::Name);
    for (const QFileInfo& fi : files) {
        Entry e;
        e.name = fi.completeBaseName();
        e.path = fi.filePath();
        e.bundled = bundled;
        const ReadResult r = readDictionaryFile(e.path);
        if (!r.usable) {
            spdlog::warn("dictionary library: {} is not usable; skipped", e.path.toStdString());
            continue;
        }
        e.vendorId = r.dictionary.vendorId();
        e.productCode = r.dictionary.productCode();
        e.revision = r.dictionary.revisionNumber();
        auto same = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& x) { return x.name == e.name; });
        if (same != entries_.end()) *same = e;  // user folder replaces bundled
        else entries_.push_back(e);
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
    r.diagnostics.push_back({name, 0, Diagnostic::Severity::Error,
                             QStringLiteral("no such file or dictionary (known: %1)").arg(names().join(QStringLiteral(", ")))});
    return r;
}

const DictionaryLibrary::Entry* DictionaryLibrary::findByIdentity(std::uint32_t vendorId, std::uint32_t productCode, std::optional<std::uint32_t> revision) const {
    const Entry* best = nullptr;
    int bestRank = -1;
    std::uint32_t bestRev = 0;
    for (const Entry& e : entries_) {
        if (e.vendorId != vendorId || e.productCode != productCode) continue;
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

void DictionaryLibrary::applyUnits(od::ObjectDictionary& od, const QByteArray& json, const QString& jsonName, Diagnostics& diagnostics) {
    QJsonParseError err{};
    const QJsonDocument doc = QJsonDocument::fromJson(json, &err);
    if (err.error != QJsonParseError::NoError || !doc.isObject()) {
        diagnostics.push_back({jsonName, 0, Diagnostic::Severity::Warning, QStringLiteral("not a JSON object (%1 at offset %2); units ignored").arg(err.errorString()).arg(err.offset)});
        return;
    }
    const QJsonObject units = doc.object().value(QStringLiteral("units")).toObject();
    for (auto it = units.begin(); it != units.end(); ++it) {
        const QString key = it.key();  // "6064:00" (hex index:sub)
        bool ok1 = false, ok2 = false;
        const uint index = key.section(u':', 0, 0).toUInt(&ok1, 16);
        const uint sub = key.section(u':', 1, 1).toUInt(&ok2, 16);
        od::SubObject* s = (ok1 && ok2 && index <= 0xFFFF && sub <= 0xFF) ? od.entryForEdit(static_cast<std::uint16_t>(index), static_cast<std::uint8_t>(sub)) : nullptr;
        if (!s) {
            diagnostics.push_back({jsonName, 0, Diagnostic::Severity::Warning, QStringLiteral("units: '%1' is not an entry of the dictionary").arg(key)});
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
    const QFileInfo fi(path);
    const QString sidecar = fi.path() + u'/' + fi.completeBaseName() + QStringLiteral(".json");
    QFile f(sidecar);
    if (r.usable && f.exists() && f.open(QIODevice::ReadOnly)) applyUnits(r.dictionary, f.readAll(), sidecar, r.diagnostics);
    return r;
}

ReadResult loadDictionaryByPathOrName(const QString& fileOrName) {
    if (QFileInfo::exists(fileOrName)) return DictionaryLibrary::loadFile(fileOrName);
    return DictionaryLibrary().load(fileOrName);
}

}  // namespace coscope::eds
