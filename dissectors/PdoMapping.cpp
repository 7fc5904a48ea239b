// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/PdoMapping.h"

#include "core/od/NumberNotation.h"
#include "core/od/ObjectDictionary.h"
#include "core/od/PermanentText.h"

namespace coscope::dissect {

PdoMapEntry makeMapEntry(uint32_t raw, const od::ObjectDictionary* dict) {
    PdoMapEntry e;
    e.index = static_cast<uint16_t>(raw >> 16);
    e.sub = static_cast<uint8_t>(raw >> 8);
    e.bits = static_cast<uint8_t>(raw);
    e.dummy = e.index >= 0x0001 && e.index <= 0x0007;
    if (e.dummy) {
        e.type = static_cast<od::DataType>(e.index);
        e.typeKnown = true;
        e.name = QStringLiteral("(dummy)");
        return e;
    }
    if (dict) {
        if (const od::SubObject* so = dict->entry(e.index, e.sub)) {
            e.type = so->dataType;
            e.typeKnown = od::isKnownBasicType(so->dataType) && od::bitSize(so->dataType) == e.bits;
            e.name = dict->displayName(e.index, e.sub);
            if (auto u = dict->unit(e.index, e.sub)) {
                e.unit = u->text;
                e.factor = u->factor;
            }
        }
    }
    e.hexKind = od::hexKindFor(e.index, e.sub);
    e.hex = e.hexKind != od::HexKind::None;
    e.cls = e.typeKnown ? od::typeClass(e.type) : od::TypeClass::Unsigned;
    if (e.name.isEmpty())
        e.name =
            QStringLiteral("%1:%2").arg(e.index, 4, 16, QLatin1Char('0')).arg(e.sub, 2, 16, QLatin1Char('0')).toUpper();
    // Copied into every decoded signal of every frame: without reference counting.
    e.name = od::permanentText(e.name);
    e.unit = od::permanentText(e.unit);
    // Permanent too: a PdoTextValue points to them after the mapping has changed.
    e.label = od::permanentText(QStringLiteral(", ") + e.name + QStringLiteral(" = "));
    if (!e.unit.isEmpty()) e.unitText = od::permanentText(u' ' + e.unit);
    return e;
}

PdoObject classifyPdoObject(uint16_t index) {
    PdoObject o;
    if (index >= 0x1400 && index <= 0x1BFF) {
        o.isPdo = true;
        o.tpdo = index >= 0x1800;
        o.mapping = (index & 0x0200) != 0;
        o.number = (index & 0x01FF) + 1;
    }
    return o;
}

}  // namespace coscope::dissect
