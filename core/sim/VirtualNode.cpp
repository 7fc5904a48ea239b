// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/VirtualNode.h"

#include <QStringList>

#include <cmath>

namespace coscope::sim {

VirtualNode::VirtualNode(uint8_t nodeId, QString dictionary) : id_(nodeId), dictionary_(std::move(dictionary)) {}

QStringList VirtualNode::simulatableDictionaries() {
    return {QStringLiteral("delta-asda-a2"), QStringLiteral("aimotor"), QStringLiteral("dexmart-dev"),
            QStringLiteral("generic-cia402")};
}

std::unique_ptr<SimNode> VirtualNode::create(uint8_t nodeId, const QString& dictionary, QString* error) {
    if (dictionary == u"icpdas-ecat-2094p") {
        if (error) *error = QStringLiteral("icpdas-ecat-2094p is an EtherCAT device: it is bundled for offline reference and cannot be simulated on CAN");
        return nullptr;
    }
    if (!simulatableDictionaries().contains(dictionary)) {
        if (error)
            *error = QStringLiteral("unknown virtual drive '%1'; known: %2")
                         .arg(dictionary, simulatableDictionaries().join(QStringLiteral(", ")));
        return nullptr;
    }
    return std::make_unique<VirtualNode>(nodeId, dictionary);
}

void VirtualNode::powerOn(int64_t nowNs) { bootUp(nowNs); }

void VirtualNode::bootUp(int64_t nowNs) {
    // Boot-up message: COB-ID 700h + node-ID, one byte 00h (CiA 301 §7.2.8.3.3); then PRE-OPERATIONAL.
    transmit(CanFrame::classic(0x700u + id_, {0x00}));
    state_ = PreOperational;
    nextHeartbeatNs_ = nowNs + heartbeatPeriodNs_;
}

void VirtualNode::sendHeartbeat() { transmit(CanFrame::classic(0x700u + id_, {static_cast<uint8_t>(state_)})); }

void VirtualNode::onFrame(const CanFrame& f, int64_t nowNs) {
    if (f.isExtended() || f.isRemote() || f.isError()) return;
    // NMT node control: COB-ID 000h, byte 0 command specifier, byte 1 node-ID (0 = all) (CiA 301 §7.2.8.3.1).
    if (f.id == 0x000 && f.len == 2 && (f.data[1] == 0 || f.data[1] == id_)) {
        switch (f.data[0]) {
        case 0x01: state_ = Operational; break;
        case 0x02: state_ = Stopped; break;
        case 0x80: state_ = PreOperational; break;
        case 0x81:
        case 0x82: bootUp(nowNs); return;
        default: return;
        }
    }
}

void VirtualNode::tick(int64_t nowNs) {
    if (state_ == BootUp) return;
    if (nowNs >= nextHeartbeatNs_) {
        sendHeartbeat();
        nextHeartbeatNs_ += heartbeatPeriodNs_;
        if (nextHeartbeatNs_ < nowNs) nextHeartbeatNs_ = nowNs + heartbeatPeriodNs_;
    }
    if (state_ == Operational && nowNs >= nextPdoNs_) {
        nextPdoNs_ = nowNs + 10'000'000;  // 10 ms
        const double t = static_cast<double>(nowNs % 60'000'000'000LL) / 1e9;
        velocity_ = static_cast<int32_t>(1000.0 * std::sin(t * 2.0 * M_PI / 4.0));
        position_ += velocity_ / 100;
        const auto p = static_cast<uint32_t>(position_);
        // TPDO1 (180h + node-ID): statusword 0x0237 (operation enabled) + position actual value.
        transmit(CanFrame::classic(0x180u + id_, {0x37, 0x02, static_cast<uint8_t>(p), static_cast<uint8_t>(p >> 8),
                                                  static_cast<uint8_t>(p >> 16), static_cast<uint8_t>(p >> 24)}));
    }
}

}  // namespace coscope::sim
