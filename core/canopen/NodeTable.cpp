// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/NodeTable.h"

#include "core/canopen/CobId.h"
#include "core/canopen/Nmt.h"

namespace coscope::canopen {

NodeInfo& NodeTable::entryLocked(int id) {
    auto& slot = nodes_[static_cast<size_t>(id & 0x7F)];
    if (!slot) {
        slot.emplace();
        slot->node = id;
    }
    return *slot;
}

namespace {

// A frame a node had queued before a command reached it may still go out just after the command:
// its frames this soon after a command say nothing about the new state.
constexpr int64_t kCommandSettleNs = 20'000'000;

void setState(NodeInfo& e, int state, NmtSource source, FrameNo n, int64_t t, uint8_t command = 0) {
    e.nmtState = state;
    e.nmtSource = source;
    e.nmtCommand = command;
    e.nmtFrame = n;
    e.nmtSinceNs = t;
}

bool afterCommand(const NodeInfo& e) {
    return e.nmtSource == NmtSource::OurCommand || e.nmtSource == NmtSource::OtherCommand;
}

// The node's own frame `source` (a PDO, an SDO answer, EMCY) at frame n: its state is corrected
// when the one known contradicts it (CiA 301 §7.3.2.2: PDOs only in Operational; SDO and EMCY
// only in Pre-operational and Operational), and a state not yet confirmed by the node becomes
// the one its frames show.
void inferState(NodeInfo& e, NmtSource source, FrameNo n, int64_t t) {
    const bool afterGap = e.stateUnknownAfterGap && n >= e.gapFrame;
    // Just after a command, a frame that contradicts it may have been queued before it.
    const bool settling = afterCommand(e) && !afterGap && t - e.nmtSinceNs < kCommandSettleNs;
    if (source == NmtSource::Pdo) {
        if (e.nmtState == 0x05 && !afterGap && !afterCommand(e)) return;  // known already
        if (settling && e.nmtState != 0x05) return;
        setState(e, 0x05, source, n, t);
        e.stateUnknownAfterGap = e.stateUnknownAfterGap && !afterGap;
        return;
    }
    // SDO or EMCY: Pre-operational or Operational; which one, only a PDO or error control tells.
    const bool contradicts = e.nmtState == 0x04 || e.nmtState == 0x00 || (afterCommand(e) && e.nmtState < 0);
    if (contradicts && settling) return;
    if (contradicts || (afterGap && e.nmtState != 0x05)) setState(e, 0x7F, source, n, t);
    if (afterGap && e.nmtState == 0x7F) e.stateUnknownAfterGap = false;
}

}  // namespace

void NodeTable::consume(const TraceStore& store, FrameNo first, size_t count) {
    bool changed = false;
    std::lock_guard lock(mutex_);
    for (size_t i = 0; i < count; ++i) {
        const FrameNo n = first + static_cast<FrameNo>(i);
        const TraceRecord& r = store.record(n);
        if (r.flags & (CanFrame::Extended | CanFrame::Error)) continue;
        const auto info = classifyCobId(r.id);
        if (info.service == Service::Nmt && r.len >= 2 && !(r.flags & CanFrame::Remote)) {
            // A command seen on the bus (CiA 301 §7.2.8.3.1): what the node was told, ours when
            // we sent it. It creates no node: a command says nothing about who is there.
            const uint8_t cs = r.data[0], target = r.data[1];
            const NmtSource source = r.flags & CanFrame::Tx ? NmtSource::OurCommand : NmtSource::OtherCommand;
            for (auto& slot : nodes_) {
                if (!slot || (target != 0 && slot->node != target)) continue;
                setState(*slot, nmtStateAfter(cs), source, n, r.timestampNs, cs);
                if (n >= slot->gapFrame) slot->stateUnknownAfterGap = false;
                changed = true;
            }
            continue;
        }
        if (info.node < 1) continue;
        // Only what a node itself sends proves it exists: error control, EMCY, SDO responses, TPDOs.
        // Requests to a node (600h, RPDOs, guarding RTR) say nothing about it being there.
        switch (info.service) {
        case Service::NmtErrorControl: {
            if (r.flags & CanFrame::Remote) {  // a guarding request: the next answer is guarding
                if (auto& slot = nodes_[static_cast<size_t>(info.node)]) slot->guardRequested = true;
                continue;
            }
            if (r.len < 1) continue;
            NodeInfo& e = entryLocked(info.node);
            const int state = r.data[0] & 0x7F;  // CiA 301 §7.2.8.3.2: bit 7 = toggle
            const bool afterGap = e.stateUnknownAfterGap && n >= e.gapFrame;
            if (afterGap) e.stateUnknownAfterGap = false;  // known again (the period spans no gap)
            if (state == 0) {
                e.seenBootUp = true;
                ++e.bootUps;
                setState(e, 0x7F, NmtSource::BootUp, n, r.timestampNs);  // then pre-operational (CiA 301 §7.3.2.2.1)
            } else if (e.guardRequested) {
                setState(e, state, NmtSource::Guarding, n, r.timestampNs);
            } else {
                if (!afterGap && e.lastHeartbeatNs && r.timestampNs > e.lastHeartbeatNs)
                    e.heartbeatPeriodNs = r.timestampNs - e.lastHeartbeatNs;
                e.seenHeartbeat = true;
                e.lastHeartbeatNs = r.timestampNs;
                setState(e, state, NmtSource::Heartbeat, n, r.timestampNs);
            }
            e.guardRequested = false;
            e.lastSeenNs = r.timestampNs;
            e.lastFrame = n;
            changed = true;
            break;
        }
        case Service::Emcy: {
            NodeInfo& e = entryLocked(info.node);
            e.seenEmcy = true;
            const uint16_t code = r.len >= 2 ? static_cast<uint16_t>(r.data[0] | (r.data[1] << 8)) : 0;
            if (code != 0) ++e.emcyCount;  // 0000h = error reset (CiA 301 §7.2.7.3.1)
            e.lastEmcyCode = code;
            e.lastSeenNs = r.timestampNs;
            e.lastFrame = n;
            inferState(e, NmtSource::Emcy, n, r.timestampNs);
            changed = true;
            break;
        }
        case Service::SdoResponse: {
            NodeInfo& e = entryLocked(info.node);
            e.seenSdo = true;
            ++e.sdoFrames;
            e.lastSeenNs = r.timestampNs;
            e.lastFrame = n;
            inferState(e, NmtSource::Sdo, n, r.timestampNs);
            changed = true;
            break;
        }
        case Service::Tpdo1:
        case Service::Tpdo2:
        case Service::Tpdo3:
        case Service::Tpdo4: {
            auto& slot = nodes_[static_cast<size_t>(info.node)];
            // PDO ids may be remapped: a TPDO alone does not create a node. An RTR asks for it.
            if (slot && !(r.flags & (CanFrame::Remote | CanFrame::Tx))) {
                slot->lastSeenNs = r.timestampNs;
                slot->lastFrame = n;
                const int before = slot->nmtState;
                const NmtSource was = slot->nmtSource;
                const bool gap = slot->stateUnknownAfterGap;
                inferState(*slot, NmtSource::Pdo, n, r.timestampNs);
                changed =
                    changed || before != slot->nmtState || was != slot->nmtSource || gap != slot->stateUnknownAfterGap;
            }
            break;
        }
        default: break;
        }
    }
    if (changed) bump();
}

void NodeTable::markGap(FrameNo from) {
    {
        std::lock_guard lock(mutex_);
        for (auto& e : nodes_) {
            if (!e) continue;
            e->stateUnknownAfterGap = true;
            e->gapFrame = from;
        }
    }
    bump();
}

void NodeTable::clear() {
    std::lock_guard lock(mutex_);
    for (auto& n : nodes_) n.reset();
    moves_.clear();
    bump();
}

std::vector<NodeTable::Move> NodeTable::moves() const {
    std::lock_guard lock(mutex_);
    return moves_;
}

std::vector<NodeInfo> NodeTable::snapshot() const {
    std::lock_guard lock(mutex_);
    std::vector<NodeInfo> out;
    for (const auto& n : nodes_)
        if (n) out.push_back(*n);
    return out;
}

std::optional<NodeInfo> NodeTable::node(int id) const {
    std::lock_guard lock(mutex_);
    if (id < 0 || id > 127) return std::nullopt;
    return nodes_[static_cast<size_t>(id)];
}

int NodeTable::presentCount() const {
    std::lock_guard lock(mutex_);
    int n = 0;
    for (const auto& e : nodes_) n += e.has_value();
    return n;
}

void NodeTable::update(int id, const std::function<void(NodeInfo&)>& fn) {
    if (id < 1 || id > 127) return;
    {
        std::lock_guard lock(mutex_);
        fn(entryLocked(id));
    }
    bump();
}

QString NodeTable::dictionary(int id) const {
    std::lock_guard lock(mutex_);
    if (id < 0 || id > 127 || !nodes_[static_cast<size_t>(id)]) return {};
    return nodes_[static_cast<size_t>(id)]->dictionary;
}

void NodeTable::markScanned(int id) {
    std::lock_guard lock(mutex_);
    entryLocked(id).scanned = true;
    bump();
}

void NodeTable::setDictionary(int id, const QString& name) {
    std::lock_guard lock(mutex_);
    if (name.isEmpty() && (id < 0 || id > 127 || !nodes_[static_cast<size_t>(id)])) return;
    entryLocked(id).dictionary = name;
    bump();
}

void NodeTable::setDeviceName(int id, const QString& name) {
    std::lock_guard lock(mutex_);
    entryLocked(id).deviceName = name;
    bump();
}

void NodeTable::setOptionalText(int id, uint16_t index, const std::optional<QString>& text) {
    const uint8_t bit = index == 0x1008   ? NodeInfo::kNoDeviceName
                        : index == 0x1009 ? NodeInfo::kNoHardwareVersion
                        : index == 0x100A ? NodeInfo::kNoSoftwareVersion
                                          : 0;
    if (!bit) return;
    std::lock_guard lock(mutex_);
    NodeInfo& e = entryLocked(id);
    if (index == 0x1008) e.deviceName = text.value_or(QString());
    else if (index == 0x1009) e.hardwareVersion = text;
    else e.softwareVersion = text;
    e.notPresent = text ? (e.notPresent & ~bit) : (e.notPresent | bit);
    bump();
}

void NodeTable::setIdentity(int id, std::optional<uint32_t> vendor, std::optional<uint32_t> product,
                            std::optional<uint32_t> revision, std::optional<uint32_t> serial) {
    std::lock_guard lock(mutex_);
    NodeInfo& e = entryLocked(id);
    e.identityRead = true;
    if (vendor) e.vendorId = vendor;
    if (product) e.productCode = product;
    if (revision) e.revision = revision;
    if (serial) e.serial = serial;
    bump();
}

void NodeTable::moveNode(int from, int to) {
    if (from < 1 || from > 127 || to < 1 || to > 127 || from == to) return;
    std::lock_guard lock(mutex_);
    auto& old = nodes_[static_cast<size_t>(from)];
    NodeInfo& e = entryLocked(to);  // usually there already: its boot-up at the new ID
    if (old) {
        e.scanned = e.scanned || old->scanned;
        if (!old->dictionary.isEmpty()) e.dictionary = old->dictionary;
        if (!old->deviceName.isEmpty()) e.deviceName = old->deviceName;
        if (old->hardwareVersion) e.hardwareVersion = old->hardwareVersion;
        if (old->softwareVersion) e.softwareVersion = old->softwareVersion;
        e.notPresent |= old->notPresent;
        e.identityRead = e.identityRead || old->identityRead;
        if (old->vendorId) e.vendorId = old->vendorId;
        if (old->productCode) e.productCode = old->productCode;
        if (old->revision) e.revision = old->revision;
        if (old->serial) e.serial = old->serial;
        if (old->deviceType) e.deviceType = old->deviceType;
        if (old->hardwareVersion) e.hardwareVersion = old->hardwareVersion;
        if (old->softwareVersion) e.softwareVersion = old->softwareVersion;
        old.reset();
    }
    moves_.push_back({from, to});
    bump();
}

}  // namespace coscope::canopen
