// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/RpdoMotion.h"

#include <algorithm>

namespace coscope::canopen {

bool isMotionObject(uint16_t index) {
    if (index < 0x6000 || index >= 0xA000) return false;                               // axes 0..7 (CiA 402-2 §5.2)
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
    default: return false;
    }
}

std::optional<RpdoLayout> rpdoLayout(const od::ObjectDictionary& d, uint8_t node, int number) {
    const PdoId id{false, number};
    const od::SubObject* cob = d.entry(id.communicationIndex(), 1);
    if (!cob) return std::nullopt;
    const auto v = cob->resolvedValue(node);
    if (!v || !v->toUInt64()) return std::nullopt;
    RpdoLayout layout;
    layout.number = number;
    layout.cobId = static_cast<uint32_t>(*v->toUInt64());
    const od::SubObject* count = d.entry(id.mappingIndex(), 0);
    const auto n = count ? count->resolvedValue(node) : std::nullopt;
    if (!n || !n->toUInt64()) return layout;
    for (uint64_t s = 1; s <= std::min<uint64_t>(*n->toUInt64(), 64); ++s) {
        const od::SubObject* e = d.entry(id.mappingIndex(), static_cast<uint8_t>(s));
        const auto m = e ? e->resolvedValue(node) : std::nullopt;
        const auto raw = m ? m->toUInt64() : std::nullopt;
        if (raw && *raw != 0)
            layout.entries.push_back(PdoMapEntry::decode(static_cast<uint32_t>(*raw)));  // 0 = unused entry
    }
    return layout;
}

std::optional<RpdoAddress> rpdoAddressed(const CanFrame& frame,
                                         const std::function<const od::ObjectDictionary*(uint8_t)>& dictionaryOf,
                                         const std::function<bool(uint8_t)>& isDrive) {
    if (frame.isError() || frame.isRemote()) return std::nullopt;
    const uint32_t id = frame.id;
    for (int node = 1; node <= 127; ++node) {
        const od::ObjectDictionary* d = dictionaryOf(static_cast<uint8_t>(node));
        if (!d) continue;
        for (int number = 1; number <= 4; ++number) {
            const auto layout = rpdoLayout(*d, static_cast<uint8_t>(node), number);
            if (!layout || !layout->valid()) continue;  // not valid (bit 31)
            if (layout->extended() != frame.isExtended() || layout->canId() != id) continue;
            RpdoAddress a;
            a.node = static_cast<uint8_t>(node);
            a.number = number;
            a.mappingKnown = true;
            for (const PdoMapEntry& e : layout->entries)
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
