// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanBus.h"
#include "core/sim/SimNetwork.h"

#include <memory>

namespace coscope {

// sim:// — a bus endpoint on an in-process virtual network (core/sim). With
// sim://?nodes=1:delta-asda-a2,2:aimotor the network holds those virtual drives; sim:// alone
// holds the default set. The network runs on its own thread; frames reach the ring from there.
// bitrate=N puts this endpoint at N bit/s: it only sees devices running at that rate (the
// devices start at SimNetwork::kDefaultBitRate). Without bitrate= the endpoint is rate-agnostic:
// it hears and reaches every device whatever its rate (like before bit rates were modelled). sim://NAME names the network: every endpoint opening that name
// shares it (SimNetwork::publish), so closing and reopening keeps the devices as they are.
class SimBus : public CanBus, public sim::SimTap {
    Q_OBJECT
public:
    explicit SimBus(const BusUrl& url, QObject* parent = nullptr);
    // Attach to an existing network (several endpoints on one virtual bus).
    SimBus(const BusUrl& url, std::shared_ptr<sim::SimNetwork> network, QObject* parent = nullptr);
    ~SimBus() override;

    void open() override;
    void close() override;

    sim::SimNetwork* network() const { return network_.get(); }
    std::shared_ptr<sim::SimNetwork> sharedNetwork() const { return network_; }

    void simReceive(const CanFrame& frame, bool own) override;
    uint32_t simBitRate() const override { return bitRate_; }

protected:
    bool sendFrame(const CanFrame& frame, QString* error) override;

private:
    std::shared_ptr<sim::SimNetwork> network_;
    bool attached_ = false;
    uint32_t bitRate_ = 0;  // 0 = any rate
};

}  // namespace coscope
