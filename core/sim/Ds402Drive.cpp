// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/Ds402Drive.h"

#include "core/canopen/HomingMethods.h"
#include "core/canopen/SdoAbort.h"
#include "core/sim/VirtualDevice.h"

#include <algorithm>
#include <cmath>

namespace coscope::sim {

using canopen::ds402::State;
namespace sw = canopen::ds402::sw;

namespace {
// Modes of operation (CiA 402-2 §6.3.1, 6060h).
constexpr int8_t kPP = 1, kPV = 3, kPT = 4, kHM = 6, kIP = 7, kCSP = 8, kCSV = 9, kCST = 10;
constexpr double kDefaultVelocity = 20000.0;    // units/s when 6081h/6099h are 0
constexpr double kDefaultWindow = 10.0;         // units when 6067h is 0
constexpr double kLagPerSecond = 400.0;         // position loop bandwidth of the model (1/s)
constexpr int kFaultReactionMs = 20;            // FAULT REACTION ACTIVE lasts this long
constexpr uint16_t kSetPointAck = 1u << 12;     // PP: set-point acknowledge; HM: homing attained; CSx: follows command
constexpr uint16_t kFollowingError = 1u << 13;  // PP/CSP: following error; HM: homing error
}  // namespace

Ds402Drive::Ds402Drive(VirtualDevice& device, int axis) : dev_(device), axis_(axis) {}

int64_t Ds402Drive::readInt(uint16_t base, uint8_t sub, int64_t fallback) const {
    const od::Value* v = dev_.valueSlot(idx(base), sub);
    if (!v) return fallback;
    return v->toInt64().value_or(fallback);
}

void Ds402Drive::writeInt(uint16_t base, uint8_t sub, int64_t v) {
    od::Value* slot = dev_.valueSlot(idx(base), sub);
    if (!slot) return;
    const od::SubObject* e = dev_.entry(idx(base), sub);
    if (od::isSigned(e->dataType)) {
        const int bits = od::bitSize(e->dataType);
        const int64_t lo = bits >= 64 ? INT64_MIN : -(int64_t(1) << (bits - 1));
        const int64_t hi = bits >= 64 ? INT64_MAX : (int64_t(1) << (bits - 1)) - 1;
        *slot = od::Value::signedInt(std::clamp(v, lo, hi));
    } else {
        const int bits = od::bitSize(e->dataType);
        const uint64_t mask = bits >= 64 ? ~uint64_t(0) : (uint64_t(1) << bits) - 1;
        *slot = od::Value::unsignedInt(uint64_t(v) & mask);
    }
}

bool Ds402Drive::canopenControlActive() const {
    const Personality& p = dev_.personality();
    if (!p.controlModeIndex) return true;
    return dev_.value(p.controlModeIndex, p.controlModeSub).value_or(od::Value{}).toInt64().value_or(0) ==
           p.controlModeValue;
}

void Ds402Drive::reset() {
    if (!faulted()) setState(State::SwitchOnDisabled);
    lastControlword_ = 0;
    velocity_ = torque_ = 0;
    demand_ = position_;
    stopMotion();
    homingDone_ = homingError_ = false;
    modeDisplay_ = static_cast<int8_t>(readInt(0x6060, 0, 0));
    publish();
}

void Ds402Drive::setState(State s) {
    state_ = s;
    if (s == State::OperationEnabled) {
        demand_ = ppTarget_ = position_;
        targetReached_ = true;
    } else {
        stopMotion();
        homeFound_ = false;  // AIMOTOR: bit 15 cleared by disabling (extract-aimotor §4.2)
    }
}

void Ds402Drive::stopMotion() {
    // A move or homing run ends with the state or mode it ran in; nothing resumes later.
    ppMoving_ = ppBuffered_ = ppAck_ = false;
    homingActive_ = false;
    homingLegs_.clear();
    stalled_ = false;
}

double Ds402Drive::countsPerRevolution() const {
    const Personality& p = dev_.personality();
    double rev = p.countsPerRevolution;
    if (p.positionFactorScalesRevolution) {
        // Delta: PUU per revolution = 1280000 x 6093h:02 / 6093h:01 (extract-delta §4.7).
        const double num = double(readInt(0x6093, 1, 1)), feed = double(readInt(0x6093, 2, 1));
        if (num > 0 && feed > 0) rev = rev * feed / num;
    }
    return rev;
}

double Ds402Drive::ramp(uint16_t base, double fallback) const {
    const double raw = double(readInt(base, 0, 0));
    if (raw <= 0) return fallback;
    // Delta: time in ms from 0 to 3000 rpm (50 rev/s); others: units/s².
    if (dev_.personality().rampsAsTimeTo3000Rpm) return 50.0 * countsPerRevolution() / (raw / 1000.0);
    return raw;
}

uint32_t Ds402Drive::checkWrite(uint16_t base, uint8_t sub, int64_t value) const {
    if (sub != 0) return 0;
    if (base == 0x6060) {
        // Modes of operation: only the modes the drive lists in 6502h (CiA 402-2 §6.4.3).
        const auto modes = uint64_t(readInt(0x6502, 0, 0));
        if (value != 0 && (value < 1 || value > 10 || !(modes & (uint64_t(1) << (value - 1)))))
            return canopen::sdoabort::InvalidValue;
    }
    if (base == 0x6098) {
        const auto& table = canopen::homing::drive(dev_.personality().dictionaryName);
        // AIMOTOR: "change 6098 only while disabled" (extract-aimotor §4.7).
        if (table.changeOnlyWhileDisabled && state_ == State::OperationEnabled && value != readInt(0x6098))
            return canopen::sdoabort::DeviceState;
        // A method the drive lacks, where its refusal is on the write (Delta, generic).
        if (table.refusal == canopen::homing::Refusal::SdoAbort && value != 0 && !table.supports(int(value)))
            return table.abortCode;
    }
    return 0;
}

void Ds402Drive::raiseFault(uint16_t errorCode) {
    pendingFault_ = errorCode;
    if (state_ == State::Fault || state_ == State::FaultReactionActive) return;
    state_ = State::FaultReactionActive;
    faultReactionMs_ = kFaultReactionMs;
    publish();
}

void Ds402Drive::onWrite(uint16_t index, uint8_t sub) {
    (void)sub;
    if (index == 0x6040) handleControlword(static_cast<uint16_t>(readInt(0x6040)));
    else if (index == 0x6060) {
        const auto mode = static_cast<int8_t>(readInt(0x6060));
        if (mode != modeDisplay_) stopMotion();
        modeDisplay_ = mode;
    }
    publish();
}

void Ds402Drive::handleControlword(uint16_t cw) {
    const uint16_t prev = lastControlword_;
    lastControlword_ = cw;
    // Fault reset on the rising edge of bit 7 (CiA 402-2 §6.2.1, transition 15).
    if (state_ == State::Fault) {
        if ((cw & 0x80) && !(prev & 0x80)) {
            pendingFault_ = 0;
            setState(State::SwitchOnDisabled);
            dev_.faultCleared(axis_);
        }
        return;
    }
    if (state_ == State::FaultReactionActive || state_ == State::NotReadyToSwitchOn) return;
    // Commands by controlword bits 0-3, 7 (CiA 402-2 Table 27).
    const bool disableVoltage = (cw & 0x82) == 0x00;
    const bool quickStop = (cw & 0x86) == 0x02;
    const bool shutdown = (cw & 0x87) == 0x06;
    const bool switchOn = (cw & 0x8F) == 0x07;
    const bool enableOp = (cw & 0x8F) == 0x0F;
    if ((state_ == State::ReadyToSwitchOn || state_ == State::SwitchedOn) && (switchOn || enableOp)) {
        if (!enableFaults_.alarmOnSwitchOn.isEmpty()) {
            // Injected: the drive trips while switching on (e.g. Delta AL013, AIMOTOR Er.620).
            if (enableFaults_.alarmOnSwitchOn == u"typical" ||
                !dev_.injectDriveFault(enableFaults_.alarmOnSwitchOn, axis_))
                dev_.injectDriveFault(DriveFault{0, 0, axis_});
            return;
        }
        if (enableFaults_.mainPowerOff && state_ == State::ReadyToSwitchOn)
            return;  // no DC bus: transition 3 not possible
    }
    switch (state_) {
    case State::SwitchOnDisabled:
        if (shutdown) setState(State::ReadyToSwitchOn);  // 2
        break;
    case State::ReadyToSwitchOn:
        if (switchOn) setState(State::SwitchedOn);                                // 3
        else if (enableOp) setState(State::OperationEnabled);                     // 3 + 4
        else if (disableVoltage || quickStop) setState(State::SwitchOnDisabled);  // 7
        break;
    case State::SwitchedOn:
        if (enableOp) setState(State::OperationEnabled);                          // 4
        else if (shutdown) setState(State::ReadyToSwitchOn);                      // 6
        else if (disableVoltage || quickStop) setState(State::SwitchOnDisabled);  // 10
        break;
    case State::OperationEnabled:
        if (switchOn) setState(State::SwitchedOn);                   // 5
        else if (shutdown) setState(State::ReadyToSwitchOn);         // 8
        else if (disableVoltage) setState(State::SwitchOnDisabled);  // 9
        else if (quickStop) {                                        // 11
            state_ = State::QuickStopActive;
            stopMotion();
        }
        break;
    case State::QuickStopActive:
        if (enableOp) state_ = State::OperationEnabled;              // 16
        else if (disableVoltage) setState(State::SwitchOnDisabled);  // 12
        break;
    default: break;
    }
    if (state_ != State::OperationEnabled) return;
    const bool rise = (cw & 0x10) && !(prev & 0x10);
    if (modeDisplay_ == kPP) handleSetPoint(cw, rise);
    if (modeDisplay_ == kHM) {
        // Homing operation start: 0 -> 1 starts, 1 -> 0 interrupts (CiA 402-2 §13.1; AIMOTOR
        // "1F -> 0F aborts homing", extract-aimotor §4.6 C).
        if (rise) startHoming();
        else if (!(cw & 0x10) && homingActive_) interruptHoming();
    }
}

void Ds402Drive::handleSetPoint(uint16_t cw, bool rise) {
    // Set-point handshake (CiA 402-2 §12.2): bit 4 rising offers 607Ah, the drive answers with
    // bit 12; bit 4 low lets bit 12 fall, unless a set-point still waits in the buffer.
    if (!(cw & 0x10)) {
        ppAck_ = ppBuffered_;
        return;
    }
    if (!rise) return;
    const double target = double(readInt(0x607A));
    const bool relative = cw & 0x40, immediate = cw & 0x20;
    if (ppMoving_ && !immediate) {
        if (ppBuffered_) return;  // buffer full: not acknowledged, the master must wait
        ppNext_ = relative ? ppTarget_ + target : target;
        ppBuffered_ = ppAck_ = true;
        return;
    }
    ppTarget_ = relative ? ppTarget_ + target : target;
    ppBuffered_ = false;
    ppMoving_ = ppAck_ = true;
    targetReached_ = false;
}

void Ds402Drive::stepVelocity(double dt, double target) {
    const double accel = std::max(double(readInt(0x6083, 0, 0)), std::abs(target) * 5.0 + 1000.0);
    const double decel = std::max(double(readInt(0x6084, 0, 0)), std::abs(velocity_) * 5.0 + 1000.0);
    stepToward(dt, target, accel, decel);
}

void Ds402Drive::stepToward(double dt, double target, double accel, double decel) {
    const double rate = std::abs(target) > std::abs(velocity_) && target * velocity_ >= 0 ? accel : decel;
    const double dv = rate * dt;
    velocity_ = velocity_ < target ? std::min(target, velocity_ + dv) : std::max(target, velocity_ - dv);
}

void Ds402Drive::stepProfilePosition(double dt) {
    double vmax = std::abs(double(readInt(0x6081, 0, 0)));
    if (vmax <= 0) vmax = kDefaultVelocity;
    const double accel = ramp(0x6083, vmax * 5.0), decel = ramp(0x6084, vmax * 5.0);
    const double remaining = ppTarget_ - position_;
    // Trapezoid: the speed that still stops on the target, v = sqrt(2 a s).
    const double vStop = std::sqrt(2.0 * decel * std::abs(remaining));
    stepToward(dt, std::copysign(std::min(vmax, vStop), remaining), accel, decel);
    if (std::abs(remaining) <= std::abs(velocity_) * dt || std::abs(remaining) < 0.5) {
        position_ = ppTarget_;
        velocity_ = 0;
        ppMoving_ = false;
        if (ppBuffered_) {
            // Single set-point: the buffered one starts when the last is reached (§12.2).
            ppTarget_ = ppNext_;
            ppBuffered_ = false;
            ppMoving_ = true;
            ppAck_ = lastControlword_ & 0x10;
        }
    } else {
        position_ += velocity_ * dt;
    }
}

void Ds402Drive::step(int64_t dtNs) {
    const double dt = double(dtNs) / 1e9;
    const double before = velocity_;
    if (state_ == State::FaultReactionActive) {
        // Fault reaction: brake, then FAULT (CiA 402-2 §6.2, transition 14).
        stepVelocity(dt, 0);
        position_ += velocity_ * dt;
        if (--faultReactionMs_ <= 0) {
            state_ = State::Fault;
            velocity_ = 0;
        }
    } else if (state_ == State::QuickStopActive) {
        const double qs = std::max(double(readInt(0x6085, 0, 0)), std::abs(velocity_) * 10.0 + 1000.0);
        const double dv = qs * dt;
        velocity_ = velocity_ > 0 ? std::max(0.0, velocity_ - dv) : std::min(0.0, velocity_ + dv);
        position_ += velocity_ * dt;
        // Quick stop option code 605Ah 0-4: after stopping go to SWITCH ON DISABLED.
        if (velocity_ == 0 && readInt(0x605A, 0, 2) <= 4) setState(State::SwitchOnDisabled);
    } else if (state_ != State::OperationEnabled) {
        velocity_ = 0;  // no torque: the model stops at once
        torque_ = 0;
        demand_ = position_;
    } else {
        const bool halt = lastControlword_ & 0x100;
        switch (modeDisplay_) {
        case kPP:
            // Halt (bit 8) stops on the deceleration ramp; the move goes on when it is released (§12.2).
            if (halt) {
                stepToward(dt, 0, 0, ramp(0x6084, std::abs(velocity_) * 5.0 + 1000.0));
                position_ += velocity_ * dt;
            } else if (ppMoving_) {
                stepProfilePosition(dt);
            } else {
                velocity_ = 0;
            }
            demand_ = ppMoving_ ? position_ + velocity_ / kLagPerSecond : ppTarget_;
            targetReached_ = halt ? std::abs(velocity_) < 1.0
                                  : !ppMoving_ && std::abs(ppTarget_ - position_) <=
                                                      std::max(double(readInt(0x6067, 0, 0)), kDefaultWindow);
            break;
        case kPV: {
            const double target = halt ? 0.0 : double(readInt(0x60FF));
            stepVelocity(dt, target);
            position_ += velocity_ * dt;
            demand_ = position_;
            targetReached_ = std::abs(velocity_ - target) <= std::max(double(readInt(0x606D, 0, 0)), 1.0);
            break;
        }
        case kPT: {
            // Torque drives a damped inertia: v' = k T - d v.
            const double target = halt ? 0.0 : double(readInt(0x6071));
            const double slope = std::max(double(readInt(0x6087, 0, 0)), 1000.0);
            torque_ =
                torque_ < target ? std::min(target, torque_ + slope * dt) : std::max(target, torque_ - slope * dt);
            velocity_ += (torque_ * 100.0 - velocity_ * 2.0) * dt;
            position_ += velocity_ * dt;
            demand_ = position_;
            targetReached_ = std::abs(torque_ - target) < 1.0;
            break;
        }
        case kHM:
            if (homingActive_ && halt && !dev_.personality().haltIgnoredInHoming) interruptHoming();
            if (homingActive_) {
                stepHoming(dt);
            } else {
                // Interrupted or ended: brake on the homing acceleration.
                stepToward(dt, 0, 0, ramp(0x609A, std::abs(velocity_) * 5.0 + 1000.0));
                position_ += velocity_ * dt;
                targetReached_ = std::abs(velocity_) < 1.0;
            }
            demand_ = position_;
            break;
        case kIP:
        case kCSP: {
            // Cyclic/interpolated position: follow the set-point with the model's lag.
            demand_ = double(modeDisplay_ == kIP ? readInt(0x60C1, 1) : readInt(0x607A));
            const double v = (demand_ - position_) * kLagPerSecond;
            velocity_ = v;
            position_ += std::abs(v * dt) >= std::abs(demand_ - position_) ? demand_ - position_ : v * dt;
            targetReached_ = true;
            break;
        }
        case kCSV: {
            const double target = double(readInt(0x60FF));
            velocity_ += (target - velocity_) * std::min(1.0, kLagPerSecond * dt);
            position_ += velocity_ * dt;
            demand_ = position_;
            break;
        }
        case kCST:
            torque_ = double(readInt(0x6071));
            velocity_ += (torque_ * 100.0 - velocity_ * 2.0) * dt;
            position_ += velocity_ * dt;
            demand_ = position_;
            break;
        default:
            velocity_ = 0;
            demand_ = position_;
            break;
        }
        if (modeDisplay_ != kPT && modeDisplay_ != kCST && !stalled_) {
            // Torque of the model: acceleration term plus a little friction (per mille of rated).
            const double accel = dt > 0 ? (velocity_ - before) / dt : 0;
            torque_ = std::clamp(accel / 2000.0 + (velocity_ > 1    ? 20.0
                                                   : velocity_ < -1 ? -20.0
                                                                    : 0.0),
                                 -3000.0, 3000.0);
        }
    }
    // Following error (CiA 402-2 §12.4: 6065h window, 60F4h actual following error).
    const double ferr = demand_ - position_;
    const int64_t window = readInt(0x6065, 0, -1);
    followingError_ = (modeDisplay_ == kPP || modeDisplay_ == kCSP || modeDisplay_ == kIP) &&
                      state_ == State::OperationEnabled && window >= 0 && uint32_t(window) != 0xFFFFFFFFu &&
                      std::abs(ferr) > double(window);
    publish();
}

void Ds402Drive::publish() {
    uint16_t s = 0;
    switch (state_) {
    case State::NotReadyToSwitchOn: s = 0x0000; break;
    case State::SwitchOnDisabled: s = sw::SwitchOnDisabled; break;
    case State::ReadyToSwitchOn: s = sw::QuickStop | sw::ReadyToSwitchOn; break;
    case State::SwitchedOn: s = sw::QuickStop | sw::ReadyToSwitchOn | sw::SwitchedOn; break;
    case State::OperationEnabled:
        s = sw::QuickStop | sw::ReadyToSwitchOn | sw::SwitchedOn | sw::OperationEnabled;
        break;
    case State::QuickStopActive: s = sw::ReadyToSwitchOn | sw::SwitchedOn | sw::OperationEnabled; break;
    case State::FaultReactionActive: s = sw::ReadyToSwitchOn | sw::SwitchedOn | sw::OperationEnabled | sw::Fault; break;
    case State::Fault: s = sw::Fault; break;
    default: break;
    }
    // Voltage enabled while mains are on (the model always has them); remote: CANopen control.
    if (state_ != State::NotReadyToSwitchOn && !enableFaults_.mainPowerOff) s |= sw::VoltageEnabled;
    if (canopenControlActive()) s |= sw::Remote;
    if (state_ == State::OperationEnabled) {
        if (targetReached_) s |= sw::TargetReached;
        switch (modeDisplay_) {
        case kPP:
            if (ppAck_) s |= kSetPointAck;
            if (followingError_) s |= kFollowingError;
            break;
        case kPV:
            if (std::abs(velocity_) < 1.0) s |= kSetPointAck;  // speed = 0
            break;
        case kHM:
            // 13/12/10 (CiA 402-2 §13.1): 000 in progress, 001 interrupted or not started,
            // 011 attained, 100/101 error with the motor moving/standing.
            if (homingActive_) s &= uint16_t(~sw::TargetReached);
            if (homingDone_) s |= kSetPointAck;
            if (homingError_) s |= kFollowingError;
            break;
        case kIP:
        case kCSP:
        case kCSV:
        case kCST:
            s |= kSetPointAck;  // drive follows the command value
            if (followingError_) s |= kFollowingError;
            break;
        default: break;
        }
    } else if (state_ == State::SwitchOnDisabled || state_ == State::ReadyToSwitchOn || state_ == State::SwitchedOn) {
        s |= sw::TargetReached;
    }
    if (homeFound_) s |= 0x8000;  // AIMOTOR "home found" (extract-aimotor §4.2)
    statusword_ = s;
    writeInt(0x6041, 0, s);
    writeInt(0x6061, 0, modeDisplay_);
    const auto pos = std::llround(position_);
    writeInt(0x6064, 0, pos);
    writeInt(0x6063, 0, pos);
    writeInt(0x6062, 0, std::llround(demand_));
    writeInt(0x606C, 0, std::llround(velocity_));
    writeInt(0x6077, 0, std::llround(torque_));
    writeInt(0x60F4, 0, std::llround(demand_ - position_));
}

void Ds402Drive::abortConnection(int16_t optionCode) {
    // As the controlword commands Disable voltage (xxxx xx0x) and Quick stop (xxxx x01x) would
    // (CiA 402-2 Table 27); the master's next controlword starts from there.
    if (optionCode == 2) handleControlword(0x0000);
    else if (optionCode == 3) handleControlword(0x0002);
    publish();
}

}  // namespace coscope::sim
