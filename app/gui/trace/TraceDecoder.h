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
//
// Bounded memory (issue 38: a snapshot is tens of kilobytes, ~14 bytes a frame, for ever): the
// snapshots kept are the newest kRecent ones (where a live view and its filters look), older ones
// on a grid of `stride` intervals, at most kSparse of them (when there are more, the stride
// doubles and every other one goes), and the kCached ones rebuilt last for older frames. A
// snapshot not kept is rebuilt from the nearest kept one before it, dissecting the frames
// between (paged back from the journal when they are not in RAM): decodeAt() does it on the
// calling thread; readyAt() asks the worker for it, so the GUI thread draws the row as loading
// rather than wait.
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

    // Every snapshot of the frames before n is at hand (kept or cached), so decodeAt() costs at
    // most one interval of dissection; otherwise false, and the worker rebuilds it: ask again
    // once readyCount() moved. Any thread.
    bool readyAt(const TraceStore& store, FrameNo n) const override;
    uint64_t readyCount() const override { return rebuilt_.load(std::memory_order_acquire); }

    // A snapshot of two drives' network is ~90 KiB (128 nodes' state): at most ~25 MiB in all.
    static constexpr size_t kRecent = 128;  // the newest 512 Ki frames
    static constexpr size_t kSparse = 128;  // older ones, on the grid
    static constexpr size_t kCached = 32;   // rebuilt for older frames, least recently used go first

    // Snapshot positions built so far (snapshot k = context before frame k * interval).
    size_t checkpointCount() const;
    // Snapshots held in memory now (at most kRecent + kSparse + 1 + kCached).
    size_t keptCheckpoints() const;
    size_t checkpointStride() const;

private:
    void resetCheckpointsLocked();
    bool extendOnceLocked(std::unique_lock<std::mutex>& lock) const;  // false when nothing to do
    void thinLocked() const;  // drops what left the newest kRecent and is off the grid
    std::shared_ptr<const dissect::NetworkContext> findLocked(size_t k) const;
    // Snapshot k (< built_) rebuilt from the nearest one before it; unlocks while dissecting.
    std::shared_ptr<const dissect::NetworkContext> rebuildLocked(std::unique_lock<std::mutex>& lock, size_t k) const;
    void workerLoop();

    const uint64_t id_;  // keys the per-thread cursors
    mutable std::mutex mutex_;
    mutable std::condition_variable wake_;
    dissect::NetworkContext base_;  // dictionaries, no frames seen
    std::shared_ptr<const TraceStore> store_;
    // k -> snapshot: the newest kRecent and the grid (0 always, then multiples of stride_).
    mutable std::map<size_t, std::shared_ptr<const dissect::NetworkContext>> checkpoints_;
    mutable size_t built_ = 1;  // positions [0, built_) done; built_ - 1 is always kept
    mutable size_t stride_ = 1;
    struct Cached {
        std::shared_ptr<const dissect::NetworkContext> context;
        uint64_t used = 0;
    };
    mutable std::map<size_t, Cached> cache_;  // rebuilt ones, at most kCached
    mutable uint64_t useClock_ = 0;
    mutable std::vector<size_t> wanted_;  // readyAt()'s requests for the worker
    mutable std::atomic<uint64_t> rebuilt_{0};
    mutable bool extending_ = false;  // someone is building the next snapshot outside the lock
    std::map<int, QString> names_;
    std::map<QString, std::pair<dissect::DictionaryPtr, QString>> loaded_;  // name or file -> dictionary, its name
    QString lastError_;
    std::atomic<uint64_t> revision_{1};
    bool stop_ = false;
    std::thread worker_;
};

}  // namespace coscope::gui
