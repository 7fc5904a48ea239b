// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/trace/TraceStore.h"

#include <QString>

#include <array>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>
#include <vector>

namespace coscope::gui {

// What is known about one CANopen node, from the traffic seen and from what we asked it.
struct NodeInfo {
    int node = 0;
    int nmtState = -1;            // last state from boot-up/heartbeat (CiA 301 Table 51), -1 unknown
    int64_t lastHeartbeatNs = 0;  // 0 = none seen
    int64_t heartbeatPeriodNs = 0;  // interval between the last two heartbeats
    int64_t lastSeenNs = 0;
    FrameNo lastFrame = 0;
    uint32_t bootUps = 0;
    uint32_t emcyCount = 0;
    uint16_t lastEmcyCode = 0;
    uint32_t sdoFrames = 0;
    bool seenHeartbeat = false, seenBootUp = false, seenEmcy = false, seenSdo = false, scanned = false;
    QString dictionary;   // matched (or assigned) dictionary name
    QString deviceName;   // 1008h
    QString hardwareVersion, softwareVersion;  // 1009h, 100Ah
    // Optional objects a scan asked for and the node does not have (it aborted the read):
    // bits kNoDeviceName, kNoHardwareVersion, kNoSoftwareVersion (CiA 301 §7.5.2.9-11).
    uint8_t notPresent = 0;
    static constexpr uint8_t kNoDeviceName = 1, kNoHardwareVersion = 2, kNoSoftwareVersion = 4;
    std::optional<uint32_t> vendorId, productCode, revision, serial;  // 1018h sub 1..4
    bool identityRead = false;  // 1018h was asked for: an empty sub above is not present
};

// The nodes seen on a bus, fed on the ingest thread (or the log loader) by consume(); the views
// take a snapshot when revision() changed. Identity, name and dictionary come from the commands
// (scan, SDO reads) via the setters. Thread-safe.
class NodeTable {
public:
    void consume(const TraceStore& store, FrameNo first, size_t count);
    void clear();

    uint64_t revision() const { return revision_.load(std::memory_order_acquire); }
    std::vector<NodeInfo> snapshot() const;
    std::optional<NodeInfo> node(int id) const;

    void markScanned(int id);
    void setDictionary(int id, const QString& name);
    void setDeviceName(int id, const QString& name);
    // 1008h, 1009h or 100Ah as read: its text, or nullopt when the node does not have it.
    void setOptionalText(int id, uint16_t index, const std::optional<QString>& text);
    void setIdentity(int id, std::optional<uint32_t> vendor, std::optional<uint32_t> product,
                     std::optional<uint32_t> revision, std::optional<uint32_t> serial);
    // The device at `from` now has node-ID `to` (LSS or its own parameter): what was learned by
    // asking it (identity, name, dictionary) goes to `to`; `from` is dropped, nothing is there.
    void moveNode(int from, int to);

private:
    NodeInfo& entryLocked(int id);
    void bump() { revision_.fetch_add(1, std::memory_order_release); }

    mutable std::mutex mutex_;
    std::array<std::optional<NodeInfo>, 128> nodes_;
    std::atomic<uint64_t> revision_{0};
};

}  // namespace coscope::gui
