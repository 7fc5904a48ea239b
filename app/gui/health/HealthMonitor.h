// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/health/ owns the Health view: the network health report of dissectors/
// (NetworkHealth) fed from the trace, its table models and the dock.
#pragma once

#include "core/trace/TraceStore.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/NetworkHealth.h"

#include <atomic>
#include <mutex>

namespace coscope::gui {

// Feeds the workspace's frames (live on the ingest thread, or while a log loads) to a
// NetworkHealth with its own network context, the same code as `coscope-cli stats`. The view asks
// for a report now and then; both sides take the lock briefly. Thread-safe.
class HealthMonitor {
public:
    HealthMonitor();

    void consume(const TraceStore& store, FrameNo first, size_t count);
    void clear();
    // The report as of `nowNs` (live: the wall clock, so a stopped heartbeat shows; offline: the
    // last frame, pass INT64_MIN).
    dissect::HealthReport report(int64_t nowNs) const;
    // Bumps with every frame consumed and on clear(): the view recomputes only when it moved.
    uint64_t revision() const { return revision_.load(std::memory_order_acquire); }

private:
    mutable std::mutex mutex_;
    dissect::NetworkContext ctx_;
    dissect::Dissection d_;
    dissect::NetworkHealth health_;
    std::atomic<uint64_t> revision_{0};
};

}  // namespace coscope::gui
