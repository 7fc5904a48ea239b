// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/LssSlave.h"

#include "core/canopen/Lss.h"
#include "core/sim/VirtualDevice.h"

namespace coscope::sim {

using namespace canopen;

namespace {
uint32_t le32(const uint8_t* b) {
    return uint32_t(b[0]) | uint32_t(b[1]) << 8 | uint32_t(b[2]) << 16 | uint32_t(b[3]) << 24;
}
}  // namespace

LssSlave::LssSlave(VirtualDevice& device) : dev_(device) {}

uint32_t LssSlave::identity(int field) const {
    // LSS address = 1018h sub 1-4 (CiA 305 §4.2).
    return static_cast<uint32_t>(
        dev_.value(0x1018, static_cast<uint8_t>(field + 1)).value_or(od::Value{}).toUInt64().value_or(0));
}

void LssSlave::reply(uint8_t cs, uint8_t b1, uint8_t b2, uint32_t value, bool withValue) {
    CanFrame f = CanFrame::classic(lss::kSlaveToMaster, {cs, b1, b2, 0, 0, 0, 0, 0});
    if (withValue) {
        f.data[1] = uint8_t(value);
        f.data[2] = uint8_t(value >> 8);
        f.data[3] = uint8_t(value >> 16);
        f.data[4] = uint8_t(value >> 24);
    }
    if (dev_.lssFaults_.replyDelayMs > 0) {
        delayed_.push_back({dev_.now() + int64_t(dev_.lssFaults_.replyDelayMs) * 1'000'000, f});
        return;
    }
    dev_.send(f);
}

void LssSlave::tick(int64_t nowNs) {
    while (!delayed_.empty() && delayed_.front().dueNs <= nowNs) {
        dev_.send(delayed_.front().frame);
        delayed_.pop_front();
    }
}

void LssSlave::onFrame(const CanFrame& f) {
    if (f.len < 1) return;
    const uint8_t* d = f.data.data();
    const uint8_t cs = d[0];
    const uint32_t v = le32(d + 1);
    switch (cs) {
    case lss::SwitchStateGlobal: {
        const bool wasConfiguration = configuration_;
        configuration_ = d[1] == 1;
        selectiveStep_ = 0;
        // An unconfigured node given a node-ID starts with it when switched to waiting state
        // (CiA 305 §6.3.2: LSS-unconfigured -> NMT reset communication with the new node-ID).
        if (wasConfiguration && !configuration_ && dev_.nodeId_ == 0xFF && dev_.pendingNodeId_ != 0xFF)
            dev_.resetCommunication(dev_.now());
        return;
    }
    case lss::SwitchSelectiveVendor:
    case lss::SwitchSelectiveProduct:
    case lss::SwitchSelectiveRevision:
    case lss::SwitchSelectiveSerial: {
        // The four fields in order; all matching switches this slave to configuration (§6.3.2).
        const int field = cs - lss::SwitchSelectiveVendor;
        if (field == 0) selectiveStep_ = 0;
        if (field == selectiveStep_ && identity(field) == v) ++selectiveStep_;
        else selectiveStep_ = 0;
        if (selectiveStep_ == 4) {
            selectiveStep_ = 0;
            configuration_ = true;
            reply(lss::SwitchSelectiveResponse);
        }
        return;
    }
    case lss::ConfigureNodeId: {
        if (!configuration_) return;
        const uint8_t id = d[1];
        if (dev_.lssFaults_.configureNodeIdError) {
            reply(lss::ConfigureNodeId, dev_.lssFaults_.configureNodeIdError);
        } else if ((id >= 1 && id <= 127) || id == 0xFF) {
            dev_.pendingNodeId_ = id;  // active after NMT Reset Communication (§6.4.2)
            dev_.pendingFromLss_ = true;
            reply(lss::ConfigureNodeId, 0);
        } else {
            reply(lss::ConfigureNodeId, 1);  // node-ID out of range
        }
        return;
    }
    case lss::ConfigureBitTiming: {
        if (!configuration_) return;
        const int rate = d[1] == 0 ? lssBitRate(d[2]) : -1;
        if (rate > 0) {
            dev_.pendingBitRate_ = static_cast<uint32_t>(rate);
            reply(lss::ConfigureBitTiming, 0);
        } else {
            reply(lss::ConfigureBitTiming, 1);  // bit timing not supported
        }
        return;
    }
    case lss::ActivateBitTiming:
        // The sim bus has no bit timing: the configured rate becomes the active one.
        if (configuration_) dev_.bitRate_ = dev_.pendingBitRate_;
        return;
    case lss::StoreConfiguration:
        if (!configuration_) return;
        if (dev_.lssFaults_.storeError) {
            reply(lss::StoreConfiguration, dev_.lssFaults_.storeError);
            return;
        }
        dev_.storedNodeId_ = dev_.pendingNodeId_;
        dev_.storedBitRate_ = dev_.pendingBitRate_;
        reply(lss::StoreConfiguration, 0);
        return;
    case lss::InquireVendor:
    case lss::InquireProduct:
    case lss::InquireRevision:
    case lss::InquireSerial:
        if (configuration_) reply(cs, 0, 0, identity(cs - lss::InquireVendor), true);
        return;
    case lss::InquireNodeId:
        if (configuration_) reply(cs, dev_.nodeId());
        return;
    case lss::IdentifyVendor: identifyStep_ = identity(0) == v ? 1 : 0; return;
    case lss::IdentifyProduct: identifyStep_ = identifyStep_ == 1 && identity(1) == v ? 2 : 0; return;
    case lss::IdentifyRevisionLow:
        revLow_ = v;
        identifyStep_ = identifyStep_ == 2 && identity(2) >= v ? 3 : 0;
        return;
    case lss::IdentifyRevisionHigh: identifyStep_ = identifyStep_ == 3 && identity(2) <= v ? 4 : 0; return;
    case lss::IdentifySerialLow:
        serialLow_ = v;
        identifyStep_ = identifyStep_ == 4 && identity(3) >= v ? 5 : 0;
        return;
    case lss::IdentifySerialHigh:
        // Every slave inside the ranges answers "identify slave" (§6.5.2).
        if (identifyStep_ == 5 && identity(3) <= v) reply(lss::IdentifySlaveResponse);
        identifyStep_ = 0;
        return;
    case lss::IdentifyNonConfigured:
        if (dev_.nodeId() == 0xFF) reply(lss::IdentifyNonConfiguredResponse);
        return;
    case lss::Fastscan: {
        // LSS Fastscan (CiA 305 §6.7): unconfigured slaves in waiting state only. BitChecked 80h
        // resets the scan; otherwise answer when IDNumber matches the field LSSSub in bits
        // BitChecked..31; a full match (BitChecked 0) moves on to LSSNext, and after the serial
        // number the slave enters configuration state.
        if (configuration_ || dev_.nodeId() != 0xFF || f.len < 8) return;
        const uint8_t bitChecked = d[5], lssSub = d[6], lssNext = d[7];
        if (bitChecked == 0x80) {
            fastscanSub_ = 0;
            reply(lss::IdentifySlaveResponse);
            return;
        }
        if (bitChecked > 31 || lssSub > 3 || lssSub != fastscanSub_) return;
        const uint32_t mask = 0xFFFFFFFFu << bitChecked;
        if ((identity(lssSub) ^ v) & mask) return;
        if (bitChecked == 0) {
            if (lssSub == 3) {
                configuration_ = true;
                fastscanSub_ = -1;
            } else {
                fastscanSub_ = lssNext;
            }
        }
        reply(lss::IdentifySlaveResponse);
        return;
    }
    default: return;
    }
}

}  // namespace coscope::sim
