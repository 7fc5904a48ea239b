// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/sim/SimNode.h"

#include <QByteArray>

#include <cstdint>
#include <deque>
#include <vector>

namespace coscope::sim {

class SimNetwork;

// The sim:// option demo=1 (README "Virtual drives"): a virtual PLC on the simulated bus that does
// what `coscope --simulate` does as master, so that `coscope-cli listen "sim://?demo=1"` shows a
// living network: producer heartbeat 1017h = 500 ms on every drive, NMT Start (all nodes), the
// AIMOTOR enabled in profile velocity (CiA 402-2: 6060h = 3, 6040h 06h -> 07h -> 0Fh) with a
// target velocity 60FFh that changes every 2 s, and SYNC every 10 ms, which the AIMOTOR's default
// TPDOs follow (extract-aimotor §3.6, transmission type 1). The drives keep their own defaults:
// everything happens through frames on the bus, as from a real master.
class DemoMaster : public SimNode {
public:
    // Plans the demo for the devices on `network` (before it starts).
    explicit DemoMaster(const SimNetwork& network);

    uint8_t nodeId() const override { return 0; }  // a master has no node-ID here; not a VirtualDevice
    void powerOn(int64_t nowNs) override;
    void onFrame(const CanFrame&, int64_t) override {}
    void tick(int64_t nowNs) override;

private:
    struct Step {
        CanFrame frame;
        int64_t pauseNs;  // before the next step
    };
    void sdoWrite(uint8_t node, uint16_t index, uint8_t sub, int64_t value, int bytes, int64_t pauseMs = 1);

    std::deque<Step> steps_;
    int64_t nextStepNs_ = -1;  // -1: not powered
    int64_t nextSyncNs_ = -1;  // -1: SYNC not started yet
    int64_t nextTargetNs_ = -1;
    uint8_t aimotor_ = 0;  // 0: none on this network
    size_t target_ = 0;
};

}  // namespace coscope::sim
