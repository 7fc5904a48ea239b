// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <array>
#include <cstdint>
#include <optional>

namespace coscope::canopen {

// What the master knows about each node 1..127: NMT state from boot-up/heartbeat/guarding
// (CiA 301 §7.2.8.3.2), when it was last heard, boot-ups, EMCY count, identity (1018h) and the
// dictionary matched to it. Owned and updated by one thread (the monitor's); others copy it.
struct NodeInfo {
    bool present = false;
    std::optional<uint8_t> nmtState;      // last reported state (0 boot-up, 4, 5, 7Fh)
    int64_t lastSeenNs = 0;               // any frame from the node
    int bootUps = 0;
    int emcyCount = 0;
    uint16_t lastEmcyCode = 0;
    bool heartbeatLost = false;           // consumer heartbeat time (1016h) or guarding life time ran out
    int guardingErrors = 0;               // missing or wrong-toggle guarding answers
    std::optional<uint32_t> deviceType;   // 1000h
    std::optional<uint32_t> vendorId, productCode, revision, serial;  // 1018h:01..04
    std::optional<QString> deviceName, hardwareVersion, softwareVersion;  // 1008h, 1009h, 100Ah; nullopt = not present
    QString dictionary;                   // matched dictionary name
};

class NodeTable {
public:
    NodeInfo& operator[](uint8_t node) { return nodes_[node & 0x7F]; }
    const NodeInfo& at(uint8_t node) const { return nodes_[node & 0x7F]; }
    int presentCount() const {
        int n = 0;
        for (int i = 1; i < 128; ++i) n += nodes_[i].present;
        return n;
    }

private:
    std::array<NodeInfo, 128> nodes_{};
};

}  // namespace coscope::canopen
