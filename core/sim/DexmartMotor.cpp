// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/DexmartMotor.h"

#include "core/sim/VirtualDevice.h"

#include <cmath>

namespace coscope::sim {

namespace {
constexpr double kAccelRpmPerS = 3000.0;  // plausible ramp: 0 to 3000 rpm in 1 s
constexpr double kHallPerRev = 24.0;      // hall edges per revolution of the model motor
}  // namespace

DexmartMotor::DexmartMotor(VirtualDevice& device, int motor) : dev_(device), motor_(motor) {}

void DexmartMotor::reset() {
    speed_ = targetSpeed_ = 0;
    moving_ = false;
    alarm_ = 0;
    publish();
}

void DexmartMotor::raiseAlarm(uint8_t code) {
    alarm_ = code;
    targetSpeed_ = 0;
    moving_ = false;
    publish();
}

void DexmartMotor::onWrite(uint16_t index, uint8_t sub) {
    const uint16_t multi = motor_ == 0 ? 0x3051 : 0x3052;
    const uint16_t lite = motor_ == 0 ? 0x305B : 0x305C;
    auto read = [&](uint16_t i, uint8_t s) {
        return double(dev_.value(i, s).value_or(od::Value{}).toInt64().value_or(0));
    };
    if (index == multi && sub == 1) {
        const int cmd = int(read(multi, 1)) & 0xFF;
        if (cmd == 0x0A) {  // continuous run, Data2 = rpm
            targetSpeed_ = read(multi, 3);
            moving_ = false;
        } else if (cmd == 0x0F) {  // relative move, Data1 = revolutions
            moveTarget_ = revs_ + read(multi, 2);
            moving_ = true;
            targetSpeed_ = moveTarget_ >= revs_ ? 3000 : -3000;
        } else if (cmd == 0x00) {
            targetSpeed_ = 0;
            moving_ = false;
        }
    } else if (index == lite && sub == 1) {
        const int cmd = int(read(lite, 1)) & 0xFF;
        if (cmd == 0x01) targetSpeed_ = read(lite, 2);  // continuous run, Data = rpm
        else if (cmd == 0x00) targetSpeed_ = 0;
        moving_ = false;
    }
    if (alarm_) targetSpeed_ = 0;
}

void DexmartMotor::step(int64_t dtNs) {
    const double dt = double(dtNs) / 1e9;
    if (moving_) {
        const double remaining = moveTarget_ - revs_;
        // Brake so as to stop on the target: v^2 = 2 a s.
        const double vStop = std::sqrt(2.0 * kAccelRpmPerS / 60.0 * std::abs(remaining)) * 60.0;
        targetSpeed_ = std::copysign(std::min(3000.0, vStop), remaining);
        if (std::abs(remaining) < 1e-3) {
            revs_ = moveTarget_;
            speed_ = targetSpeed_ = 0;
            moving_ = false;
        }
    }
    const double dv = kAccelRpmPerS * dt;
    if (speed_ < targetSpeed_) speed_ = std::min(targetSpeed_, speed_ + dv);
    else if (speed_ > targetSpeed_) speed_ = std::max(targetSpeed_, speed_ - dv);
    revs_ += speed_ / 60.0 * dt;
    if (--publishCountdown_ <= 0) {
        publishCountdown_ = 10;  // monitor values refresh every 10 ms
        publish();
    }
}

void DexmartMotor::publish() {
    const uint16_t m = monitor();
    auto put = [&](uint8_t sub, int64_t v) {
        if (auto* slot = dev_.valueSlot(m, sub)) {
            const auto* e = dev_.entry(m, sub);
            *slot = od::isSigned(e->dataType) ? od::Value::signedInt(v) : od::Value::unsignedInt(uint64_t(v) & 0xFFFF);
        }
    };
    put(0x01,
        alarm_ ? 2 : (std::abs(speed_) > 0.5 ? 1 : 0));  // motor state: 0 idle, 1 running, 2 alarm (simulator's coding)
    put(0x02, alarm_);
    put(0x05, std::lround(speed_));
    put(0x0A, std::lround(std::abs(speed_) / 3000.0 * 1500.0));  // shunt current, model: mA-ish
    put(0x14, std::lround(revs_ * kHallPerRev) & 0xFFFF);
}

}  // namespace coscope::sim
