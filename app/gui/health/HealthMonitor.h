// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/health/ owns the Health view: the network health report of dissectors/
// (NetworkHealth) fed from the trace, its table models and the dock.
#pragma once

#include "core/trace/TraceStore.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/NetworkHealth.h"

#include <atomic>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace coscope::gui {

// Feeds the workspace's frames (live on the ingest thread, or while a log loads) to a
// NetworkHealth with its own network context, the same code as `coscope-cli stats`. The view asks
// for a report now and then; both sides take the lock briefly. Thread-safe.
class HealthMonitor {
public:
    HealthMonitor();
    ~HealthMonitor();
    HealthMonitor(const HealthMonitor&) = delete;
    HealthMonitor& operator=(const HealthMonitor&) = delete;

    // Analyses the frames now, on the calling thread (a live capture: the report keeps up).
    void consume(const TraceStore& store, FrameNo first, size_t count);
    // Analyses them soon, in order, on the monitor's own lowest-priority thread: while a log
    // opens, the trace, its index, filters and plots get the CPU first and the Health view fills
    // in behind them (issue 19). Until clear(), report() is then the one that thread last
    // published (every 250 ms and when it has caught up), so the view never waits
    // for a thread the scheduler may keep waiting. Not mixed with consume() before a clear().
    void consumeLater(std::shared_ptr<const TraceStore> store, FrameNo first, size_t count);
    // Every frame handed to consumeLater() is in the report.
    bool caughtUp() const;
    // Forgets every frame, including those still waiting for consumeLater()'s thread.
    void clear();
    // The report as of `nowNs` (live: the wall clock, so a stopped heartbeat shows; offline: the
    // last frame, pass INT64_MIN).
    dissect::HealthReport report(int64_t nowNs) const;
    // Bumps with every frame consumed (or report published) and on clear(): the view recomputes
    // only when it moved.
    uint64_t revision() const { return revision_.load(std::memory_order_acquire); }

private:
    struct Pending {
        std::shared_ptr<const TraceStore> store;
        FrameNo first;
        size_t count;
    };
    void addLocked(const TraceStore& store, FrameNo first, size_t count);  // stateMutex_ held
    void laterLoop();

    mutable std::mutex stateMutex_;  // ctx_, d_, health_: whoever analyses or reports live
    dissect::NetworkContext ctx_;
    dissect::Dissection d_;
    dissect::NetworkHealth health_;
    std::atomic<uint64_t> revision_{0};
    std::atomic<uint64_t> generation_{0};  // bumped by clear(): work taken before it is dropped

    mutable std::mutex mutex_;     // the rest
    std::deque<Pending> pending_;  // consumeLater()'s ranges, oldest first
    size_t inFlight_ = 0;          // frames its thread has taken and not yet published
    bool laterMode_ = false;       // consumeLater() since the last clear(): report() is published_
    std::optional<dissect::HealthReport> published_;
    std::condition_variable pendingAdded_;
    bool stopping_ = false;
    std::thread later_;  // started by the first consumeLater()
};

}  // namespace coscope::gui
