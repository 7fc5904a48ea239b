// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/SignalScaling.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

#include <map>
#include <mutex>

namespace coscope::dissect {

namespace {
// "6093:02" -> index, sub.
bool parseObject(const QString& text, uint16_t& index, uint8_t& sub) {
    const QStringList parts = text.split(u':');
    bool ok1 = false, ok2 = parts.size() == 2;
    const uint idx = parts.value(0).toUInt(&ok1, 16);
    const uint sb = ok2 ? parts.value(1).toUInt(&ok2, 16) : 0;
    if (!ok1 || !ok2 || idx > 0xFFFF || sb > 0xFF) return false;
    index = static_cast<uint16_t>(idx);
    sub = static_cast<uint8_t>(sb);
    return true;
}

QJsonObject sidecar(const QString& name) {
    QFile f(QStringLiteral(":/dictionaries/%1.json").arg(name));
    if (name.isEmpty() || !f.open(QIODevice::ReadOnly)) return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

std::optional<RevolutionRule> readRule(const QString& name) {
    const QJsonObject r =
        sidecar(name).value(QStringLiteral("scaling")).toObject().value(QStringLiteral("revolution")).toObject();
    RevolutionRule rule;
    rule.countUnit = r.value(QStringLiteral("countUnit")).toString();
    rule.countsPerRevolution = r.value(QStringLiteral("countsPerRevolution")).toDouble();
    if (rule.countUnit.isEmpty() || !(rule.countsPerRevolution > 0)) return std::nullopt;
    if (!parseObject(r.value(QStringLiteral("multiplyBy")).toString(), rule.multiplyIndex, rule.multiplySub))
        rule.multiplyIndex = 0;
    if (!parseObject(r.value(QStringLiteral("divideBy")).toString(), rule.divideIndex, rule.divideSub))
        rule.divideIndex = 0;
    return rule;
}
}  // namespace

std::optional<RevolutionRule> revolutionRule(const QString& dictionaryName) {
    static std::mutex mutex;
    static std::map<QString, std::optional<RevolutionRule>> cache;
    std::lock_guard lock(mutex);
    auto it = cache.find(dictionaryName);
    if (it == cache.end()) it = cache.emplace(dictionaryName, readRule(dictionaryName)).first;
    return it->second;
}

std::optional<SignalScale> sidecarUnit(const QString& dictionaryName, uint16_t index, uint8_t sub) {
    static std::mutex mutex;
    static std::map<QString, QJsonObject> cache;
    std::lock_guard lock(mutex);
    auto it = cache.find(dictionaryName);
    if (it == cache.end())
        it = cache.emplace(dictionaryName, sidecar(dictionaryName).value(QStringLiteral("units")).toObject()).first;
    const QString key =
        QStringLiteral("%1:%2").arg(index, 4, 16, QLatin1Char('0')).arg(sub, 2, 16, QLatin1Char('0')).toUpper();
    const QJsonObject u = it->second.value(key).toObject();
    if (u.isEmpty()) return std::nullopt;
    return SignalScale{u.value(QStringLiteral("factor")).toDouble(1.0), 0.0,
                       u.value(QStringLiteral("unit")).toString()};
}

SignalScale engineeringScale(const QString& dictionaryName, const QString& unit, double factor,
                             const ParameterLookup& params) {
    SignalScale s{factor, 0.0, unit};
    const std::optional<RevolutionRule> rule = revolutionRule(dictionaryName);
    if (!rule || unit.isEmpty()) return s;
    const bool position = unit == rule->countUnit;
    const bool speed = unit == rule->countUnit + QStringLiteral("/s");
    if (!position && !speed) return s;
    auto param = [&](uint16_t index, uint8_t sub) {
        if (!index || !params) return 1.0;
        const std::optional<double> v = params(index, sub);
        return v && *v != 0 ? *v : 1.0;  // a zero gear would divide by zero: keep the default
    };
    const double perRev = rule->countsPerRevolution * param(rule->multiplyIndex, rule->multiplySub) /
                          param(rule->divideIndex, rule->divideSub);
    if (!(perRev > 0)) return s;
    // Written as the fraction it is: 1/1280000 rev per PUU, 60/1280000 rpm per PUU/s.
    const double top = position ? factor : factor * 60.0;
    const QString written =
        QStringLiteral("%1/%2").arg(QString::number(top, 'g', 15), QString::number(perRev, 'g', 15));
    return {top / perRev, 0.0, position ? QStringLiteral("rev") : QStringLiteral("rpm"), written};
}

QString factorText(const SignalScale& scale) {
    if (!scale.factorWritten.isEmpty() && parseFactor(scale.factorWritten) == scale.factor) return scale.factorWritten;
    return QString::number(scale.factor, 'g', 10);
}

std::optional<double> parseFactor(const QString& text) {
    const QString t = text.trimmed();
    bool ok = false;
    double v = 0;
    if (const qsizetype slash = t.indexOf(u'/'); slash > 0) {
        bool okDen = false;
        const double num = t.left(slash).trimmed().toDouble(&ok), den = t.mid(slash + 1).trimmed().toDouble(&okDen);
        ok = ok && okDen && den != 0;
        if (ok) v = num / den;
    } else {
        v = t.toDouble(&ok);
    }
    if (!ok || v == 0 || !std::isfinite(v)) return std::nullopt;
    return v;
}

}  // namespace coscope::dissect
