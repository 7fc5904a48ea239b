// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/MasterContext.h"
#include "core/canopen/PeriodicSender.h"

#include <QString>

#include <atomic>
#include <memory>

namespace coscope::canopen {

// The tool's own heartbeat (CiA 301 §7.2.8.3.2): COB-ID 700h + node-ID, one data byte with the
// NMT state of the producer (04h stopped, 05h operational, 7Fh pre-operational), every producer
// heartbeat time (1017h, ms). Drives that consume it (1016h) notice when CoScope is gone.
// Sent by the bus's PeriodicSender.
//
// Thread-safety: configure, start, stop and poll from one thread (the owner's); setState(),
// state() and frame() may be called from any thread.
class HeartbeatProducer {
public:
    static constexpr uint8_t kDefaultNodeId = 127;
    static constexpr uint16_t kDefaultPeriodMs = 1000;

    // Uses the bus's scheduler, context.periodic().
    explicit HeartbeatProducer(MasterContext& context);
    ~HeartbeatProducer();  // stops
    HeartbeatProducer(const HeartbeatProducer&) = delete;
    HeartbeatProducer& operator=(const HeartbeatProducer&) = delete;

    // Node-ID 1..127 (false otherwise). While running, the next heartbeats use it.
    bool setNodeId(uint8_t node);
    uint8_t nodeId() const { return node_; }

    // Producer heartbeat time in ms, 1..65535 (1017h; false for 0). While running, applied from
    // the next frame on.
    bool setPeriodMs(uint16_t ms);
    uint16_t periodMs() const { return periodMs_; }

    // The NMT state byte sent (CiA 301 Table 54: 00h boot-up, 04h stopped, 05h operational,
    // 7Fh pre-operational); default 05h. Takes effect with the next heartbeat.
    void setState(uint8_t nmtState);
    uint8_t state() const;

    // Starts: the first heartbeat at once. False with *error when the bus refused it
    // (listen-only, not open). Restarts when running.
    bool start(QString* error = nullptr);
    void stop();
    bool isRunning() const;
    uint64_t sent() const;      // heartbeats sent since construction
    QString lastError() const;  // why the last run stopped by itself; empty otherwise

    // The heartbeat frame as it would go out now.
    CanFrame frame() const;

private:
    struct Shared;
    void stopJob();

    MasterContext& context_;
    PeriodicSender::JobId job_ = 0;
    std::shared_ptr<Shared> shared_;  // node and state, read on the sender thread
    uint8_t node_ = kDefaultNodeId;
    uint16_t periodMs_ = kDefaultPeriodMs;
    uint64_t sentBefore_ = 0;  // heartbeats of finished runs
    QString lastError_;        // of the last finished run
};

}  // namespace coscope::canopen
