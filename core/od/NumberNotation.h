// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstdint>

namespace coscope::od {

// One rule for how the app writes the numbers of the object dictionary (trace summaries and
// field trees, wizard frames panes, step tables, wizard pages, the Object Dictionary dock):
//
//  * Identifiers and bit patterns are hexadecimal as CiA 301 writes them: upper-case digits,
//    zero-padded to the object's size, suffix "h" (controlword "0006h", statusword "0650h",
//    mapping entry "60410010h"). Indexes are written the same way ("6041h", "1A00h:01").
//  * A COB-ID is its 11-bit CAN-ID when no flag bit is set ("182h"), else all 32 bits
//    ("80000182h": bit 31 = not valid, bit 30 = no RTR, bit 29 = 29-bit CAN-ID; CiA 301 §7.5.2).
//  * Everything else (times, counts, positions, velocities, node-IDs…) is decimal with its unit.
//
// Which objects are hex is decided by their place in the dictionary (hexKindFor):
//   COB-IDs    1005h, 1012h, 1014h; 1028h subs 01..7Fh; SDO parameters 1200h..12FFh subs 01..02;
//              PDO communication parameters 1400h..15FFh and 1800h..19FFh sub 01
//   bit fields 1000h device type, 1001h error register, 1002h, 1003h subs 01..FEh (error codes),
//              1010h/1011h subs 01.. (store/restore signatures), 1016h subs 01.. (node-ID and time),
//              1018h subs 01..04 (identity), 1F80h NMT start-up;
//              PDO mapping entries 1600h..17FFh and 1A00h..1BFFh subs 01..40h
//   CiA 402    603Fh error code, 6040h controlword, 6041h statusword, 6502h supported modes,
//              60FDh digital inputs, 60FEh digital outputs (each axis: + n x 800h, CiA 402-1 §5)
enum class HexKind : std::uint8_t { None, Pattern, CobId };

HexKind hexKindFor(std::uint16_t index, std::uint8_t sub);

// "0650h": upper-case hex of `value`, at least `digits` digits, suffix h.
QString hexText(std::uint64_t value, int digits = 0);
// The same written to `out` (room for kHexTextRoom units, `digits` <= 16), no allocation;
// returns the number of units written. For hot paths (trace summaries).
inline constexpr int kHexTextRoom = 18;
int hexTextTo(char16_t* out, std::uint64_t value, int digits = 0);

// "6041h:00".
QString objectText(std::uint16_t index, std::uint8_t sub);

// The value of index:sub as the rule writes it, from its `bits` raw bits (unsigned, as on the
// wire): hex for the objects above, empty for the rest (the caller writes those in decimal with
// their unit, as the data type says).
QString hexValueText(std::uint16_t index, std::uint8_t sub, std::uint64_t raw, int bits);
// The same written to `out` (room for kHexTextRoom units); returns its length, 0 = not hex.
int hexValueTextTo(char16_t* out, std::uint16_t index, std::uint8_t sub, std::uint64_t raw, int bits);
// The same with hexKindFor(index, sub) already known.
int hexValueTextTo(char16_t* out, HexKind kind, std::uint64_t raw, int bits);

// The PDO transmission types with a name (CiA 301 §7.2.2.2, 1400h..15FFh / 1800h..19FFh sub 02):
// 255 "FFh (event)", 254 "FEh (event, manufacturer)"; the others decimal (0, a SYNC count, 252…).
QString transmissionTypeText(std::uint64_t type);
// transmissionTypeText() of 254/255 for index:sub when it is a PDO's transmission type, else empty.
QString namedValueText(std::uint16_t index, std::uint8_t sub, std::uint64_t raw);

// Same for a value whose data type is not known (a script step, an SDO without a dictionary):
// the hex text when the rule says hex, else decimal; a value whose top bit is set may be negative,
// so it reads "-100 (FFFFFF9Ch)".
QString valueText(std::uint16_t index, std::uint8_t sub, std::uint64_t raw, int bits);

}  // namespace coscope::od
