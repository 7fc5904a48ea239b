// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "dissectors/PdoMapping.h"
#include "dissectors/SignalScaling.h"

#include <QString>

#include <compare>
#include <cstdint>
#include <optional>

namespace coscope::dissect {

// A plottable signal: one object mapped into a PDO of one node on one bus, one bit of a
// CiA 402 controlword/statusword (bit >= 0), or a raw signal the user defined for a COB-ID
// (RawSignal.h; raw = its number, 1-based, node/index/sub 0).
struct SignalKey {
    uint8_t bus = 0;
    uint8_t node = 0;
    uint16_t index = 0;
    uint8_t sub = 0;
    int8_t bit = -1;
    uint16_t raw = 0;

    // NOLINTNEXTLINE(modernize-use-nullptr): clang-tidy 14 takes this "= default" for a 0.
    auto operator<=>(const SignalKey&) const = default;
    SignalKey word() const { return {bus, node, index, sub, -1, raw}; }
    uint64_t packed() const {
        return uint64_t(raw) << 48 | uint64_t(bus) << 40 | uint64_t(node) << 32 | uint64_t(index) << 16 |
               uint64_t(sub) << 8 | uint64_t(uint8_t(bit + 1));
    }
    // "n2 6064:00", "n2 6041:00.10" (with "bus1 " in front for buses other than the first).
    QString text() const;
    // Reads text() back ("raw3" too); nullopt for anything else.
    static std::optional<SignalKey> parse(const QString& text);
};

// What the catalogue says about a signal.
struct SignalInfo {
    SignalKey key;
    QString name;        // the dictionary's name ("Position actual value"), or of the bit
    QString object;      // "6064:00", "6041:00 bit 10"
    QString pdo;         // the PDO that carries it ("TPDO1")
    QString dictionary;  // the node's dictionary name ("" = unknown device)
    QString rawUnit;     // as the dictionary states it ("0.1 rpm" is rawUnit "rpm", rawFactor 0.1)
    double rawFactor = 1.0;
    SignalScale scale;  // the default engineering scale
    bool digital = false;
    uint32_t cobId = 0;  // raw signals: the COB-ID they are read from
};

// The CiA 402 words whose bits are offered as digital traces: controlword 6040h and
// statusword 6041h of any axis (+ n x 800h, CiA 402-1 §5).
bool hasDigitalBits(uint16_t index, uint8_t sub);
// Short name of bit `bit` of 6040h/6041h (CiA 402-2 §6.3.1 / §6.3.2; extract-delta §4.1/4.2).
// Statusword bits 12/13 are named by the axis' mode of operation `mode` (6061h) when known, as
// canopen::ds402::statuswordBitName() names them for the trace (HM: "homing attained"/"homing error").
QString digitalBitName(uint16_t index, int bit, std::optional<int8_t> mode = std::nullopt);

// The value of a mapped object in a PDO payload, starting at bit `bitOffset` (CiA 301 §7.2.2:
// least significant bit first), typed by the mapping (signed integers sign-extended, REAL32/64
// as IEEE 754); nullopt when the payload is too short or the type is not numeric.
std::optional<double> pdoValue(const PdoMapEntry& e, const uint8_t* data, int len, int bitOffset);

}  // namespace coscope::dissect
