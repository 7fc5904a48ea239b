// SPDX-License-Identifier: GPL-3.0-or-later
// NetworkHealth: PDO rate and period jitter per COB-ID, RPDOs nobody sends, SYNC cycles
// (CiA 301 §7.2.2 PDO, §7.2.5 SYNC).
#include "dissectors/NetworkHealth.h"

#include "core/canopen/CobId.h"

#include <algorithm>
#include <cmath>

namespace coscope::dissect {

using canopen::Service;

void NetworkHealth::addPdo(const CanFrame& f, const Dissection& d, BusTrack& b, const NetworkContext& ctx) {
    int32_t* slot;
    if (f.isExtended()) {
        auto it = b.extPdoIndex.try_emplace(f.id, -1).first;
        slot = &it->second;
    } else {
        slot = &b.pdoIndex[f.id & 0x7FF];
    }
    if (*slot < 0) {
        *slot = static_cast<int32_t>(pdos_.size());
        PdoTrack p;
        p.cobId = f.id;
        p.bus = f.bus;
        p.node = d.node;
        p.tpdo = isTpdo(d.service);
        p.number = d.pdoNumber;
        p.firstNs = f.timestampNs;
        p.firstFrame = frameNo_;
        pdos_.push_back(std::move(p));
    }
    PdoTrack& p = pdos_[static_cast<size_t>(*slot)];
    if (p.frames && f.timestampNs >= p.lastNs) {
        p.periods.add(f.timestampNs - p.lastNs);
        p.marks.add(f.timestampNs - p.lastNs, f.timestampNs, frameNo_);
    }
    ++p.frames;
    p.lastNs = f.timestampNs;
    if (p.tpdo && d.node >= 1 && d.node < 128) {
        NodeTrack& t = node(f.bus, d.node);
        t.present = true;
        ++t.frames;
        // The statusword, where the node's mapping carries it (CiA 402-2 §8.4.1, 6041h).
        const PdoConfig* cfg = ctx.node(f.bus, d.node).findPdo(true, d.pdoNumber);
        const int count = cfg && cfg->mappingKnown ? cfg->count : -1;
        if (cfg != p.swConfig || count != p.swMapCount) [[unlikely]] {
            p.swConfig = cfg;
            p.swMapCount = count;
            p.swBit = -1;
            for (int i = 0, bit = 0; i < count && static_cast<size_t>(i) < cfg->entries.size();
                 bit += cfg->entries[static_cast<size_t>(i)].bits, ++i) {
                const PdoMapEntry& e = cfg->entries[static_cast<size_t>(i)];
                if (!e.dummy && e.index == 0x6041 && e.sub == 0 && e.bits == 16) {
                    p.swBit = bit;
                    break;
                }
            }
        }
        if (p.swBit >= 0 && p.swBit % 8 == 0 && p.swBit / 8 + 2 <= f.len) {
            const int at = p.swBit / 8;
            addStatusword(
                t, f,
                static_cast<uint16_t>(f.data[static_cast<size_t>(at)] | f.data[static_cast<size_t>(at) + 1] << 8));
        }
    }
}

void NetworkHealth::addSync(const CanFrame& f, BusTrack& b) {
    ++syncs_;
    if (b.syncSeen && f.timestampNs >= b.lastSyncNs) {
        syncPeriods_.add(f.timestampNs - b.lastSyncNs);
        syncMarks_.add(f.timestampNs - b.lastSyncNs, f.timestampNs, frameNo_);
    }
    b.syncSeen = true;
    b.lastSyncNs = f.timestampNs;
}

void NetworkHealth::fillPdos(HealthReport& r, const NetworkContext* ctx) const {
    for (const PdoTrack& p : pdos_) {
        PdoHealth h;
        h.bus = p.bus;
        h.cobId = p.cobId;
        h.node = p.node;
        h.service = QStringLiteral("%1%2").arg(p.tpdo ? QStringLiteral("TPDO") : QStringLiteral("RPDO")).arg(p.number);
        h.frames = p.frames;
        h.firstFrame = p.firstFrame;
        h.firstNs = p.firstNs;
        const IntervalStats& s = p.periods;
        if (s.count) {
            h.periodMinMs = static_cast<double>(s.minNs) / 1e6;
            h.periodMaxMs = static_cast<double>(s.maxNs) / 1e6;
            h.periodAvgMs = s.averageMs();
            h.jitterMs = s.jitterMs();
            h.cyclic = s.count >= 3 && s.shareNear(s.medianMs(), 0.25) >= 0.8;
            if (h.cyclic) h.irregularAt = p.marks.select(s.medianMs(), 0.25, false);
            const double span = static_cast<double>(p.lastNs - p.firstNs) / 1e9;
            h.rateHz = span > 0 ? static_cast<double>(s.count) / span : 0;
        }
        if (!p.tpdo && p.node >= 1 && p.node < 128 && static_cast<size_t>(p.bus) < buses_.size()) {
            const NodeTrack* t = buses_[static_cast<size_t>(p.bus)].nodes[static_cast<size_t>(p.node)].get();
            h.consumerSeen = t && t->present;
        }
        r.pdos.push_back(std::move(h));
    }
    std::sort(r.pdos.begin(), r.pdos.end(), [](const PdoHealth& a, const PdoHealth& b) {
        return a.bus != b.bus ? a.bus < b.bus : a.cobId < b.cobId;
    });
    if (!ctx) return;
    // RPDOs a present node has valid in its mapping (dictionary defaults or what the trace wrote)
    // that no frame on the bus carries: the node waits for data nobody produces.
    for (size_t bus = 0; bus < buses_.size() && static_cast<int>(bus) < ctx->busCount(); ++bus)
        for (int id = 1; id < 128; ++id) {
            const NodeTrack* t = buses_[bus].nodes[static_cast<size_t>(id)].get();
            if (!t || !t->present || t->state != 5) continue;  // only an operational node processes PDOs
            const NodeState& s = ctx->node(static_cast<int>(bus), id);
            for (size_t i = 0; i < s.rpdo.size(); ++i) {
                const PdoConfig& c = s.rpdo[i];
                if (!c.valid() || (c.mappingKnown && c.count == 0)) continue;
                const uint32_t can = c.canId();
                const bool ext = c.cobId & 0x20000000u;
                const BusTrack& b = buses_[bus];
                const bool seen = ext ? b.extPdoIndex.count(can) > 0 : b.pdoIndex[can & 0x7FF] >= 0;
                if (!seen) r.bus.rpdosNoProducer.push_back({static_cast<int>(bus), id, static_cast<int>(i) + 1, can});
            }
        }
}

}  // namespace coscope::dissect
