// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/DeviceConfiguration.h"

#include <QByteArray>
#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

namespace coscope::canopen {

// One entry of a concise DCF.
struct ConciseDcfEntry {
    uint16_t index = 0;
    uint8_t sub = 0;
    QByteArray data;
};

// The concise DCF of CiA 302-3 (the value of 1F22h, which a master such as a PLC writes to a
// node at boot): UNSIGNED32 number of entries, then per entry UNSIGNED16 index, UNSIGNED8
// sub-index, UNSIGNED32 data size in bytes and the data, all little-endian (CiA 301 §7.1).
// Made from the writes of an apply plan, so it holds what "dcf apply --all" would write, in the
// same order: writable entries with a ParameterValue, no command objects (1010h, 1011h, 1F51h,
// 6040h), PDO writes framed by "invalid" COB-IDs (DeviceConfiguration::plan).
QByteArray conciseDcf(const ApplyPlan& plan);
// The plan of every writable ParameterValue of `dcf` for `node` ($NODEID), encoded.
QByteArray conciseDcf(uint8_t node, const od::ObjectDictionary& dcf, std::vector<SkippedEntry>* skipped = nullptr);
// Reads one back; nullopt with *error when the bytes do not add up.
std::optional<std::vector<ConciseDcfEntry>> parseConciseDcf(const QByteArray& bytes, QString* error = nullptr);

}  // namespace coscope::canopen
