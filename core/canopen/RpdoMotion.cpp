// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/RpdoMotion.h"

#include <algorithm>

namespace coscope::canopen {

bool isMotionObject(uint16_t index) {
    if (index < 0x6000 || index >= 0x6800) return false;
    const uint16_t base = static_cast<uint16_t>(0x6000 + ((index - 0x6000) % 0x800));  // axis 0 (CiA 402-2 §5.2)
    switch (base) {
    case 0x6040:  // controlword
    case 0x6042:  // vl target velocity
    case 0x6060:  // modes of operation
    case 0x6071:  // target torque
    case 0x607A:  // target position
    case 0x60B0:  // position offset
    case 0x60B1:  // velocity offset
    case 0x60B2:  // torque offset
    case 0x60C1:  // interpolation data record
    case 0x60FE:  // digital outputs (brake)
    case 0x60FF:  // target velocity
        return true;
    default:
        return false;
    }
}

namespace {
// The RPDO's COB-ID and mapping as the dictionary holds them for `node` (defaults with $NODEID
// resolved, or a DCF's ParameterValue). False when the dictionary does not describe the PDO.
bool readRpdo(const od::ObjectDictionary& d, uint8_t node, int number, uint32_t* cobId, std::vector<PdoMapEntry>* entries) {
    const PdoId id{false, number};
    const od::SubObject* cob = d.entry(id.communicationIndex(), 1);
    if (!cob) return false;
    const auto v = cob->resolvedValue(node);
    if (!v || !v->toUInt64()) return false;
    *cobId = static_cast<uint32_t>(*v->toUInt64());
    entries->clear();
    const od::SubObject* count = d.entry(id.mappingIndex(), 0);
    const auto n = count ? count->resolvedValue(node) : std::nullopt;
    if (!n || !n->toUInt64()) return true;
    for (uint64_t s = 1; s <= std::min<uint64_t>(*n->toUInt64(), 64); ++s) {
        const od::SubObject* e = d.entry(id.mappingIndex(), static_cast<uint8_t>(s));
        const auto m = e ? e->resolvedValue(node) : std::nullopt;
        const auto raw = m ? m->toUInt64() : std::nullopt;
        if (raw && *raw != 0) entries->push_back(PdoMapEntry::decode(static_cast<uint32_t>(*raw)));  // 0 = unused entry
    }
    return true;
}
}  // namespace

std::optional<RpdoAddress> rpdoAddressed(const CanFrame& frame, const std::function<const od::ObjectDictionary*(uint8_t)>& dictionaryOf,
                                         const std::function<bool(uint8_t)>& isDrive) {
    if (frame.isError() || frame.isRemote()) return std::nullopt;
    const uint32_t id = frame.id;
    for (int node = 1; node <= 127; ++node) {
        const od::ObjectDictionary* d = dictionaryOf(static_cast<uint8_t>(node));
        if (!d) continue;
        for (int number = 1; number <= 4; ++number) {
            uint32_t cob = 0;
            std::vector<PdoMapEntry> entries;
            if (!readRpdo(*d, static_cast<uint8_t>(node), number, &cob, &entries)) continue;
            if (cob & 0x80000000u) continue;  // not valid (bit 31)
            const bool extended = cob & 0x20000000u;
            if (extended != frame.isExtended() || (cob & (extended ? 0x1FFFFFFFu : 0x7FFu)) != id) continue;
            RpdoAddress a;
            a.node = static_cast<uint8_t>(node);
            a.number = number;
            a.mappingKnown = true;
            for (const PdoMapEntry& e : entries)
                if (isMotionObject(e.index)) a.motion.push_back(e);
            return a;
        }
    }
    // The pre-defined connection set: RPDO n of node k is (n + 1)·100h + k (CiA 301 §7.3.5).
    if (frame.isExtended() || id < 0x201 || id > 0x57F || (id & 0x7F) == 0) return std::nullopt;
    const auto node = static_cast<uint8_t>(id & 0x7F);
    if (dictionaryOf(node) || !isDrive(node)) return std::nullopt;
    RpdoAddress a;
    a.node = node;
    a.number = static_cast<int>(id >> 8) - 1;
    return a;
}

}  // namespace coscope::canopen
