// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanBus.h"
#include "core/trace/TraceStore.h"

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace coscope {

// The ingest worker of DESIGN.md "Data flow": drains a bus's ring on its own thread, appends to
// the trace store and hands each new batch to consumers (dissection, node table, plot buffers,
// recorder) on that same thread. Views poll the store; nothing per frame crosses a Qt signal.
class CaptureSession {
public:
    // Called on the ingest thread with the frame numbers [first, first + count) just appended.
    using Consumer = std::function<void(const TraceStore& store, FrameNo first, size_t count)>;

    explicit CaptureSession(std::shared_ptr<TraceStore> store = std::make_shared<TraceStore>());
    ~CaptureSession();

    void addConsumer(Consumer consumer);  // before start()
    // Starts draining `bus` (already created; may be opening). The session does not own it.
    void start(CanBus* bus);
    void stop();
    bool isRunning() const { return running_.load(); }

    const std::shared_ptr<TraceStore>& store() const { return store_; }

private:
    void run();

    std::shared_ptr<TraceStore> store_;
    std::vector<Consumer> consumers_;
    CanBus* bus_ = nullptr;
    std::thread thread_;
    std::atomic<bool> running_{false};
};

}  // namespace coscope
