// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/HeartbeatConsumer.h"

#include "core/canopen/SdoAbort.h"
#include "core/sim/Ds402Drive.h"
#include "core/sim/VirtualDevice.h"

namespace coscope::sim {

namespace {
constexpr uint16_t kHeartbeatError = 0x8130;  // life guard error or heartbeat error (CiA 301 Table 21)

uint8_t producerOf(uint32_t entry) { return static_cast<uint8_t>(entry >> 16); }
uint32_t timeOf(uint32_t entry) { return entry & 0xFFFF; }
// An entry watches a node when both its node-ID (1..127) and its time are set (CiA 301 §7.5.2.18).
bool inUse(uint32_t entry) { return timeOf(entry) != 0 && producerOf(entry) >= 1 && producerOf(entry) <= 127; }
}  // namespace

HeartbeatConsumer::HeartbeatConsumer(VirtualDevice& device) : dev_(device) {}

void HeartbeatConsumer::reset() { watching_.clear(); }

uint32_t HeartbeatConsumer::entry(uint8_t sub) const {
    return static_cast<uint32_t>(dev_.value(0x1016, sub).value_or(od::Value{}).toUInt64().value_or(0));
}

void HeartbeatConsumer::onHeartbeat(uint8_t producer, int64_t nowNs) {
    const auto count = dev_.value(0x1016, 0).value_or(od::Value{}).toUInt64().value_or(0);
    for (uint8_t sub = 1; sub <= count && sub < 255; ++sub) {
        const uint32_t e = entry(sub);
        if (!inUse(e) || producerOf(e) != producer) continue;
        // The time runs from the first heartbeat on (CiA 301 §7.2.8.3.2.2; extract-aimotor §3.3).
        watching_[sub] = Watch{e, nowNs};
    }
}

void HeartbeatConsumer::tick(int64_t nowNs) {
    for (auto it = watching_.begin(); it != watching_.end();) {
        const uint32_t e = entry(it->first);
        if (e != it->second.armedWith) {
            it = watching_.erase(it);  // rewritten: waits for a first heartbeat again
            continue;
        }
        if (nowNs - it->second.lastNs > int64_t(timeOf(e)) * 1'000'000) {
            it = watching_.erase(it);  // one event; watching again from the next heartbeat
            masterLost(producerOf(e));
            continue;
        }
        ++it;
    }
}

uint32_t HeartbeatConsumer::checkWrite(uint8_t sub, uint32_t value) const {
    if (!inUse(value)) return 0;
    // Several consumer times for one node-ID: abort 06040043h (CiA 301 §7.5.2.18).
    const auto count = dev_.value(0x1016, 0).value_or(od::Value{}).toUInt64().value_or(0);
    for (uint8_t s = 1; s <= count && s < 255; ++s)
        if (s != sub && inUse(entry(s)) && producerOf(entry(s)) == producerOf(value))
            return canopen::sdoabort::ParameterIncompatible;
    return 0;
}

void HeartbeatConsumer::masterLost(uint8_t producer) {
    (void)producer;
    ++events_;
    const Vendor vendor = dev_.personality().vendor;
    const bool vendorAlarm = (vendor == Vendor::Delta || vendor == Vendor::Aimotor) && dev_.axisCount() > 0;
    if (vendorAlarm) {
        // The drive raises its alarm (EMCY 8130h with the alarm number, 603Fh, fault).
        bool servoOn = false;
        for (int a = 0; a < dev_.axisCount(); ++a) servoOn |= dev_.drive(a)->enabled();
        dev_.injectDriveFault(vendor == Vendor::Aimotor ? QStringLiteral("Er.D03")
                              : servoOn                 ? QStringLiteral("AL170")
                                                        : QStringLiteral("AL180"));
    } else {
        // CiA 402 abort connection option 1 "fault signal": the axis faults (EMCY, 603Fh).
        bool faulted = false;
        for (int a = 0; a < dev_.axisCount(); ++a)
            if (abortOption(a) == 1) {
                dev_.injectDriveFault(DriveFault{kHeartbeatError, 0, a});
                faulted = true;
            }
        if (!faulted) {
            dev_.recordError(kHeartbeatError, 0);
            const uint8_t none[5] = {};
            dev_.sendEmcy(kHeartbeatError, none);
        }
    }
    // Communication error behaviour 1029h:01 (CiA 301 §7.5.2.32).
    if (const auto behaviour = dev_.value(0x1029, 1)) {
        const auto b = behaviour->toUInt64().value_or(0);
        if (b == 0 && dev_.nmtState() == canopen::NmtState::Operational)
            dev_.setNmtState(canopen::NmtState::PreOperational);
        else if (b == 2) dev_.setNmtState(canopen::NmtState::Stopped);
    }
    if (!vendorAlarm) reactOnAxes();
}

int64_t HeartbeatConsumer::abortOption(int axis) const {
    const auto option = dev_.value(static_cast<uint16_t>(0x6007 + axis * 0x800), 0);
    return option ? option->toInt64().value_or(0) : 0;
}

void HeartbeatConsumer::reactOnAxes() {
    // 2 disable voltage, 3 quick stop (the drive model runs the command).
    for (int a = 0; a < dev_.axisCount(); ++a)
        if (const int64_t code = abortOption(a); code == 2 || code == 3)
            dev_.drive(a)->abortConnection(static_cast<int16_t>(code));
}

}  // namespace coscope::sim
