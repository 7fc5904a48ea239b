// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/od/DataType.h"
#include "dissectors/Dissection.h"

#include <QString>

#include <cstdint>

namespace coscope::dissect {

// Decodes `len` little-endian bytes as `type` (CiA 301 §7.1) into a flat value: integers as
// Int/UInt, REAL32/64 as Real, strings as Text, anything else as hex text. typeKnown = false:
// 1..8 bytes as an unsigned integer, longer data as text when printable, else hex.
// Returns the display text (with unit and factor applied when given).
QString decodeValue(od::DataType type, bool typeKnown, const uint8_t* data, int len, FlatField& value,
                    const QString& unit = {}, double factor = 1.0);

// Same for a bit field of a PDO: `bits` bits starting at bit `bitOffset` of `data`.
QString decodeBits(od::DataType type, bool typeKnown, const uint8_t* data, int bitOffset, int bits, FlatField& value,
                   const QString& unit = {}, double factor = 1.0);

// The value as JSON-ish text without unit: for summaries and the SDO record.
QString valueText(const FlatField& v);

}  // namespace coscope::dissect
