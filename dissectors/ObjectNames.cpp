// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/ObjectNames.h"

#include "dissectors/ParameterNames.h"
#include "dissectors/SidecarNames.h"

#include <QRegularExpression>

namespace coscope::dissect {

namespace {

QString key(std::uint16_t index, int sub) {
    QString k = QStringLiteral("%1").arg(index, 4, 16, QLatin1Char('0')).toUpper();
    if (sub >= 0) k += QStringLiteral(":%1").arg(sub, 2, 16, QLatin1Char('0')).toUpper();
    return k;
}

}  // namespace

QString localObjectName(const QString& bundledName, std::uint16_t index, int sub, const QString& edsName,
                        const QString& lang) {
    if (bundledName.isEmpty() || (lang != u"zh_TW" && lang != u"zh_CN")) return edsName;
    const SidecarSections& all = sidecarSections(QStringLiteral("objectNames"));
    const auto table = all.constFind(bundledName);
    if (table == all.constEnd()) return edsName;
    auto it = table->constFind(key(index, sub));
    // The objects of axis n of a multi-axis drive (CiA 402: index + 800h * (n - 1)).
    if (it == table->constEnd() && index >= 0x6800 && index < 0xA000)
        it = table->constFind(key(static_cast<std::uint16_t>(0x6000 + (index - 0x6000) % 0x800), sub));
    if (it == table->constEnd()) return edsName;
    QString zh = it->value(lang).toString();
    if (zh.isEmpty()) return edsName;
    static const QRegularExpression axis(QStringLiteral(R"( \(axis (\d+)\)$)"));
    if (const auto m = axis.match(edsName); m.hasMatch())
        zh += (lang == u"zh_TW" ? QStringLiteral(u"（第 %1 軸）") : QStringLiteral(u"（第 %1 轴）")).arg(m.captured(1));
    return zh;
}

QString localDisplayName(const od::ObjectDictionary& dict, std::uint16_t index, std::uint8_t sub, const QString& lang) {
    const od::Object* o = dict.object(index);
    if (!o) return {};
    QString name = localParameterName(localObjectName(dict.bundledName, index, -1, o->name, lang), lang);
    if (!o->isComposite()) return name;
    const od::SubObject* s = o->sub(sub);
    return s ? name + QStringLiteral(": ") +
                   localParameterName(localObjectName(dict.bundledName, index, sub, s->name, lang), lang)
             : name;
}

}  // namespace coscope::dissect
