// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstdint>

namespace coscope::canopen {

// SDO abort codes (CiA 301 §7.2.4.3.17, Table 22).
namespace sdoabort {
inline constexpr uint32_t ToggleBit = 0x05030000;
inline constexpr uint32_t Timeout = 0x05040000;
inline constexpr uint32_t InvalidCommand = 0x05040001;
inline constexpr uint32_t InvalidBlockSize = 0x05040002;
inline constexpr uint32_t InvalidSequence = 0x05040003;
inline constexpr uint32_t CrcError = 0x05040004;
inline constexpr uint32_t OutOfMemory = 0x05040005;
inline constexpr uint32_t UnsupportedAccess = 0x06010000;
inline constexpr uint32_t WriteOnly = 0x06010001;
inline constexpr uint32_t ReadOnly = 0x06010002;
inline constexpr uint32_t NoObject = 0x06020000;
inline constexpr uint32_t NotMappable = 0x06040041;
inline constexpr uint32_t PdoLengthExceeded = 0x06040042;
inline constexpr uint32_t ParameterIncompatible = 0x06040043;
inline constexpr uint32_t InternalIncompatible = 0x06040047;
inline constexpr uint32_t HardwareError = 0x06060000;
inline constexpr uint32_t TypeMismatch = 0x06070010;
inline constexpr uint32_t LengthTooHigh = 0x06070012;
inline constexpr uint32_t LengthTooLow = 0x06070013;
inline constexpr uint32_t NoSubIndex = 0x06090011;
inline constexpr uint32_t InvalidValue = 0x06090030;
inline constexpr uint32_t ValueTooHigh = 0x06090031;
inline constexpr uint32_t ValueTooLow = 0x06090032;
inline constexpr uint32_t MaxLessThanMin = 0x06090036;
inline constexpr uint32_t NoResource = 0x060A0023;
inline constexpr uint32_t GeneralError = 0x08000000;
inline constexpr uint32_t CannotStore = 0x08000020;
inline constexpr uint32_t LocalControl = 0x08000021;
inline constexpr uint32_t DeviceState = 0x08000022;
inline constexpr uint32_t NoDictionary = 0x08000023;
inline constexpr uint32_t NoData = 0x08000024;
}  // namespace sdoabort

// The CiA 301 meaning of an abort code, empty when the code is not a standard one (vendors
// define their own; the bundled alarm tables carry those).
QString sdoAbortText(uint32_t code);

}  // namespace coscope::canopen
