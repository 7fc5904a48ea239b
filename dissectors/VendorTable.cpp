// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/VendorTable.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <spdlog/spdlog.h>

#include <map>
#include <memory>
#include <mutex>

namespace coscope::dissect {

namespace {

uint32_t number(const QJsonValue& v, bool* ok) {
    if (v.isDouble()) {
        *ok = true;
        return static_cast<uint32_t>(v.toDouble());
    }
    return v.toString().toUInt(ok, 0);
}

std::unique_ptr<VendorTable> readTable(const QString& name) {
    QFile f(QStringLiteral(":/alarms/%1.json").arg(name));
    if (!f.open(QIODevice::ReadOnly)) return nullptr;
    QJsonParseError err;
    const QJsonObject root = QJsonDocument::fromJson(f.readAll(), &err).object();
    if (err.error != QJsonParseError::NoError) {
        spdlog::warn("alarm table {}: {}", name.toStdString(), err.errorString().toStdString());
        return nullptr;
    }
    auto t = std::make_unique<VendorTable>();
    t->name = name;
    const QJsonObject layout = root.value(QStringLiteral("emcyLayout")).toObject();
    t->verified = layout.value(QStringLiteral("verified")).toBool(true);
    for (const QJsonValue fv : layout.value(QStringLiteral("alarmFields")).toArray()) {
        const QJsonObject fo = fv.toObject();
        const QJsonArray bytes = fo.value(QStringLiteral("bytes")).toArray();
        if (bytes.isEmpty()) continue;
        VendorTable::AlarmField af;
        af.name = fo.value(QStringLiteral("name")).toString();
        af.firstByte = bytes.at(0).toInt(3);
        af.u16 = fo.value(QStringLiteral("encoding")).toString() == QLatin1String("u16le");
        af.motor = fo.value(QStringLiteral("motor")).toInt(0);
        if (af.firstByte < 3 || af.firstByte + (af.u16 ? 2 : 1) > 8) continue;
        t->fields.push_back(af);
    }
    for (const QJsonValue av : root.value(QStringLiteral("alarms")).toArray()) {
        const QJsonObject ao = av.toObject();
        VendorTable::Alarm a;
        a.code = ao.value(QStringLiteral("code")).toString();
        a.text = ao.value(QStringLiteral("text")).toString();
        a.textZhTW = ao.value(QStringLiteral("name_zh_TW")).toString();
        a.textZhCN = ao.value(QStringLiteral("name_zh_CN")).toString();
        bool ok = false;
        const uint32_t ec = number(ao.value(QStringLiteral("emcyCode")), &ok);
        a.emcyCode = ok ? static_cast<int>(ec) : -1;
        const uint32_t n = number(ao.value(QStringLiteral("number")), &ok);
        if (ok) t->alarms.insert(n, a);
        for (const QJsonValue also : ao.value(QStringLiteral("alsoNumbers")).toArray()) {
            const uint32_t m = number(also, &ok);
            if (ok && !t->alarms.contains(m)) t->alarms.insert(m, a);
        }
    }
    for (const QJsonValue sv : root.value(QStringLiteral("sdoAborts")).toArray()) {
        const QJsonObject so = sv.toObject();
        bool ok = false;
        const uint32_t code = number(so.value(QStringLiteral("code")), &ok);
        if (ok) t->aborts.insert(code, so.value(QStringLiteral("text")).toString());
    }
    return t;
}

std::mutex& languageMutex() {
    static std::mutex m;
    return m;
}

QString& languageValue() {
    static QString lang = QStringLiteral("en");
    return lang;
}

}  // namespace

void setVendorTextLanguage(const QString& lang) {
    std::lock_guard lock(languageMutex());
    languageValue() = lang.isEmpty() ? QStringLiteral("en") : lang;
}

QString vendorTextLanguage() {
    std::lock_guard lock(languageMutex());
    return languageValue();
}

QString VendorTable::Alarm::textIn(const QString& lang) const {
    // Chinese names as printed in the manuals (Delta CANopen manual 4.2, AIMOTOR manual 6.1).
    const QString& zh = lang == u"zh_TW" ? textZhTW : lang == u"zh_CN" ? textZhCN : text;
    return zh.isEmpty() ? text : zh;
}

QString VendorTable::decodeEmcy(const uint8_t* data, int len, uint16_t emcyCode) const {
    QStringList parts;
    for (const AlarmField& f : fields) {
        if (f.firstByte + (f.u16 ? 2 : 1) > len) continue;
        const uint32_t v = f.u16 ? uint32_t(data[f.firstByte] | (data[f.firstByte + 1] << 8)) : data[f.firstByte];
        const QString prefix = f.motor ? QStringLiteral("M%1 ").arg(f.motor) : QString();
        auto it = alarms.constFind(v);
        if (it != alarms.constEnd()) {
            // Unverified layouts: accept the value only when its alarm comes with this error code.
            if (!verified && it->emcyCode >= 0 && it->emcyCode != emcyCode) continue;
            parts << prefix + it->code + QStringLiteral(" ") + it->localText();
        } else if (f.motor) {
            // Per-motor alarm bytes (DEXMART): show the code even when its meaning is not documented.
            if (v) parts << QStringLiteral("M%1 alarm %2").arg(f.motor).arg(v);
        } else if (verified && v) {
            parts << QStringLiteral("%1 0x%2 (not in the table)").arg(f.name).arg(v, 4, 16, QLatin1Char('0'));
        }
    }
    return parts.join(QStringLiteral("; "));
}

const VendorTable* vendorTable(const QString& name) {
    static std::mutex m;
    static std::map<QString, std::unique_ptr<VendorTable>> cache;
    if (name.isEmpty()) return nullptr;
    std::lock_guard lock(m);
    auto it = cache.find(name);
    if (it == cache.end()) it = cache.emplace(name, readTable(name)).first;
    return it->second.get();
}

}  // namespace coscope::dissect
