// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "dissectors/Dissection.h"

#include <cstdint>
#include <optional>

namespace coscope::dissect {

struct NodeState;

// CiA 402 meaning on top of a value of 6040h (controlword: command), 6041h (statusword: state
// and bits) or 6060h/6061h (modes of operation), for any axis (+ n x 800h, CiA 402-1 §5).
// Adds the ds402.* flat fields (and tree items at `depth` when asked) and returns a short text
// for the summary; empty when the object is none of these. `mode`: the axis' mode of operation
// where known, for the names of statusword bits 12/13 (HM: homing attained / homing error).
QString ds402Meaning(uint16_t index, uint8_t sub, uint64_t raw, Dissection& out, int depth = 1, int byteOffset = 0,
                     int byteLength = 0, std::optional<int8_t> mode = std::nullopt);
// The mode of operation of the axis of `index` as last seen on node `n` (nullopt: not seen).
std::optional<int8_t> ds402ModeOf(const NodeState& n, uint16_t index);
// Keeps the mode when `index` is 6060h/6061h of an axis (sub 0) with value `raw`.
void ds402LearnMode(NodeState& n, uint16_t index, uint8_t sub, uint64_t raw);
// The short text alone (command, state or mode name), for a summary without fields or tree.
QString ds402MeaningText(uint16_t index, uint8_t sub, uint64_t raw);

}  // namespace coscope::dissect
