// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/od/ObjectDictionary.h"

#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace coscope::canopen {

// Which PDO: TPDO n uses 1800h/1A00h + n-1, RPDO n 1400h/1600h + n-1 (CiA 301 §7.5.2.35-38).
struct PdoId {
    bool transmit = true;
    int number = 1;  // 1..512
    uint16_t communicationIndex() const { return static_cast<uint16_t>((transmit ? 0x1800 : 0x1400) + number - 1); }
    uint16_t mappingIndex() const { return static_cast<uint16_t>((transmit ? 0x1A00 : 0x1600) + number - 1); }
    QString name() const {
        return QStringLiteral("%1%2").arg(transmit ? QStringLiteral("TPDO") : QStringLiteral("RPDO")).arg(number);
    }
    // Default COB-ID of PDOs 1..4 (CiA 301 §7.3.5): TPDO1 180h + node ... RPDO4 500h + node.
    uint32_t defaultCobId(uint8_t node) const;
};
// "tpdo1", "RPDO4" -> PdoId.
std::optional<PdoId> parsePdoName(const QString& text);

// One mapping entry: index, sub-index and length in bits (CiA 301 §7.5.2.36: IIIISSLL).
struct PdoMapEntry {
    uint16_t index = 0;
    uint8_t sub = 0;
    uint8_t bits = 0;
    uint32_t encode() const { return (uint32_t(index) << 16) | (uint32_t(sub) << 8) | bits; }
    static PdoMapEntry decode(uint32_t v) {
        return {static_cast<uint16_t>(v >> 16), static_cast<uint8_t>(v >> 8), static_cast<uint8_t>(v)};
    }
    bool operator==(const PdoMapEntry&) const = default;
};
// "6041:00,6064:00" or with lengths "6041:00/16,6064:00/32".
std::optional<std::vector<PdoMapEntry>> parsePdoEntries(const QString& text, QString* error);

// A PDO's communication parameters and mapping.
struct PdoConfig {
    uint32_t cobId = 0;  // bit 31 set = PDO not valid
    uint8_t transmissionType = 0xFF;
    std::optional<uint16_t> inhibitTime;  // 100 µs units (sub 3)
    std::optional<uint16_t> eventTimer;   // ms (sub 5)
    std::vector<PdoMapEntry> entries;
    bool valid() const { return !(cobId & 0x80000000u); }
    int totalBits() const;
};

// Checks a mapping before anything is sent: each object exists in the dictionary, may be
// mapped (PDOMapping=1; dummy types 0001h-0007h are always allowed), is readable for a TPDO or
// writable for an RPDO; lengths of 0 are filled in from the data type; the sum is <= 64 bits
// (classic CAN payload). Without a dictionary every length must be given. False + *error
// ("6041:00 is not PDO-mappable").
bool validatePdoMapping(std::vector<PdoMapEntry>& entries, const PdoId& pdo, const od::ObjectDictionary* dictionary,
                        QString* error);

}  // namespace coscope::canopen
