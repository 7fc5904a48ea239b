// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/trace/TraceStore.h"

#include <QString>

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <vector>

namespace coscope::canopen {

// Where a node's NMT state was learned (shown beside it in the Nodes dock). Only error control
// (heartbeat, guarding answer, boot-up) is the node saying its state; a command seen on the bus
// is what the node was told (not confirmed); the node's own frames bound its state: PDOs only in
// Operational, SDO and EMCY only in Pre-operational or Operational, Stopped has nothing but NMT
// and error control (CiA 301 §7.3.2.2, the table of NMT states and communication objects).
enum class NmtSource : uint8_t {
    Unknown,
    BootUp,        // 700h+n 00h: then Pre-operational (CiA 301 §7.3.2.2.1)
    Heartbeat,     // 700h+n with the state (CiA 301 §7.2.8.3.2.2)
    Guarding,      // the answer to our (or another master's) RTR on 700h+n (CiA 301 §7.2.8.3.2.1)
    OurCommand,    // an NMT command we sent (a Tx frame on 000h); nmtCommand says which
    OtherCommand,  // an NMT command another master sent (an Rx frame on 000h)
    Pdo,           // the node sends PDOs: Operational
    Sdo,           // the node answers SDO: at least Pre-operational
    Emcy,          // the node sends EMCY: at least Pre-operational
};

// CoScope's watch over a node's error control (HeartbeatMonitor, CiA 301 §7.2.8.3.2): the
// heartbeat the user expects from it (a consumer time, as 1016h would hold) or node guarding
// (guard time 100Ch, life time factor 100Dh), and what the watch finds.
struct ErrorControlWatch {
    enum class Status : uint8_t {
        Off,      // not watched
        Waiting,  // watched, nothing received yet
        Ok,       // heartbeat in time / the last guarding request answered with the right toggle
        Late,     // a heartbeat overdue / a guarding request unanswered or a wrong toggle, life time not over
        Lost,     // no heartbeat within the consumer time / no answer within the node life time
    };
    int consumerTimeMs = 0;  // heartbeat watched when > 0
    int guardTimeMs = 0;     // node guarding when > 0: an RTR on 700h + node every guard time
    int lifeTimeFactor = 0;  // node life time = guard time x factor
    Status status = Status::Off;
    int64_t lastNs = 0;  // the last heartbeat or guarding answer (0 = none yet)
    uint32_t lost = 0;   // times it was lost
    bool guarding() const { return guardTimeMs > 0; }
};

// What is known about one node 1..127: from the traffic seen (boot-up, heartbeat, EMCY, SDO
// responses; CiA 301 §7.2.8.3.2), from the master's heartbeat consumer / node guarding, and
// from what was asked (scan, identity reads), with the dictionary matched or assigned to it.
struct NodeInfo {
    int node = 0;
    int nmtState = -1;                         // last state (0 initialising, 4, 5, 7Fh), -1 unknown
    NmtSource nmtSource = NmtSource::Unknown;  // where nmtState comes from
    uint8_t nmtCommand = 0;                    // the command specifier behind OurCommand/OtherCommand
    FrameNo nmtFrame = 0;                      // the frame nmtState was taken from
    int64_t nmtSinceNs = 0;                    // its time
    bool guardRequested = false;               // an RTR on 700h+n is pending: the next answer is guarding
    int64_t lastHeartbeatNs = 0;               // 0 = none seen
    int64_t heartbeatPeriodNs = 0;             // interval between the last two heartbeats
    int64_t lastSeenNs = 0;                    // any frame from the node
    FrameNo lastFrame = 0;
    uint32_t bootUps = 0;
    uint32_t emcyCount = 0;
    uint16_t lastEmcyCode = 0;
    uint32_t sdoFrames = 0;
    bool seenHeartbeat = false, seenBootUp = false, seenEmcy = false, seenSdo = false, scanned = false;
    bool heartbeatLost = false;  // consumer heartbeat time (1016h) or guarding life time ran out
    // The adapter was lost (issue 16): nmtState is the last one before the gap and may be stale
    // until a frame at or after gapFrame shows it: error control, a PDO, an SDO answer or EMCY
    // from a node last seen otherwise than Operational, or an NMT command.
    bool stateUnknownAfterGap = false;
    FrameNo gapFrame = 0;
    int guardingErrors = 0;              // missing or wrong-toggle guarding answers
    ErrorControlWatch watch;             // CoScope's heartbeat consumer / node guarding of the node
    std::optional<uint32_t> deviceType;  // 1000h
    std::optional<uint32_t> vendorId, productCode, revision, serial;  // 1018h:01..04
    QString deviceName;                                               // 1008h, empty = unknown
    std::optional<QString> hardwareVersion, softwareVersion;          // 1009h, 100Ah; nullopt = unknown
    // Optional objects a scan asked for and the node does not have (it aborted the read):
    // bits kNoDeviceName, kNoHardwareVersion, kNoSoftwareVersion (CiA 301 §7.5.2.9-11).
    uint8_t notPresent = 0;
    static constexpr uint8_t kNoDeviceName = 1, kNoHardwareVersion = 2, kNoSoftwareVersion = 4;
    bool identityRead = false;  // 1018h was asked for: an empty sub above is not present
    QString dictionary;         // matched (or assigned) dictionary name
};

// The one node table of a bus (DESIGN.md "core/"): the Nodes dock, the wizards, the master
// services and the trace's network context read it. Fed by consume() on the ingest thread (or
// the log loader), by the heartbeat monitor and by the scan / identity reads through the
// setters. Thread-safe; views take a snapshot when revision() moved. A node is in the table
// once something proved it exists (what it sent, or an answer to a scan).
class NodeTable {
public:
    void consume(const TraceStore& store, FrameNo first, size_t count);
    void clear();

    uint64_t revision() const { return revision_.load(std::memory_order_acquire); }
    std::vector<NodeInfo> snapshot() const;
    std::optional<NodeInfo> node(int id) const;
    int presentCount() const;

    // Changes (creates) node `id` under the lock; `fn` must not call back into the table.
    void update(int id, const std::function<void(NodeInfo&)>& fn);
    void markScanned(int id);
    // An empty name clears the dictionary of a node in the table and creates none.
    void setDictionary(int id, const QString& name);
    QString dictionary(int id) const;
    void setDeviceName(int id, const QString& name);
    // 1008h, 1009h or 100Ah as read: its text, or nullopt when the node does not have it.
    void setOptionalText(int id, uint16_t index, const std::optional<QString>& text);
    void setIdentity(int id, std::optional<uint32_t> vendor, std::optional<uint32_t> product,
                     std::optional<uint32_t> revision, std::optional<uint32_t> serial);
    // The device at `from` now has node-ID `to` (LSS or its own parameter): what was learned by
    // asking it (identity, name, dictionary) goes to `to`; `from` is dropped, nothing is there.
    void moveNode(int from, int to);
    // The moves since clear(), oldest first: a view showing `from` follows the device to `to`.
    struct Move {
        int from = 0, to = 0;
    };
    std::vector<Move> moves() const;
    // The bus was lost: every node's state is unknown from frame `from` on, until a frame shows
    // it again (NodeInfo::stateUnknownAfterGap).
    void markGap(FrameNo from);

private:
    NodeInfo& entryLocked(int id);
    void bump() { revision_.fetch_add(1, std::memory_order_release); }

    mutable std::mutex mutex_;
    std::array<std::optional<NodeInfo>, 128> nodes_;
    std::vector<Move> moves_;
    std::atomic<uint64_t> revision_{0};
};

}  // namespace coscope::canopen
