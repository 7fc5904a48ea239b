// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/logio/Mdf4Blocks.h"

#include <QString>

#include <cstdint>
#include <vector>

namespace coscope::logio::mdf4 {

// A CC block (channel conversion): cc_type 0 identity, 1 linear (phys = v0 + v1 * raw),
// 2 rational, 4 value-to-value table with and 5 without interpolation (key, value pairs).
// Other types (text tables, formulas) leave the raw value as it is.
struct Conversion {
    uint8_t type = 0;
    std::vector<double> values;
    double apply(double x) const;
    // Reads the CC block at `at` (0: identity).
    static Conversion read(BlockFile& file, uint64_t at);
};

// One CN block (channel): where its value sits in a record and how it converts.
// cn_type: 0 fixed length, 1 VLSD (the record holds an offset into signal data), 2 master,
// 3 virtual master, 4 sync, 5 maximum length, 6 virtual data (the value is the record's
// index, converted: CANedge uses a factor-0 linear CC as a per-group constant).
// cn_data_type: 0/1 unsigned LE/BE, 2/3 signed LE/BE, 4/5 float LE/BE, 10 byte array.
struct Channel {
    bool present = false;
    uint8_t type = 0;
    uint8_t dataType = 0;
    uint8_t bitOffset = 0;
    uint32_t byteOffset = 0;  // after the record id
    uint32_t bitCount = 0;
    uint64_t dataLink = 0;  // VLSD: the signal data (SD/DL/DZ/HL) or the VLSD channel group
    Conversion cc;

    bool isVirtual() const { return type == 3 || type == 6; }
    bool isVlsd() const { return type == 1; }
    // Whether the channel's bytes lie within `recordBytes` (virtual channels always do).
    bool fits(uint32_t recordBytes) const;
    // The stored value as an integer (virtual: the record index).
    uint64_t raw(const unsigned char* record, uint64_t index) const;
    // The converted (physical) value.
    double value(const unsigned char* record, uint64_t index) const;
    uint64_t integer(const unsigned char* record, uint64_t index) const;
};

// The time of a master channel in ns: exact integer arithmetic when the conversion is a whole
// number of ns per unit (1e-9, 1e-6 s), else through double.
int64_t timeNs(const Channel& time, const unsigned char* record, uint64_t index);

// ASAM MDF 4.1 Associated Standard "Bus Logging": a CAN channel group holds a master time
// channel and a composed channel CAN_DataFrame, CAN_RemoteFrame or CAN_ErrorFrame whose
// children are named "<frame>.BusChannel", ".ID", ".IDE", ".DLC", ".DataLength", ".DataBytes",
// ".Dir", ".EDL", ".BRS", ".ESI", ".ErrorType" (cn_byte_offset counts from the record start).
enum class FrameKind : uint8_t { Data, Remote, Error };
struct CanLayout {
    FrameKind kind = FrameKind::Data;
    Channel time, bus, id, ide, dlc, dataLength, dataBytes, dir, edl, brs, esi, errorType;
};

// Reads the channels from `firstChannel` on. Returns false (no error) for a group that is not
// CAN bus logging (LIN, signals); false with *error for a CAN group that cannot be read.
bool readCanLayout(BlockFile& file, uint64_t firstChannel, uint32_t recordBytes, CanLayout& layout, QString* error);

}  // namespace coscope::logio::mdf4
