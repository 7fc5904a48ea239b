// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/DemoMaster.h"

#include "core/od/ObjectDictionary.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"

#include <iterator>

namespace coscope::sim {

namespace {
constexpr int64_t kMs = 1'000'000;
constexpr int64_t kStartAfterNs = 500 * kMs;  // after the boot-ups
constexpr int64_t kSyncPeriodNs = 10 * kMs;
constexpr int64_t kTargetPeriodNs = 2000 * kMs;
// Target velocities in pulse/s (1000 pulses = 1 rev: 3000 pulse/s = 180 rpm), as the GUI's demo.
constexpr int64_t kProfile[] = {3000, 6000, 4000, -2000, -5000, 0};

CanFrame frame(uint32_t id, const QByteArray& data) {
    CanFrame f;
    f.id = id;
    f.len = static_cast<uint8_t>(data.size());
    for (int i = 0; i < data.size(); ++i) f.data[size_t(i)] = static_cast<uint8_t>(data[i]);
    return f;
}
}  // namespace

DemoMaster::DemoMaster(const SimNetwork& network) {
    for (const auto& n : network.nodes()) {
        const auto* d = dynamic_cast<const VirtualDevice*>(n.get());
        if (!d) continue;
        // 1017h is UNSIGNED16 in CiA 301 (7.5.2.24); some dictionaries declare it UNSIGNED32
        // (AIMOTOR): written in the size the device declares, as a configuration tool does.
        const od::SubObject* hb = d->dictionary().entry(0x1017, 0);
        const int bytes =
            hb && (hb->dataType == od::DataType::Unsigned32 || hb->dataType == od::DataType::Integer32) ? 4 : 2;
        sdoWrite(d->nodeId(), 0x1017, 0, 500, bytes);
        if (d->dictionaryName() == u"aimotor" && !aimotor_) aimotor_ = d->nodeId();
    }
    steps_.push_back(
        {frame(0x000, QByteArray::fromHex("0100")), 20 * kMs});  // NMT Start, all nodes (CiA 301 7.2.8.3.1)
    if (aimotor_) {
        sdoWrite(aimotor_, 0x2002, 0x01, 8, 2);      // H02-00 = 8: CANopen control (extract-aimotor)
        sdoWrite(aimotor_, 0x6060, 0, 3, 1);         // modes of operation: profile velocity
        sdoWrite(aimotor_, 0x6083, 0, 20000, 4);     // profile acceleration, pulse/s²
        sdoWrite(aimotor_, 0x6084, 0, 20000, 4);     // profile deceleration
        sdoWrite(aimotor_, 0x60FF, 0, 0, 4);         // target velocity 0 until enabled
        sdoWrite(aimotor_, 0x6040, 0, 0x06, 2, 20);  // shutdown -> READY TO SWITCH ON
        sdoWrite(aimotor_, 0x6040, 0, 0x07, 2, 20);  // switch on -> SWITCHED ON
        sdoWrite(aimotor_, 0x6040, 0, 0x0F, 2, 20);  // enable operation -> OPERATION ENABLED
    }
}

// Expedited SDO download (CiA 301 7.2.4.3.3): command 23h/27h/2Bh/2Fh for 4/3/2/1 bytes.
void DemoMaster::sdoWrite(uint8_t node, uint16_t index, uint8_t sub, int64_t value, int bytes, int64_t pauseMs) {
    QByteArray d(8, '\0');
    d[0] = static_cast<char>(0x23 | ((4 - bytes) << 2));
    d[1] = static_cast<char>(index & 0xFF);
    d[2] = static_cast<char>(index >> 8);
    d[3] = static_cast<char>(sub);
    for (int i = 0; i < bytes; ++i) d[4 + i] = static_cast<char>((value >> (8 * i)) & 0xFF);
    steps_.push_back({frame(0x600u + node, d), pauseMs * kMs});
}

void DemoMaster::powerOn(int64_t nowNs) {
    if (nextStepNs_ < 0) nextStepNs_ = nowNs + kStartAfterNs;
}

void DemoMaster::tick(int64_t nowNs) {
    if (nextStepNs_ < 0) return;
    if (!steps_.empty() && nowNs >= nextStepNs_) {
        const Step s = steps_.front();
        steps_.pop_front();
        transmit(s.frame);
        nextStepNs_ = nowNs + s.pauseNs;
        if (steps_.empty()) {
            nextSyncNs_ = nowNs + kSyncPeriodNs;
            nextTargetNs_ = nowNs;
        }
    }
    if (nextSyncNs_ >= 0 && nowNs >= nextSyncNs_) {
        transmit(frame(0x080, {}));  // SYNC without counter (CiA 301 7.2.5)
        nextSyncNs_ += kSyncPeriodNs;
        if (nextSyncNs_ <= nowNs) nextSyncNs_ = nowNs + kSyncPeriodNs;  // a late tick: no burst
    }
    if (aimotor_ && nextTargetNs_ >= 0 && nowNs >= nextTargetNs_) {
        sdoWrite(aimotor_, 0x60FF, 0, kProfile[target_++ % std::size(kProfile)], 4);
        const Step s = steps_.front();
        steps_.pop_front();
        transmit(s.frame);
        nextTargetNs_ = nowNs + kTargetPeriodNs;
    }
}

}  // namespace coscope::sim
