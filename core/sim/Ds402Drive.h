// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/Ds402.h"
#include "core/sim/HomingMotion.h"

#include <QString>

#include <cstdint>
#include <utility>
#include <vector>

namespace coscope::sim {

class VirtualDevice;

// One CiA 402 axis of a virtual drive: the power drive state machine (CiA 402-2 §6.2) driven by
// the controlword 6040h, the statusword 6041h with the state bits, target reached and following
// error, the modes of operation 6060h/6061h the vendor supports (6502h), and a motion model
// (1 ms steps) so that position 6064h, velocity 606Ch and torque 6077h move plausibly.
// Objects of axis n are at index + n * 800h (CiA 402 multi-axis offset).
//
// Profile position (CiA 402-2 §12): 607Ah taken on the rising edge of controlword bit 4, bit 5
// change set immediately, bit 6 relative to the last target; statusword bit 12 set-point
// acknowledge (stays on while a set-point waits in the one-deep buffer), bit 10 target reached
// (within 6067h of the target, or stopped by halt). 6081h, 6083h, 6084h in the vendor's units.
// Homing (CiA 402-2 §13, Ds402DriveHoming.cpp): the method 6098h as the drive's own table
// (canopen::homing) defines it, run on the modelled machine (HomingMachine) at 6099h:01/02 with
// 609Ah; bit 4 starts it, bit 4 low (or halt) interrupts it; bits 10/12/13 per §13 (homing
// attained, homing error); position 6064h = home offset 607Ch at home.
class Ds402Drive {
public:
    Ds402Drive(VirtualDevice& device, int axis);

    canopen::ds402::State state() const { return state_; }
    uint16_t statusword() const { return statusword_; }
    int8_t modeDisplay() const { return modeDisplay_; }
    double position() const { return position_; }  // in position units (6064h)
    double velocity() const { return velocity_; }  // in velocity units per second (606Ch)

    // A fault happened: fault reaction active, then FAULT (the caller sends the EMCY).
    void raiseFault(uint16_t errorCode);
    // The connection to the master was lost and 6007h (abort connection option code, CiA 402-2)
    // asks for 2 "disable voltage" or 3 "quick stop": the drive runs that command itself.
    void abortConnection(int16_t optionCode);
    bool faulted() const {
        return state_ == canopen::ds402::State::Fault || state_ == canopen::ds402::State::FaultReactionActive;
    }
    bool enabled() const { return state_ == canopen::ds402::State::OperationEnabled; }
    // NMT reset / power cycle: back to SWITCH ON DISABLED (fault kept if latched).
    void reset();

    // Called after 6040h/6060h/607Ah/... were written (SDO or RPDO).
    void onWrite(uint16_t index, uint8_t sub);
    // 1 ms step of the motion model; `dtNs` since the last step.
    void step(int64_t dtNs);
    // Whether the control-mode parameter allows CANopen control (vendor pre-condition).
    bool canopenControlActive() const;
    // The drive's own checks of an SDO write to object `base` (axis offset removed): 0 or the
    // abort code (modes 6060h against 6502h, homing method 6098h against the drive's table).
    uint32_t checkWrite(uint16_t base, uint8_t sub, int64_t value) const;
    // Machine position (before homing offsets) for tests of the homing model.
    double machinePosition() const { return position_ + machineOffset_; }
    // The lowest and highest machine position since homing last started (tests of where a
    // switch method travels, without sampling it from outside).
    std::pair<double, double> homingTravel() const { return {travelLow_, travelHigh_}; }

    // Fault injection for enable tests (network thread). mainPowerOff: voltage enabled (bit 4)
    // stays off and Switch on is not accepted (the drive stays in Ready to switch on), as a drive
    // without mains does. alarmOnSwitchOn: the vendor alarm (Personality::alarm name, or
    // "typical" for the personality's typical fault) raised when Switch on or Enable operation
    // is commanded; it comes again on every attempt until cleared.
    struct EnableFaults {
        bool mainPowerOff = false;
        QString alarmOnSwitchOn;
    };
    EnableFaults& enableFaults() { return enableFaults_; }

private:
    uint16_t idx(uint16_t base) const { return static_cast<uint16_t>(base + axis_ * 0x800); }
    int64_t readInt(uint16_t base, uint8_t sub = 0, int64_t fallback = 0) const;
    void writeInt(uint16_t base, uint8_t sub, int64_t v);
    void handleControlword(uint16_t cw);
    void setState(canopen::ds402::State s);
    void publish();
    void stepProfilePosition(double dt);
    void stepVelocity(double dt, double target);
    void stepToward(double dt, double target, double accel, double decel);
    void handleSetPoint(uint16_t cw, bool rise);
    void stopMotion();  // leaving Operation enabled, quick stop, mode change
    double countsPerRevolution() const;
    double ramp(uint16_t base, double fallback) const;  // 6083h/6084h/6085h/609Ah in units/s²
    // Ds402DriveHoming.cpp
    double homingSpeed(uint8_t sub) const;
    void startHoming();
    void interruptHoming();
    void finishHoming();
    void stepHoming(double dt);

    VirtualDevice& dev_;
    int axis_;
    canopen::ds402::State state_ = canopen::ds402::State::SwitchOnDisabled;
    uint16_t statusword_ = 0;
    uint16_t lastControlword_ = 0;
    int8_t modeDisplay_ = 0;
    double position_ = 0;  // actual
    double velocity_ = 0;  // actual, units/s
    double torque_ = 0;    // per mille of rated torque
    double demand_ = 0;    // position demand (6062h)
    double ppTarget_ = 0;  // active profile-position target
    bool ppMoving_ = false;
    double ppNext_ = 0;  // the buffered set-point (single set-point mode)
    bool ppBuffered_ = false;
    bool ppAck_ = false;  // statusword bit 12 in PP
    bool targetReached_ = true;
    bool followingError_ = false;
    bool homingDone_ = false;  // bit 12 in HM: homing attained
    bool homingActive_ = false;
    double travelLow_ = 0, travelHigh_ = 0;  // homingTravel()
    bool homingError_ = false;               // bit 13 in HM
    bool homeFound_ = false;                 // AIMOTOR bit 15
    bool stalled_ = false;                   // hard-stop homing: against the end stop, torque at the limit
    std::vector<HomingLeg> homingLegs_;
    size_t homingLeg_ = 0;
    double homingElapsed_ = 0;  // s
    double stallTime_ = 0;      // s
    double machineOffset_ = 0;  // machine position = position_ + machineOffset_
    int faultReactionMs_ = 0;
    uint16_t pendingFault_ = 0;
    EnableFaults enableFaults_;
};

}  // namespace coscope::sim
