// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"

#include <cstdint>
#include <functional>

namespace coscope::sim {

// A device on the in-process virtual bus. Everything a node does runs on the network's thread:
// onFrame() for each frame another participant sent, tick() once per millisecond.
class SimNode {
public:
    virtual ~SimNode() = default;

    virtual uint8_t nodeId() const = 0;
    virtual void powerOn(int64_t nowNs) = 0;  // the node sends its boot-up here
    virtual void onFrame(const CanFrame& frame, int64_t nowNs) = 0;
    virtual void tick(int64_t nowNs) = 0;
    // The bit rate the node's CAN controller runs at (bit/s); it only hears and is heard by
    // participants at the same rate. 0 = any rate (a node that does not model bit timing).
    virtual uint32_t bitRate() const { return 0; }

    // Set by the network: puts a frame on the bus.
    void setTransmitter(std::function<void(const CanFrame&)> tx) { transmit_ = std::move(tx); }

protected:
    void transmit(const CanFrame& frame) const {
        if (transmit_) transmit_(frame);
    }

private:
    std::function<void(const CanFrame&)> transmit_;
};

}  // namespace coscope::sim
