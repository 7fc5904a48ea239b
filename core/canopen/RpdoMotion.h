// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"
#include "core/canopen/PdoMapping.h"
#include "core/od/ObjectDictionary.h"

#include <functional>
#include <optional>
#include <vector>

namespace coscope::canopen {

// Objects of a CiA 402 drive whose value can set a motor moving (or let it move), on any axis
// (index + n·800h, CiA 402-2 §5.2): controlword 6040h, modes of operation 6060h, the targets
// 607Ah (position), 60FFh (velocity), 6071h (torque), 6042h (vl target velocity), the
// interpolation data record 60C1h, the offsets 60B0h-60B2h and the digital outputs 60FEh (its
// bit 0 releases the brake, extract-aimotor §4.9).
bool isMotionObject(uint16_t index);

// A frame aimed at a node's RPDO (CiA 301 §7.2.2: the node receives the PDO whose COB-ID 140xh:01
// holds the frame's identifier).
struct RpdoAddress {
    uint8_t node = 0;
    int number = 0;                   // RPDO 1..4
    bool mappingKnown = false;        // from the node's dictionary; false: the default COB-ID of a node
                                      // whose mapping is not known (treat as carrying motion)
    std::vector<PdoMapEntry> motion;  // the mapped motion objects (isMotionObject)
    bool carriesMotion() const { return !mappingKnown || !motion.empty(); }
};

// An RPDO as a node's dictionary holds it: 140xh:01 COB-ID (defaults with $NODEID resolved, or
// a DCF's ParameterValue) and the 160xh mapping (unused entries 0 left out).
struct RpdoLayout {
    int number = 0;      // RPDO 1..512
    uint32_t cobId = 0;  // as 140xh:01: bit 31 not valid, bit 29 a 29-bit CAN-ID
    std::vector<PdoMapEntry> entries;
    bool valid() const { return !(cobId & 0x80000000u); }
    bool extended() const { return cobId & 0x20000000u; }
    uint32_t canId() const { return cobId & (extended() ? 0x1FFFFFFFu : 0x7FFu); }
};
// RPDO `number` of `node` from its dictionary; nullopt when the dictionary does not describe it.
std::optional<RpdoLayout> rpdoLayout(const od::ObjectDictionary& dictionary, uint8_t node, int number);

// Which RPDO `frame` addresses: first by the nodes' dictionaries (140xh:01 as the dictionary
// holds it for that node-ID, 160xh the mapping; `dictionaryOf` returns null for a node without
// one), then by the pre-defined connection set (200h/300h/400h/500h + node, CiA 301 §7.3.5) for
// the nodes `isDrive` says are drives and have no dictionary. nullopt: no RPDO of a known node.
std::optional<RpdoAddress> rpdoAddressed(const CanFrame& frame,
                                         const std::function<const od::ObjectDictionary*(uint8_t node)>& dictionaryOf,
                                         const std::function<bool(uint8_t node)>& isDrive);

}  // namespace coscope::canopen
