// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"

#include <QByteArray>
#include <QString>

#include <cstdint>

namespace coscope::canopen {

// One SDO frame taken apart (CiA 301 §7.2.4.3). Client -> server frames travel on 600h + node,
// server -> client on 580h + node. Block transfer sub-block segments cannot be told from
// commands by their bytes alone: the caller says when a sub-block is in progress.
enum class SdoCommand : uint8_t {
    Invalid,
    // client -> server
    InitiateDownloadRequest,  // ccs 1
    DownloadSegmentRequest,   // ccs 0
    InitiateUploadRequest,    // ccs 2
    UploadSegmentRequest,     // ccs 3
    BlockUploadInitiate,      // ccs 5, cs 0
    BlockUploadStart,         // ccs 5, cs 3
    BlockUploadAck,           // ccs 5, cs 2
    BlockUploadEndResponse,   // ccs 5, cs 1
    BlockDownloadInitiate,    // ccs 6, cs 0
    BlockDownloadEnd,         // ccs 6, cs 1
    // server -> client
    InitiateDownloadResponse,       // scs 3
    DownloadSegmentResponse,        // scs 1
    InitiateUploadResponse,         // scs 2
    UploadSegmentResponse,          // scs 0
    BlockDownloadInitiateResponse,  // scs 5, ss 0
    BlockDownloadAck,               // scs 5, ss 2
    BlockDownloadEndResponse,       // scs 5, ss 1
    BlockUploadInitiateResponse,    // scs 6, ss 0
    BlockUploadEnd,                 // scs 6, ss 1
    // both
    Abort,         // cs 4
    BlockSegment,  // seqno 1..127 (+ bit 7 = last), 7 data bytes
};

struct SdoFrame {
    SdoCommand command = SdoCommand::Invalid;
    uint16_t index = 0;
    uint8_t sub = 0;
    bool hasMux = false;  // index/sub present in this frame
    bool expedited = false;
    bool sizeIndicated = false;
    uint32_t size = 0;  // total size when indicated
    QByteArray data;    // expedited / segment / block segment payload (unused bytes removed)
    bool toggle = false;
    bool last = false;      // c bit: no more segments / last block segment
    uint8_t seqno = 0;      // block segment sequence number
    uint8_t blockSize = 0;  // blksize
    uint8_t ackSeq = 0;     // ackseq
    bool crcSupported = false;
    uint16_t crc = 0;
    uint8_t unusedBytes = 0;     // n in end-of-block frames (bytes of the last segment without data)
    uint8_t protocolSwitch = 0;  // pst
    uint32_t abortCode = 0;
    QString error;  // why the frame is Invalid or odd (wrong DLC, unknown specifier)
};

// fromClient: the frame went client -> server (600h + node). inSubBlock: a block transfer's
// sub-block is being sent in this direction, so the frame is a BlockSegment.
SdoFrame parseSdo(const uint8_t* data, int len, bool fromClient, bool inSubBlock = false);

// Short name of a command ("initiate download request", "abort", ...).
QString sdoCommandName(SdoCommand c);

// CRC-16 of SDO block transfers: CCITT polynomial x^16 + x^12 + x^5 + 1, initial value 0
// (CiA 301 §7.2.4.3.16).
uint16_t sdoBlockCrc(const uint8_t* data, size_t len, uint16_t crc = 0);

// Frame builders (payloads of 8 bytes; the caller puts them on 600h/580h + node).
namespace sdo {
CanFrame initiateDownload(uint8_t node, uint16_t index, uint8_t sub,
                          const QByteArray& data);  // expedited if ≤ 4 bytes, else segmented with size
CanFrame downloadSegment(uint8_t node, bool toggle, const QByteArray& chunk, bool last);
CanFrame initiateUpload(uint8_t node, uint16_t index, uint8_t sub);
CanFrame uploadSegmentRequest(uint8_t node, bool toggle);
CanFrame abortFromClient(uint8_t node, uint16_t index, uint8_t sub, uint32_t code);
CanFrame abortFromServer(uint8_t node, uint16_t index, uint8_t sub, uint32_t code);
CanFrame initiateDownloadResponse(uint8_t node, uint16_t index, uint8_t sub);
CanFrame downloadSegmentResponse(uint8_t node, bool toggle);
CanFrame initiateUploadResponse(uint8_t node, uint16_t index, uint8_t sub,
                                const QByteArray& data);  // expedited if ≤ 4 bytes
CanFrame uploadSegmentResponse(uint8_t node, bool toggle, const QByteArray& chunk, bool last);
}  // namespace sdo

}  // namespace coscope::canopen
