// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/od/NumberNotation.h"
#include "core/od/Value.h"

#include <utility>

namespace coscope::od {

// What a person typed into an integer field of the app (the Object Dictionary dock's editor, the
// wizards' fields), read by the one rule of README "Numbers" (TextStyle::Field): decimal "31",
// "-5", hex "0x1F" / "1Fh" (either case); a hex number is the type's bit pattern.
struct IntegerInput {
    enum class Problem : std::uint8_t {
        None,
        Empty,
        NotANumber,  // anything but decimal, 0x1F or 1Fh
        OutOfRange,  // a number outside [low, high]
    };
    Problem problem = Problem::None;
    Value value;  // the value read, when problem is None
    // The values the field takes: the type's range narrowed by the entry's LowLimit/HighLimit.
    Value low, high;
    bool ok() const { return problem == Problem::None; }
};

IntegerInput readInteger(DataType type, const QString& text, const Limits& limits = {});

// The range `type` takes within `limits` (the low and high of readInteger).
std::pair<Value, Value> integerRange(DataType type, const Limits& limits = {});

// `value` as an integer field shows it: in the notation of its object (kind from hexKindFor:
// "001Fh" for 6040h, "182h" for a COB-ID), else decimal.
QString integerText(DataType type, const Value& value, HexKind kind);

}  // namespace coscope::od
