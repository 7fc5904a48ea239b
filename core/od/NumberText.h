// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstdint>
#include <optional>

namespace coscope::od {

// How integers written as text are read.
//  Field:  what the app's integer fields take (README "Numbers"): decimal "31", "-5", "007"
//          (= 7, leading zeros are decimal), hex as C writes it "0x1F" / "0X1f" or as CiA 301
//          writes it "1Fh" / "1fH" (the way the app shows hex values).
//  Person: Field, and binary "0b101" (the CLI, scripts).
//  Eds:    CiA 306 v1.3 4.5.1: "0x" hex, a leading 0 means octal ("010" = 8) when every digit
//          is 0..7; a leading-zero number with an 8 or 9 falls back to decimal.
enum class TextStyle : std::uint8_t { Person, Eds, Field };

// A parsed integer: magnitude plus sign, so both INTEGER64 and UNSIGNED64 ranges fit.
struct ParsedInteger {
    std::uint64_t magnitude = 0;
    bool negative = false;
    bool hex = false;  // written as 0x or with suffix h (a bit pattern for signed types)
};

std::optional<ParsedInteger> parseIntegerText(const QString& text, TextStyle style);

// CiA 306 4.5.1: "$NODEID+0x180", "0x180+$NODEID", "$NODEID" (case-insensitive, spaces allowed).
bool containsNodeId(const QString& text);
// Sum of the terms with $NODEID replaced by nodeId; nullopt when a term is not a number.
std::optional<std::uint64_t> evaluateNodeIdFormula(const QString& text, std::uint8_t nodeId);

}  // namespace coscope::od
