// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstdint>

namespace coscope::canopen {

// Layer setting services (CiA 305): master -> slaves on 7E5h, slave -> master on 7E4h,
// 8 bytes, byte 0 the command specifier.
namespace lss {
inline constexpr uint32_t kMasterToSlave = 0x7E5;
inline constexpr uint32_t kSlaveToMaster = 0x7E4;

inline constexpr uint8_t SwitchStateGlobal = 0x04;  // byte 1: 0 waiting, 1 configuration
inline constexpr uint8_t SwitchSelectiveVendor = 0x40;
inline constexpr uint8_t SwitchSelectiveProduct = 0x41;
inline constexpr uint8_t SwitchSelectiveRevision = 0x42;
inline constexpr uint8_t SwitchSelectiveSerial = 0x43;
inline constexpr uint8_t SwitchSelectiveResponse = 0x44;
inline constexpr uint8_t ConfigureNodeId = 0x11;     // byte 1 node-ID; response byte 1 error code
inline constexpr uint8_t ConfigureBitTiming = 0x13;  // byte 1 table selector, byte 2 table index
inline constexpr uint8_t ActivateBitTiming = 0x15;   // bytes 1-2 switch delay in ms
inline constexpr uint8_t StoreConfiguration = 0x17;
inline constexpr uint8_t InquireVendor = 0x5A;
inline constexpr uint8_t InquireProduct = 0x5B;
inline constexpr uint8_t InquireRevision = 0x5C;
inline constexpr uint8_t InquireSerial = 0x5D;
inline constexpr uint8_t InquireNodeId = 0x5E;
inline constexpr uint8_t IdentifyVendor = 0x46;
inline constexpr uint8_t IdentifyProduct = 0x47;
inline constexpr uint8_t IdentifyRevisionLow = 0x48;
inline constexpr uint8_t IdentifyRevisionHigh = 0x49;
inline constexpr uint8_t IdentifySerialLow = 0x4A;
inline constexpr uint8_t IdentifySerialHigh = 0x4B;
inline constexpr uint8_t IdentifyNonConfigured = 0x4C;
inline constexpr uint8_t IdentifySlaveResponse = 0x4F;
inline constexpr uint8_t IdentifyNonConfiguredResponse = 0x50;
inline constexpr uint8_t Fastscan = 0x51;  // bytes 1-4 IDNumber, 5 BitChecked, 6 LSSSub, 7 LSSNext
}  // namespace lss

// Name of an LSS command specifier; `fromMaster` picks between request and response meaning.
QString lssCommandName(uint8_t cs, bool fromMaster);

// CiA 305 standard bit timing table (table selector 0): index -> bit/s; 0 for "automatic"
// and -1 for an index outside the table. Index 5 is 100 kbit/s in CiA 305 v2 (reserved later).
int lssBitRate(uint8_t i);
int lssTableIndexForBitRate(int bitRate);  // -1 when the rate is not in the table

}  // namespace coscope::canopen
