// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/project/ProjectFile.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QSaveFile>

#include <algorithm>

namespace coscope::project {

namespace {

const QStringList kTopKeys = {QStringLiteral("format"),      QStringLiteral("generator"),  QStringLiteral("name"),
                              QStringLiteral("bus"),         QStringLiteral("nodes"),      QStringLiteral("master"),
                              QStringLiteral("transmit"),    QStringLiteral("rawSignals"), QStringLiteral("plots"),
                              QStringLiteral("traceFilters")};
const QStringList kNodeKeys = {QStringLiteral("id"),       QStringLiteral("name"),       QStringLiteral("dictionary"),
                               QStringLiteral("identity"), QStringLiteral("parameters"), QStringLiteral("pdoLayouts"),
                               QStringLiteral("firmware")};

// A number written as JSON number or as text ("0x1DD", "477").
std::optional<uint32_t> readU32(const QJsonValue& v) {
    if (v.isDouble()) {
        const double d = v.toDouble();
        if (d < 0 || d > 4294967295.0 || d != static_cast<double>(static_cast<uint64_t>(d))) return std::nullopt;
        return static_cast<uint32_t>(d);
    }
    if (!v.isString()) return std::nullopt;
    bool ok = false;
    const uint64_t n = v.toString().trimmed().toULongLong(&ok, 0);
    if (!ok || n > 0xFFFFFFFFull) return std::nullopt;
    return static_cast<uint32_t>(n);
}

int lineAt(const QByteArray& text, int offset) {
    return 1 + static_cast<int>(
                   std::count(text.begin(), text.begin() + std::clamp<qsizetype>(offset, 0, text.size()), '\n'));
}

QJsonObject unknownKeys(const QJsonObject& o, const QStringList& known) {
    QJsonObject out;
    for (auto it = o.begin(); it != o.end(); ++it)
        if (!known.contains(it.key())) out.insert(it.key(), it.value());
    return out;
}

// PDO layouts for people reading the file (CiA 301 7.5.2.35-38: 1400h-1BFFh); not read back, the
// parameters are what counts.
QJsonArray pdoLayouts(const ProjectNode& node) {
    QJsonArray out;
    for (const ProjectParameter& p : node.parameters) {
        if (p.index < 0x1400 || p.index > 0x1BFF) continue;
        const bool tx = p.index >= 0x1800;
        const int n = (p.index & 0x1FF) + 1;
        const bool mapping = (p.index & 0x200) != 0;
        out.append(QStringLiteral("%1PDO%2 %3 %4 = %5")
                       .arg(tx ? QStringLiteral("T") : QStringLiteral("R"))
                       .arg(n)
                       .arg(mapping ? QStringLiteral("mapping") : QStringLiteral("communication"),
                            objectKey(p.index, p.sub), p.value));
    }
    return out;
}

}  // namespace

ProjectReadResult ProjectFile::read(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {std::nullopt, QStringLiteral("%1: cannot open: %2").arg(path, f.errorString())};
    return parse(f.readAll(), path);
}

ProjectReadResult ProjectFile::parse(const QByteArray& json, const QString& fileName) {
    ProjectReadResult r;
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(json, &pe);
    if (pe.error != QJsonParseError::NoError) {
        r.error = QStringLiteral("%1:%2: error: not valid JSON: %3")
                      .arg(fileName)
                      .arg(lineAt(json, pe.offset))
                      .arg(pe.errorString());
        return r;
    }
    auto fail = [&](const QString& key, const QString& what) {
        r.error = QStringLiteral("%1: %2: %3").arg(fileName, key, what);
        return r;
    };
    if (!doc.isObject()) return fail(QStringLiteral("(top)"), QStringLiteral("must be a JSON object"));
    const QJsonObject top = doc.object();
    Project p;
    const auto format = readU32(top.value(QStringLiteral("format")));
    if (!format || *format < 1)
        return fail(QStringLiteral("format"),
                    QStringLiteral("missing or not a number (a CoScope project has \"format\": 1)"));
    if (*format > static_cast<uint32_t>(Project::kFormat))
        return fail(
            QStringLiteral("format"),
            QStringLiteral("version %1 is newer than this CoScope reads (%2)").arg(*format).arg(Project::kFormat));
    p.format = static_cast<int>(*format);
    p.name = top.value(QStringLiteral("name")).toString();
    const QJsonObject bus = top.value(QStringLiteral("bus")).toObject();
    p.busUrl = bus.value(QStringLiteral("url")).toString();
    if (bus.contains(QStringLiteral("bitRate"))) {
        const auto rate = readU32(bus.value(QStringLiteral("bitRate")));
        if (!rate) return fail(QStringLiteral("bus.bitRate"), QStringLiteral("must be a number of bit/s"));
        p.bitRate = *rate;
    }
    const QJsonValue nodesValue = top.value(QStringLiteral("nodes"));
    if (!nodesValue.isUndefined() && !nodesValue.isArray())
        return fail(QStringLiteral("nodes"), QStringLiteral("must be a list"));
    const QJsonArray nodes = nodesValue.toArray();
    for (qsizetype i = 0; i < nodes.size(); ++i) {
        const QString key = QStringLiteral("nodes[%1]").arg(i);
        if (!nodes[i].isObject()) return fail(key, QStringLiteral("must be an object"));
        const QJsonObject o = nodes[i].toObject();
        ProjectNode n;
        const auto id = readU32(o.value(QStringLiteral("id")));
        if (!id || *id < 1 || *id > 127)
            return fail(key + QStringLiteral(".id"), QStringLiteral("must be a node-ID 1-127"));
        n.id = static_cast<uint8_t>(*id);
        if (p.node(n.id)) return fail(key + QStringLiteral(".id"), QStringLiteral("node %1 is listed twice").arg(n.id));
        n.name = o.value(QStringLiteral("name")).toString();
        n.dictionary = o.value(QStringLiteral("dictionary")).toString();
        const QJsonObject identity = o.value(QStringLiteral("identity")).toObject();
        const std::pair<const char*, std::optional<uint32_t>*> fields[] = {{"vendorId", &n.identity.vendorId},
                                                                           {"productCode", &n.identity.productCode},
                                                                           {"revision", &n.identity.revision},
                                                                           {"serial", &n.identity.serial}};
        for (const auto& [name, slot] : fields) {
            const QJsonValue v = identity.value(QLatin1String(name));
            if (v.isUndefined() || v.isNull()) continue;
            *slot = readU32(v);
            if (!*slot)
                return fail(QStringLiteral("%1.identity.%2").arg(key, QLatin1String(name)),
                            QStringLiteral("must be a 32-bit number"));
        }
        const QJsonArray params = o.value(QStringLiteral("parameters")).toArray();
        for (qsizetype j = 0; j < params.size(); ++j) {
            const QString pkey = QStringLiteral("%1.parameters[%2]").arg(key).arg(j);
            const QJsonObject po = params[j].toObject();
            ProjectParameter pp;
            if (!parseObjectKey(po.value(QStringLiteral("object")).toString(), &pp.index, &pp.sub))
                return fail(pkey + QStringLiteral(".object"),
                            QStringLiteral("must be INDEX:SUB in hex, e.g. \"6081:00\""));
            const QJsonValue value = po.value(QStringLiteral("value"));
            if (!value.isString())
                return fail(pkey + QStringLiteral(".value"),
                            QStringLiteral("must be the value as DCF text, e.g. \"0x01F4\""));
            pp.value = value.toString();
            pp.name = po.value(QStringLiteral("name")).toString();
            n.parameters.push_back(std::move(pp));
        }
        const QJsonValue fw = o.value(QStringLiteral("firmware"));
        if (!fw.isUndefined() && !fw.isNull()) {
            if (!fw.isObject())
                return fail(
                    key + QStringLiteral(".firmware"),
                    QStringLiteral("must be an object, e.g. {\"file\": \"drive-2.0.img\", \"version\": \"2.0\"}"));
            const QJsonObject fo = fw.toObject();
            ProjectFirmware f;
            f.file = fo.value(QStringLiteral("file")).toString();
            if (fo.contains(QStringLiteral("program"))) {
                const auto program = readU32(fo.value(QStringLiteral("program")));
                if (!program || *program < 1 || *program > 254)
                    return fail(key + QStringLiteral(".firmware.program"),
                                QStringLiteral("must be a program number 1-254"));
                f.program = static_cast<uint8_t>(*program);
            }
            const QJsonValue id = fo.value(QStringLiteral("softwareId"));
            if (!id.isUndefined() && !id.isNull()) {
                f.softwareId = readU32(id);
                if (!f.softwareId)
                    return fail(key + QStringLiteral(".firmware.softwareId"),
                                QStringLiteral("must be a 32-bit number"));
            }
            f.version = fo.value(QStringLiteral("version")).toString();
            n.firmware = std::move(f);
        }
        n.unknown = unknownKeys(o, kNodeKeys);
        p.nodes.push_back(std::move(n));
    }
    p.master = top.value(QStringLiteral("master")).toObject();
    p.transmit = top.value(QStringLiteral("transmit")).toArray();
    p.rawSignals = top.value(QStringLiteral("rawSignals")).toArray();
    p.plots = top.value(QStringLiteral("plots")).toObject();
    p.traceFilters = top.value(QStringLiteral("traceFilters")).toObject();
    p.unknown = unknownKeys(top, kTopKeys);
    r.project = std::move(p);
    return r;
}

QByteArray ProjectFile::serialize(const Project& p) {
    QJsonObject top = p.unknown;
    top.insert(QStringLiteral("format"), Project::kFormat);
    top.insert(QStringLiteral("generator"), QStringLiteral("CoScope"));
    if (!p.name.isEmpty()) top.insert(QStringLiteral("name"), p.name);
    QJsonObject bus;
    bus.insert(QStringLiteral("url"), p.busUrl);
    if (p.bitRate) bus.insert(QStringLiteral("bitRate"), static_cast<qint64>(p.bitRate));
    top.insert(QStringLiteral("bus"), bus);
    QJsonArray nodes;
    for (const ProjectNode& n : p.nodes) {
        QJsonObject o = n.unknown;
        o.insert(QStringLiteral("id"), n.id);
        if (!n.name.isEmpty()) o.insert(QStringLiteral("name"), n.name);
        o.insert(QStringLiteral("dictionary"), n.dictionary);
        QJsonObject identity;
        if (n.identity.vendorId) identity.insert(QStringLiteral("vendorId"), hex32Text(*n.identity.vendorId));
        if (n.identity.productCode) identity.insert(QStringLiteral("productCode"), hex32Text(*n.identity.productCode));
        if (n.identity.revision) identity.insert(QStringLiteral("revision"), hex32Text(*n.identity.revision));
        if (n.identity.serial) identity.insert(QStringLiteral("serial"), hex32Text(*n.identity.serial));
        o.insert(QStringLiteral("identity"), identity);
        QJsonArray params;
        for (const ProjectParameter& pp : n.parameters) {
            QJsonObject po;
            po.insert(QStringLiteral("object"), objectKey(pp.index, pp.sub));
            if (!pp.name.isEmpty()) po.insert(QStringLiteral("name"), pp.name);
            po.insert(QStringLiteral("value"), pp.value);
            params.append(po);
        }
        o.insert(QStringLiteral("parameters"), params);
        const QJsonArray pdos = pdoLayouts(n);
        if (!pdos.isEmpty()) o.insert(QStringLiteral("pdoLayouts"), pdos);
        if (n.firmware) {
            QJsonObject fo;
            if (!n.firmware->file.isEmpty()) fo.insert(QStringLiteral("file"), n.firmware->file);
            if (n.firmware->program != 1) fo.insert(QStringLiteral("program"), n.firmware->program);
            if (n.firmware->softwareId) fo.insert(QStringLiteral("softwareId"), hex32Text(*n.firmware->softwareId));
            if (!n.firmware->version.isEmpty()) fo.insert(QStringLiteral("version"), n.firmware->version);
            o.insert(QStringLiteral("firmware"), fo);
        }
        nodes.append(o);
    }
    top.insert(QStringLiteral("nodes"), nodes);
    if (!p.master.isEmpty()) top.insert(QStringLiteral("master"), p.master);
    if (!p.transmit.isEmpty()) top.insert(QStringLiteral("transmit"), p.transmit);
    if (!p.rawSignals.isEmpty()) top.insert(QStringLiteral("rawSignals"), p.rawSignals);
    if (!p.plots.isEmpty()) top.insert(QStringLiteral("plots"), p.plots);
    if (!p.traceFilters.isEmpty()) top.insert(QStringLiteral("traceFilters"), p.traceFilters);
    return QJsonDocument(top).toJson(QJsonDocument::Indented);
}

bool ProjectFile::write(const Project& project, const QString& path, QString* error) {
    QSaveFile f(path);
    if (!f.open(QIODevice::WriteOnly)) {
        if (error) *error = QStringLiteral("%1: cannot write: %2").arg(path, f.errorString());
        return false;
    }
    f.write(serialize(project));
    if (!f.commit()) {
        if (error) *error = QStringLiteral("%1: cannot write: %2").arg(path, f.errorString());
        return false;
    }
    return true;
}

}  // namespace coscope::project
