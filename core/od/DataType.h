// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstdint>
#include <optional>

namespace coscope::od {

// Data type codes of the object dictionary (CiA 301 v4.2, 7.4.7.1 table 44). Static data
// types live at index 0x0001..0x001F of the dictionary; codes outside this list (custom
// DEFTYPE/DEFSTRUCT, 0x0020..0x025F) are kept as their number and treated as DOMAIN bytes.
enum class DataType : std::uint16_t {
    Boolean = 0x0001,
    Integer8 = 0x0002,
    Integer16 = 0x0003,
    Integer32 = 0x0004,
    Unsigned8 = 0x0005,
    Unsigned16 = 0x0006,
    Unsigned32 = 0x0007,
    Real32 = 0x0008,
    VisibleString = 0x0009,
    OctetString = 0x000A,
    UnicodeString = 0x000B,
    TimeOfDay = 0x000C,
    TimeDifference = 0x000D,
    Domain = 0x000F,
    Integer24 = 0x0010,
    Real64 = 0x0011,
    Integer40 = 0x0012,
    Integer48 = 0x0013,
    Integer56 = 0x0014,
    Integer64 = 0x0015,
    Unsigned24 = 0x0016,
    Unsigned40 = 0x0018,
    Unsigned48 = 0x0019,
    Unsigned56 = 0x001A,
    Unsigned64 = 0x001B,
    // Complex types predefined by CiA 301 (DEFSTRUCT records).
    PdoCommunicationParameter = 0x0020,
    PdoMapping = 0x0021,
    SdoParameter = 0x0022,
    Identity = 0x0023,
};

// How a type is represented in od::Value.
enum class TypeClass : std::uint8_t {
    Boolean,
    Signed,
    Unsigned,
    Real,
    VisibleString,
    OctetString,
    UnicodeString,
    Time,
    Domain
};

TypeClass typeClass(DataType t);
// Size in bits on the bus (BOOLEAN counts as 8 bits in SDO/PDO payloads: CiA 301 7.1.4.2
// packs it as 1 bit in PDOs, we report 1); 0 for variable-size types (strings, DOMAIN).
int bitSize(DataType t);
// Size in bytes of the little-endian encoding, 0 when variable.
int byteSize(DataType t);
// "UNSIGNED16"; unknown codes as "DATATYPE_0040".
QString dataTypeName(DataType t);
// Parses a CiA 301 name ("UNSIGNED16", case-insensitive) or a number ("0x0006", "6").
std::optional<DataType> dataTypeFromString(const QString& text);
bool isKnownBasicType(DataType t);
bool isInteger(DataType t);
bool isSigned(DataType t);
bool isString(DataType t);

}  // namespace coscope::od
