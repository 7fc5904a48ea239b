// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanBus.h"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace coscope {

// replay://PATH?speed=1.0&loop=1 — plays a log file (any format core/logio reads) with its
// original timing on its own thread. speed scales time (2 = twice as fast, 0 = as fast as the
// consumer takes frames); loop=1 starts over at the end. Delivered timestamps keep the log's
// spacing, shifted so the first frame of each pass is "now". Without loop the bus closes with
// "replay finished". Bad lines are reported through errorOccurred and the rest plays.
// A replay bus is read-only: send() fails.
class ReplayBus : public CanBus {
    Q_OBJECT
public:
    explicit ReplayBus(const BusUrl& url, QObject* parent = nullptr);
    ~ReplayBus() override;

    void open() override;
    void close() override;

protected:
    bool sendFrame(const CanFrame& frame, QString* error) override;

private:
    void run();
    void stopThread();
    // Sleeps until the steady-clock time `dueNs`; false when stopping.
    bool waitUntil(int64_t dueNs);

    std::thread thread_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::atomic<bool> stop_{false};
};

}  // namespace coscope
