// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"

#include <QByteArray>

#include <cstdint>

// Client-side frames of SDO block transfer (CiA 301 §7.2.4.3.9 - §7.2.4.3.16), on 600h + node.
namespace coscope::canopen::sdo {

// ccs 5, cs 0: cc (CRC supported) set, blksize segments per sub-block, pst protocol switch.
CanFrame blockUploadInitiate(uint8_t node, uint16_t index, uint8_t sub, uint8_t blockSize, uint8_t protocolSwitch = 0);
CanFrame blockUploadStart(uint8_t node);                                   // ccs 5, cs 3
CanFrame blockUploadAck(uint8_t node, uint8_t ackSeq, uint8_t blockSize);  // ccs 5, cs 2
CanFrame blockUploadEndResponse(uint8_t node);                             // ccs 5, cs 1
// ccs 6, cs 0: cc set, size indicated.
CanFrame blockDownloadInitiate(uint8_t node, uint16_t index, uint8_t sub, uint32_t size);
// One sub-block segment: seqno 1..127, bit 7 = last, 7 bytes (chunk padded with zeros).
CanFrame blockSegment(uint8_t node, uint8_t seqno, bool last, const char* chunk, int len, bool fromServer = false);
// ccs 6, cs 1: n = bytes of the last segment without data, CRC of the whole data.
CanFrame blockDownloadEnd(uint8_t node, uint8_t unusedBytes, uint16_t crc);

}  // namespace coscope::canopen::sdo
