// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"
#include "dissectors/Dissection.h"
#include "dissectors/SignalScaling.h"

#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace coscope::dissect {

// A signal defined by hand for a frame whose device has no dictionary ("raw signal"): bits of
// one COB-ID's payload, with the DBC conventions so it exports to a DBC file unchanged:
// - Intel (little-endian, DBC "@1"): `startBit` is the least significant bit, bits counted
//   LSB first (bit k of byte n = 8n + k) - the CANopen PDO layout (CiA 301 §7.2.2.4);
// - Motorola (big-endian, DBC "@0"): `startBit` is the most significant bit in the same
//   numbering, the following bits taken towards bit 0 of that byte, then bit 7 of the next.
// value = raw x factor + offset, in `unit`; float types are IEEE 754 of 32 or 64 bits.
struct RawSignal {
    enum class Type : uint8_t { Unsigned, Signed, Float };
    enum class Order : uint8_t { Intel, Motorola };

    QString name;
    uint32_t cobId = 0;
    bool extended = false;  // a 29-bit identifier
    int startBit = 0;
    int length = 8;
    Type type = Type::Unsigned;
    Order order = Order::Intel;
    double factor = 1.0;
    double offset = 0.0;
    QString unit;

    bool matches(const CanFrame& f) const { return f.id == cobId && f.isExtended() == extended && !f.isRemote(); }
    // The raw value (before factor and offset); nullopt when the payload is too short.
    std::optional<double> rawValue(const uint8_t* data, int len) const;
    std::optional<double> value(const uint8_t* data, int len) const;
    SignalScale scale() const { return {factor, offset, unit}; }
    // The payload bytes the signal needs (its last bit's byte + 1).
    int bytesNeeded() const;
    // Empty when the definition is usable, else why not ("length 0", "float must be 32 or 64 bits").
    QString problem() const;

    // The command-line form NAME=COBID:START:LEN:TYPE[:FACTOR[:OFFSET[:UNIT]]], TYPE one of
    // u (unsigned), s (signed), f (float), Intel; a "@0" after it for Motorola ("s@0"), "@1"
    // for Intel. COBID decimal or 0x hex; a value over 7FFh or with an "x" suffix ("0x18FF00x")
    // is a 29-bit identifier.
    static std::optional<RawSignal> parse(const QString& spec, QString* error = nullptr);
    QString spec() const;

    bool operator==(const RawSignal&) const = default;
};

// The raw signals of a frame added to its dissection as PDO signals (PdoSignal::raw), and to
// the summary after the frame's own decoding: "  | speed = 12.5 rpm".
void applyRawSignals(const std::vector<RawSignal>& raw, const CanFrame& f, Dissection& d);

}  // namespace coscope::dissect
