// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/sim/SimNode.h"

#include <QString>

#include <memory>

namespace coscope::sim {

// A virtual CANopen device on the simulated bus: NMT slave with boot-up and heartbeat producer
// (CiA 301 §7.2.8.3), and in OPERATIONAL a TPDO1 carrying a moving position so the bus has
// life. The dictionary-driven device model (SDO server, PDO engine, CiA 402) builds on this.
class VirtualNode : public SimNode {
public:
    enum NmtState : uint8_t { BootUp = 0x00, Stopped = 0x04, Operational = 0x05, PreOperational = 0x7F };

    VirtualNode(uint8_t nodeId, QString dictionary);

    static std::unique_ptr<SimNode> create(uint8_t nodeId, const QString& dictionary, QString* error);
    static QStringList simulatableDictionaries();

    uint8_t nodeId() const override { return id_; }
    const QString& dictionary() const { return dictionary_; }
    NmtState nmtState() const { return state_; }

    void powerOn(int64_t nowNs) override;
    void onFrame(const CanFrame& frame, int64_t nowNs) override;
    void tick(int64_t nowNs) override;

private:
    void bootUp(int64_t nowNs);
    void sendHeartbeat();

    uint8_t id_;
    QString dictionary_;
    NmtState state_ = BootUp;
    int64_t nextHeartbeatNs_ = 0;
    int64_t nextPdoNs_ = 0;
    int64_t heartbeatPeriodNs_ = 1'000'000'000;  // 1017h producer heartbeat time
    int32_t position_ = 0;
    int32_t velocity_ = 0;
};

}  // namespace coscope::sim
