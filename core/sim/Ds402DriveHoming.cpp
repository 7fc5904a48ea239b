// SPDX-License-Identifier: GPL-3.0-or-later
// Homing mode (6060h = 6) of the virtual CiA 402 drive: the method 6098h from the drive's own
// table (canopen::homing), run on the modelled machine (HomingMachine), with the vendor's
// refusals, time limit and hard-stop homing.
#include "core/sim/Ds402Drive.h"

#include "core/canopen/HomingMethods.h"
#include "core/sim/VirtualDevice.h"

#include <algorithm>
#include <cmath>

namespace coscope::sim {

namespace {
// When 6099h/609Ah are 0 (the generic drive's defaults): the simulator's own choice, in
// revolutions per second (squared).
constexpr double kFastRevPerS = 0.5, kSlowRevPerS = 0.1, kAccelRevPerS2 = 5.0;
constexpr double kStallSeconds = 0.2;        // hard stop: torque at the limit this long = home
constexpr double kDefaultTorqueLimit = 100;  // 0.1 % units: 10 % when H05-58 is 0
}  // namespace

double Ds402Drive::homingSpeed(uint8_t sub) const {
    const double raw = std::abs(double(readInt(0x6099, sub, 0)));
    const double rev = countsPerRevolution();
    if (raw <= 0) return (sub == 1 ? kFastRevPerS : kSlowRevPerS) * rev;
    // Delta: 0.1 rpm when P1-01 = 0Ch (extract-delta §3.3); others: position units/s.
    if (dev_.personality().homingSpeedInDeciRpm) return raw * 0.1 / 60.0 * rev;
    return raw;
}

void Ds402Drive::startHoming() {
    const Personality& p = dev_.personality();
    const auto& table = canopen::homing::drive(p.dictionaryName);
    const int number = int(readInt(0x6098));
    homingDone_ = homingError_ = homeFound_ = false;
    stopMotion();
    const canopen::homing::Method* method = table.method(number);
    if (!method) {
        if (table.refusal == canopen::homing::Refusal::AlarmAtStart && !table.alarm.isEmpty()) {
            // AIMOTOR: Er.668 homing method mismatch (vendor 0668h, EMCY FF00h, extract-aimotor §6b).
            dev_.injectDriveFault(table.alarm, axis_);
            return;
        }
        // No method (0) or one refused before: homing error at once, nothing moves.
        homingError_ = true;
        targetReached_ = true;
        return;
    }
    travelLow_ = travelHigh_ = machinePosition();
    homingLegs_ = homingPath(*method, machinePosition(), HomingMachine::forRevolution(countsPerRevolution()));
    homingLeg_ = 0;
    homingElapsed_ = stallTime_ = 0;
    homingActive_ = true;
    targetReached_ = false;
    if (homingLegs_.empty()) finishHoming();  // current position (35, 37): no movement
}

void Ds402Drive::interruptHoming() {
    homingActive_ = false;
    homingLegs_.clear();
    stalled_ = false;
}

void Ds402Drive::finishHoming() {
    // At home the position actual value becomes the home offset 607Ch (CiA 402-2 §13.2;
    // AIMOTOR: "the current position is cleared to zero", its 607Ch defaults to 0).
    const double machine = machinePosition();
    position_ = double(readInt(0x607C));
    machineOffset_ = machine - position_;
    demand_ = ppTarget_ = position_;
    velocity_ = 0;
    homingActive_ = stalled_ = false;
    homingLegs_.clear();
    homingDone_ = true;
    homeFound_ = dev_.personality().homeFoundBit15;
    targetReached_ = true;
}

void Ds402Drive::stepHoming(double dt) {
    const Personality& p = dev_.personality();
    travelLow_ = std::min(travelLow_, machinePosition());
    travelHigh_ = std::max(travelHigh_, machinePosition());
    homingElapsed_ += dt;
    if (p.homingTimeLimitIndex) {
        // AIMOTOR H05-35: home not found in time -> ER.601 homing timeout (extract-aimotor §4.7).
        const auto limitMs =
            dev_.value(p.homingTimeLimitIndex, p.homingTimeLimitSub).value_or(od::Value{}).toInt64().value_or(0);
        if (limitMs > 0 && homingElapsed_ * 1000.0 > double(limitMs)) {
            interruptHoming();
            homingError_ = true;
            dev_.injectDriveFault(QStringLiteral("Er.601"), axis_);
            return;
        }
    }
    if (homingLeg_ >= homingLegs_.size()) return finishHoming();
    const HomingLeg& leg = homingLegs_[homingLeg_];
    const double speed = homingSpeed(leg.slow ? 2 : 1);
    const double accel = ramp(0x609A, kAccelRevPerS2 * countsPerRevolution());
    const double remaining = leg.to - machinePosition();
    if (leg.endStop) {
        // Hard-stop homing: creep at the slow speed until the end stop holds the motor; the torque
        // rises to the homing torque limit and, held there, marks home (AIMOTOR 37/38, H05-58).
        if (std::abs(remaining) > 0.5 && !stalled_) {
            stepToward(dt, std::copysign(speed, remaining), accel, accel);
            position_ += std::abs(velocity_ * dt) >= std::abs(remaining) ? remaining : velocity_ * dt;
            return;
        }
        stalled_ = true;
        velocity_ = 0;
        double limit = kDefaultTorqueLimit;
        if (p.homingTorqueLimitIndex)
            if (const auto v = dev_.value(p.homingTorqueLimitIndex, p.homingTorqueLimitSub)
                                   .value_or(od::Value{})
                                   .toInt64()
                                   .value_or(0);
                v > 0)
                limit = double(v);
        torque_ = std::copysign(limit, leg.to);
        stallTime_ += dt;
        if (stallTime_ >= kStallSeconds) ++homingLeg_;
        if (homingLeg_ >= homingLegs_.size()) finishHoming();
        return;
    }
    // Trapezoid onto the end of the stretch, v = sqrt(2 a s), as in profile position.
    const double vStop = std::sqrt(2.0 * accel * std::abs(remaining));
    stepToward(dt, std::copysign(std::min(speed, vStop), remaining), accel, accel);
    if (std::abs(remaining) <= std::abs(velocity_) * dt || std::abs(remaining) < 0.5) {
        position_ += remaining;
        velocity_ = 0;
        if (++homingLeg_ >= homingLegs_.size()) finishHoming();
    } else {
        position_ += velocity_ * dt;
    }
}

}  // namespace coscope::sim
