// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/od/DataType.h"
#include "core/od/NumberNotation.h"

#include <QString>

#include <cstdint>
#include <vector>

namespace coscope::od {
class ObjectDictionary;
}

namespace coscope::dissect {

// One mapped object of a PDO (CiA 301 §7.5.2.36: mapping entry = index << 16 | sub << 8 | bits),
// with what decoding it needs resolved once, when the mapping is set.
struct PdoMapEntry {
    uint16_t index = 0;
    uint8_t sub = 0;
    uint8_t bits = 0;
    od::DataType type = od::DataType::Unsigned32;
    bool typeKnown = false;                       // from the dictionary; otherwise unsigned of `bits`
    bool dummy = false;                           // index 0001h..0007h: a gap (CiA 301 §7.4.7.1 dummy mapping)
    bool hex = false;                             // written in hex (controlword, statusword…: od/NumberNotation.h)
    od::HexKind hexKind = od::HexKind::None;      // od::hexKindFor(index, sub); hex = not None
    od::TypeClass cls = od::TypeClass::Unsigned;  // od::typeClass(type) when typeKnown, else Unsigned
    QString name;
    QString unit;
    double factor = 1.0;
    // The summary's text around the value, made once with the entry (PdoDissector): ", " name
    // " = " before it (the first signal drops the comma) and " " unit after it (empty: no unit).
    QString label;
    QString unitText;
};

// Communication and mapping parameters of one PDO (1400h/1600h for RPDOs, 1800h/1A00h for TPDOs).
struct PdoConfig {
    bool cobIdKnown = false;
    uint32_t cobId = 0;  // 1400h/1800h sub 1 as written (bit 31 = not valid, bit 29 = 29-bit id)
    bool mappingKnown = false;
    uint8_t count = 0;                 // sub 0 of the mapping object
    std::vector<PdoMapEntry> entries;  // subs 1..64 as known (index 0 = sub 1)

    bool valid() const { return cobIdKnown && !(cobId & 0x80000000u); }
    uint32_t canId() const { return cobId & ((cobId & 0x20000000u) ? 0x1FFFFFFFu : 0x7FFu); }
    int mappedBits() const {  // inline: every PDO frame checks its length by it
        int bits = 0;
        const int n = count < static_cast<int>(entries.size()) ? count : static_cast<int>(entries.size());
        for (int i = 0; i < n; ++i) bits += entries[static_cast<size_t>(i)].bits;
        return bits;
    }
};

// Fills `e` from a raw mapping value, resolving name/type/unit in `dict` (may be null).
PdoMapEntry makeMapEntry(uint32_t raw, const od::ObjectDictionary* dict);

// PDO parameter object classification: 1400h..15FFh RPDO comm, 1600h..17FFh RPDO mapping,
// 1800h..19FFh TPDO comm, 1A00h..1BFFh TPDO mapping (CiA 301 §7.5.2.35..38).
struct PdoObject {
    bool isPdo = false;
    bool tpdo = false;
    bool mapping = false;
    int number = 0;  // 1-based PDO number
};
PdoObject classifyPdoObject(uint16_t index);

}  // namespace coscope::dissect
