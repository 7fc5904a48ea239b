// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"

#include <cstdint>
#include <deque>

namespace coscope::sim {

class VirtualDevice;

// The LSS slave of a virtual device (CiA 305): switch state global and selective, configure
// node-ID and bit timing, activate bit timing, store configuration, inquire identity/node-ID,
// identify remote slave / non-configured slave, and fastscan. Identity is 1018h sub 1-4.
class LssSlave {
public:
    explicit LssSlave(VirtualDevice& device);

    bool configurationState() const { return configuration_; }
    void onFrame(const CanFrame& frame);
    // Sends the answers held back by LssFaults::replyDelayMs once due.
    void tick(int64_t nowNs);

private:
    uint32_t identity(int field) const;  // 0 vendor, 1 product, 2 revision, 3 serial
    void reply(uint8_t cs, uint8_t b1 = 0, uint8_t b2 = 0, uint32_t value = 0, bool withValue = false);

    VirtualDevice& dev_;
    bool configuration_ = false;
    int selectiveStep_ = 0;  // switch-state-selective: fields matched so far
    int identifyStep_ = 0;   // identify remote slave: fields matched so far
    uint32_t revLow_ = 0, serialLow_ = 0;
    int fastscanSub_ = 0;  // LSSSub the slave expects next (0..3), -1 = dropped out
    struct Delayed {
        int64_t dueNs;
        CanFrame frame;
    };
    std::deque<Delayed> delayed_;
};

}  // namespace coscope::sim
