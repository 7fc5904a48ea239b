// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/HeartbeatProducer.h"
#include "core/canopen/MasterContext.h"
#include "core/canopen/PeriodicSender.h"
#include "core/canopen/SyncProducer.h"
#include "core/canopen/TransmitList.h"

namespace coscope::canopen {

// The master services that send on their own, one owner per open bus (DESIGN.md "Master
// services ... live in core with one owner per open bus"): the SYNC producer, the tool's
// heartbeat and the transmit list, all scheduled on the bus's one PeriodicSender
// (context.periodic()). The GUI's Workspace and the CLI's BusSession each own one per bus,
// created after the MasterContext and destroyed before the bus closes.
//
// Thread-safety: create, use and destroy on one thread (the owner's); the parts document what
// they allow from other threads.
class BusMaster {
public:
    explicit BusMaster(MasterContext& context);
    ~BusMaster();  // stopAll()
    BusMaster(const BusMaster&) = delete;
    BusMaster& operator=(const BusMaster&) = delete;

    MasterContext& context() { return context_; }
    PeriodicSender& periodic() { return context_.periodic(); }
    SyncProducer& sync() { return sync_; }
    HeartbeatProducer& heartbeat() { return heartbeat_; }
    TransmitList& transmit() { return transmit_; }

    // Stops SYNC, the heartbeat and every periodic transmit row (the rows are kept).
    void stopAll();
    // Anything sending periodically now (SYNC, heartbeat or a transmit row).
    bool anyRunning() const;

private:
    MasterContext& context_;
    SyncProducer sync_;
    HeartbeatProducer heartbeat_;
    TransmitList transmit_;
};

}  // namespace coscope::canopen
