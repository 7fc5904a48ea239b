// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"
#include "dissectors/DictionaryCatalog.h"
#include "dissectors/Dissection.h"
#include "dissectors/PdoMapping.h"
#include "dissectors/SdoReassembly.h"

#include <QString>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace coscope::dissect {

struct VendorTable;

// What the context knows about one node, as of the frame being decoded.
struct NodeState {
    DictionaryPtr dictionary;  // null = unknown device
    QString dictionaryName;
    bool userAssigned = false;  // set by the user (never replaced by identity matching)
    const VendorTable* vendor = nullptr;
    int nmtState = -1;  // last NMT state: 0, 4, 5, 127; -1 = not seen
    int64_t lastNmtNs = 0;
    int guardToggle = -1;  // last node-guarding toggle bit, -1 = none
    bool guardRequested = false;
    eds::DeviceIdentity identity;       // 1000h, 1018h:01..03, 1008h, 100Ah seen in the trace
    std::vector<PdoConfig> rpdo, tpdo;  // index = PDO number - 1 (grown on demand)
    SdoChannel sdo;
    bool seen = false;
    // Modes of operation 6060h/6061h (+ n x 800h) last seen per axis, for the mode-specific
    // names of statusword bits 12/13 (ds402ModeOf, Ds402Meaning.h); bit n of ds402ModeKnown set
    // once axis n's mode was seen.
    std::array<int8_t, 8> ds402Mode{};
    uint8_t ds402ModeKnown = 0;

    PdoConfig& pdo(bool tpdoDir, int number);  // creates
    const PdoConfig* findPdo(bool tpdoDir, int number) const;
};

// The network context (DESIGN.md "dissectors/"): per node the dictionary, NMT state, PDO
// mappings in force and SDO transfer state, updated frame by frame. dissect() must see the
// frames in trace order: its result for frame N depends on frames < N.
//
// One context per bus (CanFrame::bus): node 5 on can0 and node 5 on can1 are different devices,
// with their own NMT state, PDO mappings, SDO channels and identity. A dictionary assigned with
// assignDictionary() applies to that node-ID on every bus (a bus seen later starts from them).
// node()/nodeForEdit()/namesFor() answer for the bus of the frame being (or last) dissected;
// node(bus, id) for any bus.
//
// Random access ("decode frame N", the GUI): the context is a value type. Copying it is a
// snapshot (dictionaries are shared, immutable). The GUI keeps a snapshot every K frames (the
// ingest worker passes over the trace once anyway) and decodes frame N by copying the nearest
// snapshot at or before N and dissecting forward to N; see checkpointInterval().
class NetworkContext {
public:
    NetworkContext();

    // Assigns a dictionary to a node (1..127): a bundled name or an EDS/DCF/XDD file.
    bool assignDictionary(int node, const QString& nameOrFile, QString* error);
    void assignDictionary(int node, DictionaryPtr dictionary, const QString& name, bool byUser = true);
    // Match nodes without a user dictionary by the identity read in the trace (default on).
    void setIdentityMatching(bool on) { identityMatching_ = on; }
    // Names from the generic CiA 301/402 dictionary for nodes without one of their own (on by
    // default). Statistics turn it off: they show no names, and loading it costs ~5 ms.
    void setGenericNames(bool on) { genericNames_ = on; }
    // That generic dictionary, parsed once per process and shared (thread-safe): a consumer may
    // load it on another thread ahead of the frames that need it.
    static DictionaryPtr genericDictionary();

    // Decodes one frame and advances the context.
    void dissect(const CanFrame& frame, Dissection& out, Dissection::Level level = Dissection::Level::Flat);

    const NodeState& node(int id) const { return buses_[current_].nodes[static_cast<size_t>(id & 0x7F)]; }
    NodeState& nodeForEdit(int id) { return buses_[current_].nodes[static_cast<size_t>(id & 0x7F)]; }
    // Node `id` on bus `bus` (the assigned defaults when that bus has not been seen).
    const NodeState& node(int bus, int id) const;
    // Buses seen so far (index = CanFrame::bus); at least 1.
    int busCount() const { return static_cast<int>(buses_.size()); }
    uint64_t framesSeen() const { return frames_; }

    // The snapshot interval the GUI should use for random access.
    static constexpr uint64_t checkpointInterval() { return 4096; }

    // Internal, for the per-service dissectors.
    const od::ObjectDictionary* namesFor(int node) const;  // node's dictionary, else generic CiA 402 names
    void applySdoTransfer(int node, const SdoTransferRecord& t);
    void pdoCobIdChanged(int node, bool tpdoDir, int number);

private:
    struct Route {
        int node = -1;
        int number = 0;  // PDO number, 1-based
        bool tpdo = false;
    };
    // What the context knows about one bus.
    struct Bus {
        std::array<NodeState, 128> nodes;
        std::vector<int32_t> routes =
            std::vector<int32_t>(2048, -1);  // standard id -> node << 12 | tpdo << 11 | (number - 1); -1 = default
    };
    void loadDefaults(Bus& bus, int node);
    static void rebuildRoutes(Bus& bus);
    void rebuildRoutes() { rebuildRoutes(buses_[current_]); }
    void selectBus(int bus);

    std::shared_ptr<const Bus>
        template_;            // the assigned dictionaries, no frames seen: a new bus starts here (shared by snapshots)
    std::vector<Bus> buses_;  // index = CanFrame::bus
    size_t current_ = 0;      // the bus of the frame being dissected
    DictionaryPtr generic_;
    bool genericNames_ = true;
    bool identityMatching_ = true;
    uint64_t frames_ = 0;
};

}  // namespace coscope::dissect
