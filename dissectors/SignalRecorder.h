// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/trace/SignalBuffer.h"
#include "core/trace/TraceStore.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/RawSignal.h"
#include "dissectors/SignalCatalog.h"

#include <QString>

#include <atomic>
#include <bitset>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace coscope::dissect {

// The plot's data side (DESIGN.md "Data flow": the ingest worker feeds plot buffers). Runs as a
// consumer on the ingest thread (live capture or log loading): follows the trace with its own
// network context (PDO mappings from the dictionaries and from SDO writes in the trace),
// keeps the catalogue of the signals each node's PDOs carry, and appends every mapped value
// of every PDO frame to that signal's SignalBuffer. Readers on any thread take the catalogue
// (a copy, with a revision) and the buffers; nothing per frame crosses a thread by signal.
class SignalRecorder {
public:
    explicit SignalRecorder(size_t capacityPerSignal = SignalBuffer::kDefaultCapacity);
    ~SignalRecorder();
    SignalRecorder(const SignalRecorder&) = delete;
    SignalRecorder& operator=(const SignalRecorder&) = delete;

    // Ingest thread: frames [first, first + count) of `store`, in trace order.
    void consume(const TraceStore& store, FrameNo first, size_t count);

    // Any thread: node-ID -> dictionary (bundled name or file) as the node table matched or
    // the user assigned; applied before the next batch. Nodes not listed are matched by the
    // identity read in the trace.
    void setDictionaries(const std::map<int, QString>& names);
    // Any thread: the user's raw signals (signal n has SignalKey::raw n + 1), recorded from the
    // next batch on; a signal is listed once a frame of its COB-ID was seen.
    void setRawSignals(const std::vector<RawSignal>& raw);

    // Any thread.
    uint64_t catalogRevision() const { return revision_.load(std::memory_order_acquire); }
    std::vector<SignalInfo> catalog() const;  // sorted by key; bits of 6040h/6041h included
    std::optional<SignalInfo> info(const SignalKey& key) const;
    // The samples of a signal (of its word for a bit key); null when unknown.
    std::shared_ptr<const SignalBuffer> buffer(const SignalKey& key) const;
    // Time of the first frame consumed (the plot's t = 0); nullopt before any.
    std::optional<int64_t> originNs() const;
    int64_t latestNs() const { return latestNs_.load(std::memory_order_acquire); }
    uint64_t framesConsumed() const { return frames_.load(std::memory_order_acquire); }

    // A PDO seen in the trace (by its COB-ID), whether or not its mapping is known: what the
    // plot can say when it has no signal to offer ("TPDO1 185h of node 5: no dictionary").
    struct PdoSeen {
        int bus = 0;
        uint32_t cobId = 0;
        int node = -1;
        QString pdo;  // "TPDO1"
        bool operator<(const PdoSeen& o) const { return std::tie(bus, cobId) < std::tie(o.bus, o.cobId); }
    };
    std::vector<PdoSeen> pdosSeen() const;  // any thread; sorted by bus and COB-ID

private:
    struct Slot {
        SignalInfo info;
        std::shared_ptr<SignalBuffer> buffer;
        std::vector<SignalSample> pending;  // ingest thread only
    };
    Slot& slotFor(int bus, int node, const PdoMapEntry& e, bool tpdo, int pdoNumber);
    bool notePdoSeen(int bus, uint32_t id, bool extended);
    Slot& rawSlot(int bus, size_t number);
    void recordRaw(const CanFrame& f, FrameNo n);
    void ensureCatalogue();
    void applyDictionaries();
    void learnParameter(int bus, int node, const SdoTransferRecord& t);
    // Modes of operation 6061h (6060h) seen in PDOs or SDO transfers, for the names of the
    // statusword's mode-specific bits; ingest thread, modes_ under mutex_.
    void learnMode(int bus, int node, uint16_t index, uint8_t sub, uint64_t raw);
    std::optional<int8_t> modeOf(const SignalKey& word) const;  // mutex_ held
    SignalScale scaleFor(int bus, int node, const QString& dictionary, const QString& unit, double factor) const;

    const size_t capacity_;
    NetworkContext context_;
    Dissection scratch_;

    mutable std::mutex mutex_;  // guards slots_ inserts/info and the pending dictionaries
    std::unordered_map<uint64_t, std::unique_ptr<Slot>> slots_;  // by SignalKey::packed() of the word
    std::vector<Slot*> dirty_;
    std::map<int, QString> pendingNames_, appliedNames_;
    bool namesChanged_ = false;
    std::vector<RawSignal> pendingRaw_, raw_;  // pendingRaw_ guarded by mutex_; raw_ ingest thread
    bool rawChanged_ = false;
    std::vector<std::bitset<2048>> pdoSeenStd_;  // ingest thread: [bus][11-bit COB-ID] in pdos_
    std::set<uint64_t> pdoKeysExtended_;         // ingest thread: bus << 32 | 29-bit COB-ID in pdos_
    std::vector<PdoSeen> pdos_;                  // guarded by mutex_
    std::map<uint64_t, int8_t> modes_;           // bus << 32 | node << 8 | axis -> mode (guarded by mutex_)
    std::map<uint64_t, double> parameters_;      // bus << 32 | node << 24 | index << 8 | sub -> value
    std::atomic<uint64_t> revision_{1};
    std::atomic<int64_t> originNs_{0};
    std::atomic<bool> haveOrigin_{false};
    std::atomic<int64_t> latestNs_{0};
    std::atomic<uint64_t> frames_{0};
};

}  // namespace coscope::dissect
