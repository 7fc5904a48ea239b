// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Numbers of Vector's BLF format that the reader (VectorBlf.cpp) and the writer
// (VectorBlfWriter.cpp) share: object types and the flags of a CAN message object, as documented
// by Vector's binlog headers and read by python-can's blf module.

#include <cstdint>

namespace coscope::logio::blf {

// Object types (ObjectHeaderBase.objectType).
constexpr uint32_t kCanMessage = 1, kCanError = 2, kLogContainer = 10, kCanErrorExt = 73, kCanMessage2 = 86,
                   kCanFdMessage = 100, kCanFdMessage64 = 101;
constexpr uint32_t kMsgExt = 0x80000000U;         // extended id flag in the arbitration id
constexpr uint8_t kDirTx = 0x01, kRemote = 0x80;  // CAN message flags: transmitted, remote frame

}  // namespace coscope::logio::blf
