// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>

namespace coscope::canopen::ds402 {

// CiA 402 power drive system state machine (CiA 402-2 §6.2, statusword 6041h bits 0-3, 5, 6).
enum class State : uint8_t {
    NotReadyToSwitchOn,
    SwitchOnDisabled,
    ReadyToSwitchOn,
    SwitchedOn,
    OperationEnabled,
    QuickStopActive,
    FaultReactionActive,
    Fault,
    Unknown,
};

State stateFromStatusword(uint16_t sw);
QString stateName(State s);

// Statusword bits (CiA 402-2 Table 30).
namespace sw {
inline constexpr uint16_t ReadyToSwitchOn = 1u << 0;
inline constexpr uint16_t SwitchedOn = 1u << 1;
inline constexpr uint16_t OperationEnabled = 1u << 2;
inline constexpr uint16_t Fault = 1u << 3;
inline constexpr uint16_t VoltageEnabled = 1u << 4;
inline constexpr uint16_t QuickStop = 1u << 5;  // active low: 0 = quick stop active
inline constexpr uint16_t SwitchOnDisabled = 1u << 6;
inline constexpr uint16_t Warning = 1u << 7;
inline constexpr uint16_t Remote = 1u << 9;
inline constexpr uint16_t TargetReached = 1u << 10;
inline constexpr uint16_t InternalLimitActive = 1u << 11;
}  // namespace sw
// Names of the statusword bits that are set (e.g. "ready to switch on", "voltage enabled").
QStringList statuswordBits(uint16_t sw);
QString statuswordBitName(int bit);
// The same in mode of operation `mode` (6061h): bits 12 and 13 are mode specific (CiA 402-2
// §12-§16: PP "set-point acknowledge"/"following error", HM "homing attained"/"homing error",
// PV "zero speed"/"max slippage error", IP "ip mode active", CSx "drive follows the command
// value"/"following error"); nullopt = mode not known, the names without a mode.
QStringList statuswordBits(uint16_t sw, std::optional<int8_t> mode);
QString statuswordBitName(int bit, std::optional<int8_t> mode);
// What a statusword bit being on (`set`) or off means for a technician, in plain words, e.g.
// bit 4 off: "main power is not on". Empty when there is nothing useful to say.
QString statuswordBitMeaning(int bit, bool set);

// Controlword commands (CiA 402-2 Table 27: bits 0-3 and 7).
enum class Command : uint8_t {
    Shutdown,           // 0006h
    SwitchOn,           // 0007h
    SwitchOnAndEnable,  // 000Fh
    DisableVoltage,     // 0000h
    QuickStop,          // 0002h
    DisableOperation,   // 0007h
    EnableOperation,    // 000Fh
    FaultReset,         // 0080h (rising edge of bit 7)
};
uint16_t controlwordFor(Command c);
// The command a controlword value encodes, as a name ("Shutdown", "Enable operation", ...).
QString controlwordCommandName(uint16_t cw);
QString commandName(Command c);

// Modes of operation 6060h/6061h (CiA 402-2 Table 35).
QString modeName(int8_t mode);       // "Profile position (PP)", ...
QString modeShortName(int8_t mode);  // "pp", "pv", "pt", "hm", "ip", "csp", "csv", "cst", "vl"
std::optional<int8_t> modeFromShortName(const QString& name);
// 6502h supported drive modes: bit n-1 for mode n (pp bit 0, vl 1, pv 2, pt 3, hm 5, ip 6, csp 7, csv 8, cst 9).
bool modeSupported(uint32_t supportedModes6502, int8_t mode);

// The next command on the way to Operation enabled from `s` (Fault: Fault reset; Switch on
// disabled: Shutdown; Ready to switch on: Switch on; Switched on: Enable operation; Quick stop
// active: Disable voltage); nullopt in Operation enabled and the transient states.
std::optional<Command> nextEnableCommand(State s);

}  // namespace coscope::canopen::ds402
