// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/ds402/Ds402Units.h"

#include "core/od/Value.h"
#include "dissectors/DictionaryCatalog.h"

#include <QCoreApplication>
#include <QLocale>

#include <cmath>

namespace coscope::gui {

Ds402Units Ds402Units::forDictionary(const QString& dictionaryName) {
    auto fallback = [](const char* text) {
        return od::Unit{QCoreApplication::translate("coscope::gui::Ds402Units", text), 1.0};
    };
    Ds402Units u{fallback("units/s"), fallback("units/s"),  fallback("units"),
                 fallback("units"),   fallback("units/s"),  fallback("units/s²"),
                 fallback("units/s"), fallback("units/s²"), fallback("units")};
    if (dictionaryName.isEmpty()) return u;
    const dissect::DictionaryPtr od = eds::DictionaryLibrary::shared().loadShared(dictionaryName);
    if (!od) return u;
    auto take = [&](uint16_t index, od::Unit& into, uint8_t sub = 0) {
        if (const od::SubObject* e = od->entry(index, sub);
            e && e->unit && !e->unit->text.isEmpty() && e->unit->factor > 0)
            into = *e->unit;
    };
    take(0x60FF, u.jogVelocity);
    take(0x6081, u.profileVelocity);
    take(0x607A, u.distance);
    take(0x6064, u.position);
    take(0x606C, u.velocity);
    take(0x6083, u.profileAcceleration);
    take(0x6099, u.homingSpeed, 1);
    take(0x609A, u.homingAcceleration);
    take(0x607C, u.homeOffset);
    return u;
}

QString inUnit(double raw, const od::Unit& unit) {
    od::FormatOptions o;
    o.unit = unit.text;
    o.factor = unit.factor;
    return od::Value::format(od::DataType::Integer32, od::Value::signedInt(static_cast<int64_t>(std::llround(raw))), o);
}

QString rawUnitSuffix(const od::Unit& unit) {
    if (unit.factor == 1.0) return QStringLiteral(" ") + unit.text;
    return QStringLiteral(" × %1 %2").arg(QLocale().toString(unit.factor, 'g', 6), unit.text);
}

int unitDecimals(const od::Unit& unit) {
    if (unit.factor >= 1.0 || unit.factor <= 0) return 0;
    return std::min(6, static_cast<int>(std::ceil(-std::log10(unit.factor) - 1e-9)));
}

}  // namespace coscope::gui
