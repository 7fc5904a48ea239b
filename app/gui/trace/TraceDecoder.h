// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/trace/FrameDecoder.h"
#include "dissectors/NetworkContext.h"

#include <QString>

#include <atomic>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace coscope::gui {

// The decoder the app uses: the dissectors with their network context (dictionary names, PDO
// mappings learned from SDO, SDO reassembly, EMCY vendor alarms, CiA 402 meaning).
//
// Random access (DESIGN.md "dissectors/"): a snapshot of the context is kept every
// NetworkContext::checkpointInterval() frames of the bound store; frame N is decoded by copying
// the nearest snapshot at or before N and dissecting forward to N. A worker thread builds the
// snapshots as the store grows; a caller that gets ahead of it builds the missing ones itself.
// Each thread keeps a cursor (a context positioned after the frame it decoded last), so the
// rows of a view or a filter scan, asked in order, cost one dissection each.
// decode() (no trace context) uses the assigned dictionaries only. Thread-safe.
class TraceDecoder final : public FrameDecoder {
public:
    explicit TraceDecoder(bool background = true);
    ~TraceDecoder() override;
    TraceDecoder(const TraceDecoder&) = delete;
    TraceDecoder& operator=(const TraceDecoder&) = delete;

    // The store decodeAt() answers for (others are decoded frame by frame); forgets the snapshots.
    void setStore(std::shared_ptr<const TraceStore> store);
    // Node-ID -> dictionary (bundled name or EDS/DCF/XDD file), as matched or assigned in the
    // node table. Nodes not listed are matched by the identity read in the trace. A change
    // forgets the snapshots. Names that fail to load are skipped (see lastError()).
    void setDictionaries(const std::map<int, QString>& names);
    std::map<int, QString> dictionaries() const;
    QString lastError() const;

    void decode(const CanFrame& frame, dissect::Dissection& out) const override;
    void decodeAt(const TraceStore& store, FrameNo n, dissect::Dissection& out) const override;
    uint64_t revision() const override { return revision_.load(std::memory_order_acquire); }

    // Snapshots built so far (snapshot k = context before frame k * interval).
    size_t checkpointCount() const;

private:
    void resetCheckpointsLocked();
    bool extendOnceLocked(std::unique_lock<std::mutex>& lock) const;  // false when nothing to do
    void workerLoop();

    const uint64_t id_;  // keys the per-thread cursors
    mutable std::mutex mutex_;
    mutable std::condition_variable wake_;
    dissect::NetworkContext base_;  // dictionaries, no frames seen
    std::shared_ptr<const TraceStore> store_;
    mutable std::vector<std::shared_ptr<const dissect::NetworkContext>> checkpoints_;
    mutable bool extending_ = false;  // someone is building the next snapshot outside the lock
    std::map<int, QString> names_;
    std::map<QString, std::pair<dissect::DictionaryPtr, QString>> loaded_;  // name or file -> dictionary, its name
    QString lastError_;
    std::atomic<uint64_t> revision_{1};
    bool stop_ = false;
    std::thread worker_;
};

}  // namespace coscope::gui
