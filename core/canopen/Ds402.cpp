// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/Ds402.h"

namespace coscope::canopen::ds402 {

State stateFromStatusword(uint16_t s) {
    // CiA 402-2 Table 30: state coding with x = don't care.
    if ((s & 0x4F) == 0x00) return State::NotReadyToSwitchOn;
    if ((s & 0x4F) == 0x40) return State::SwitchOnDisabled;
    if ((s & 0x6F) == 0x21) return State::ReadyToSwitchOn;
    if ((s & 0x6F) == 0x23) return State::SwitchedOn;
    if ((s & 0x6F) == 0x27) return State::OperationEnabled;
    if ((s & 0x6F) == 0x07) return State::QuickStopActive;
    if ((s & 0x4F) == 0x0F) return State::FaultReactionActive;
    if ((s & 0x4F) == 0x08) return State::Fault;
    return State::Unknown;
}

QString stateName(State s) {
    switch (s) {
    case State::NotReadyToSwitchOn: return QStringLiteral("Not ready to switch on");
    case State::SwitchOnDisabled: return QStringLiteral("Switch on disabled");
    case State::ReadyToSwitchOn: return QStringLiteral("Ready to switch on");
    case State::SwitchedOn: return QStringLiteral("Switched on");
    case State::OperationEnabled: return QStringLiteral("Operation enabled");
    case State::QuickStopActive: return QStringLiteral("Quick stop active");
    case State::FaultReactionActive: return QStringLiteral("Fault reaction active");
    case State::Fault: return QStringLiteral("Fault");
    case State::Unknown: break;
    }
    return QStringLiteral("Unknown state");
}

QString statuswordBitName(int bit) {
    switch (bit) {
    case 0: return QStringLiteral("ready to switch on");
    case 1: return QStringLiteral("switched on");
    case 2: return QStringLiteral("operation enabled");
    case 3: return QStringLiteral("fault");
    case 4: return QStringLiteral("voltage enabled");
    case 5: return QStringLiteral("quick stop");
    case 6: return QStringLiteral("switch on disabled");
    case 7: return QStringLiteral("warning");
    case 8: return QStringLiteral("manufacturer specific (bit 8)");
    case 9: return QStringLiteral("remote");
    case 10: return QStringLiteral("target reached");
    case 11: return QStringLiteral("internal limit active");
    case 12: return QStringLiteral("operation mode specific (bit 12)");
    case 13: return QStringLiteral("operation mode specific (bit 13)");
    case 14: return QStringLiteral("manufacturer specific (bit 14)");
    case 15: return QStringLiteral("manufacturer specific (bit 15)");
    default: return {};
    }
}

QStringList statuswordBits(uint16_t s) {
    QStringList out;
    for (int b = 0; b < 16; ++b)
        if (s & (1u << b)) out << statuswordBitName(b);
    return out;
}

QString statuswordBitName(int bit, std::optional<int8_t> mode) {
    if (!mode || (bit != 12 && bit != 13)) return statuswordBitName(bit);
    // CiA 402-2 §12.1 (PP), §13.1 (HM), §14.1 (PV), §15 (IP), §16-18 (CSP, CSV, CST); the
    // Delta and AIMOTOR manuals use the same meanings (extract-delta §4.2, extract-aimotor §4.2).
    switch (*mode) {
    case 1: return bit == 12 ? QStringLiteral("set-point acknowledge") : QStringLiteral("following error");
    case 3: return bit == 12 ? QStringLiteral("zero speed") : QStringLiteral("max slippage error");
    case 6: return bit == 12 ? QStringLiteral("homing attained") : QStringLiteral("homing error");
    case 7: return bit == 12 ? QStringLiteral("ip mode active") : statuswordBitName(bit);
    case 8: return bit == 12 ? QStringLiteral("drive follows the command value") : QStringLiteral("following error");
    case 9:
    case 10: return bit == 12 ? QStringLiteral("drive follows the command value") : statuswordBitName(bit);
    default: return statuswordBitName(bit);
    }
}

QStringList statuswordBits(uint16_t s, std::optional<int8_t> mode) {
    QStringList out;
    for (int b = 0; b < 16; ++b)
        if (s & (1u << b)) out << statuswordBitName(b, mode);
    return out;
}

uint16_t controlwordFor(Command c) {
    switch (c) {
    case Command::Shutdown: return 0x0006;
    case Command::SwitchOn: return 0x0007;
    case Command::SwitchOnAndEnable: return 0x000F;
    case Command::DisableVoltage: return 0x0000;
    case Command::QuickStop: return 0x0002;
    case Command::DisableOperation: return 0x0007;
    case Command::EnableOperation: return 0x000F;
    case Command::FaultReset: return 0x0080;
    }
    return 0;
}

QString commandName(Command c) {
    switch (c) {
    case Command::Shutdown: return QStringLiteral("Shutdown");
    case Command::SwitchOn: return QStringLiteral("Switch on");
    case Command::SwitchOnAndEnable: return QStringLiteral("Switch on + enable operation");
    case Command::DisableVoltage: return QStringLiteral("Disable voltage");
    case Command::QuickStop: return QStringLiteral("Quick stop");
    case Command::DisableOperation: return QStringLiteral("Disable operation");
    case Command::EnableOperation: return QStringLiteral("Enable operation");
    case Command::FaultReset: return QStringLiteral("Fault reset");
    }
    return {};
}

QString controlwordCommandName(uint16_t cw) {
    // CiA 402-2 Table 27, in order of precedence.
    if (cw & 0x80) return QStringLiteral("Fault reset");
    if ((cw & 0x02) == 0) return QStringLiteral("Disable voltage");
    if ((cw & 0x06) == 0x02) return QStringLiteral("Quick stop");
    if ((cw & 0x07) == 0x06) return QStringLiteral("Shutdown");
    if ((cw & 0x0F) == 0x07) return QStringLiteral("Switch on / disable operation");
    if ((cw & 0x0F) == 0x0F) return QStringLiteral("Enable operation");
    return QStringLiteral("No command");
}

QString modeName(int8_t mode) {
    switch (mode) {
    case 0: return QStringLiteral("No mode");
    case 1: return QStringLiteral("Profile position (PP)");
    case 2: return QStringLiteral("Velocity (VL)");
    case 3: return QStringLiteral("Profile velocity (PV)");
    case 4: return QStringLiteral("Profile torque (PT)");
    case 6: return QStringLiteral("Homing (HM)");
    case 7: return QStringLiteral("Interpolated position (IP)");
    case 8: return QStringLiteral("Cyclic synchronous position (CSP)");
    case 9: return QStringLiteral("Cyclic synchronous velocity (CSV)");
    case 10: return QStringLiteral("Cyclic synchronous torque (CST)");
    default:
        return mode < 0 ? QStringLiteral("Manufacturer-specific mode %1").arg(mode)
                        : QStringLiteral("Reserved mode %1").arg(mode);
    }
}

QString modeShortName(int8_t mode) {
    switch (mode) {
    case 1: return QStringLiteral("pp");
    case 2: return QStringLiteral("vl");
    case 3: return QStringLiteral("pv");
    case 4: return QStringLiteral("pt");
    case 6: return QStringLiteral("hm");
    case 7: return QStringLiteral("ip");
    case 8: return QStringLiteral("csp");
    case 9: return QStringLiteral("csv");
    case 10: return QStringLiteral("cst");
    default: return QString::number(mode);
    }
}

std::optional<int8_t> modeFromShortName(const QString& name) {
    const QString n = name.trimmed().toLower();
    for (int8_t m : {1, 2, 3, 4, 6, 7, 8, 9, 10})
        if (modeShortName(m) == n) return m;
    return std::nullopt;
}

bool modeSupported(uint32_t supported, int8_t mode) {
    if (mode < 1 || mode > 10 || mode == 5) return false;
    return supported & (1u << (mode - 1));
}

QString statuswordBitMeaning(int bit, bool set) {
    // Plain words for the bits a technician has to act on (CiA 402-2 Table 30 and the usual
    // causes named in the drive manuals' commissioning chapters).
    switch (bit) {
    case 0:
        return set ? QString()
                   : QStringLiteral(
                         "the drive is not ready: it ignored Shutdown (is it still starting up, or not under CANopen "
                         "control?)");
    case 1:
        return set ? QString()
                   : QStringLiteral(
                         "the drive did not switch on: main power, the enable input or safe torque off (STO) may be "
                         "blocking it");
    case 2:
        return set ? QString()
                   : QStringLiteral(
                         "the motor is not energised (servo off): check the enable/STO inputs and that the drive "
                         "accepts CANopen commands");
    case 3:
        return set ? QStringLiteral(
                         "the drive is in fault: read the error code and the vendor alarm, remove the cause, then "
                         "fault reset")
                   : QString();
    case 4: return set ? QString() : QStringLiteral("main power is not on (the power stage has no DC bus voltage)");
    case 5:
        return set ? QString()
                   : QStringLiteral("quick stop is active: the quick stop command or input is holding the drive");
    case 6:
        return set ? QStringLiteral("the drive is locked out (switch on disabled): it needs Shutdown first")
                   : QString();
    case 7:
        return set ? QStringLiteral("the drive reports a warning (not a fault): look at the drive's panel") : QString();
    case 9:
        return set ? QString()
                   : QStringLiteral(
                         "the drive is not under CANopen control (remote off): check its control-mode parameter");
    case 11: return set ? QStringLiteral("an internal limit is active (torque, speed or position limit)") : QString();
    default: return {};
    }
}

std::optional<Command> nextEnableCommand(State s) {
    switch (s) {
    case State::Fault: return Command::FaultReset;
    case State::SwitchOnDisabled: return Command::Shutdown;
    case State::ReadyToSwitchOn: return Command::SwitchOn;
    case State::SwitchedOn: return Command::EnableOperation;
    case State::QuickStopActive: return Command::DisableVoltage;
    default: return std::nullopt;
    }
}

}  // namespace coscope::canopen::ds402
