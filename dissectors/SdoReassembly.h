// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/Sdo.h"
#include "dissectors/Dissection.h"

#include <QByteArray>

#include <cstdint>

namespace coscope::dissect {

// The state of one SDO channel (client 600h+n <-> server 580h+n) while a transfer is under
// way, following the CiA 301 §7.2.4.3 protocols: expedited, segmented (toggle bit checked),
// block (sequence numbers, sub-block acks, CRC-16 checked at the end).
struct SdoChannel {
    enum class Phase : uint8_t {
        Idle,
        DownloadInitiated,  // initiate download request seen, response awaited
        DownloadSegments,   // segments client -> server
        UploadInitiated,    // initiate upload request seen
        UploadSegments,     // segments server -> client
        BlockDownloadInitiated,
        BlockDownloadSubBlock,  // client sends segments
        BlockDownloadEnd,       // end request seen, end response awaited
        BlockUploadInitiated,
        BlockUploadStarted,  // server sends segments
        BlockUploadEnd,      // server's end seen, client's end response awaited
    };
    Phase phase = Phase::Idle;
    uint16_t index = 0;
    uint8_t sub = 0;
    bool expedited = false;
    bool sizeIndicated = false;
    uint32_t size = 0;
    QByteArray data;
    bool toggle = false;    // toggle expected in the next segment request
    bool lastSent = false;  // the c bit was seen: the next response ends the transfer
    uint8_t blockSize = 0;
    uint8_t expectedSeq = 1;
    bool crcSupported = false;
    uint16_t endCrc = 0;
    int64_t startNs = 0;
    // Block segments of the sub-block in progress are buffered until acknowledged.
    QByteArray subBlock;

    bool inSubBlock(bool fromClient) const {
        return fromClient ? phase == Phase::BlockDownloadSubBlock : phase == Phase::BlockUploadStarted;
    }
};

class NetworkContext;

// Parses one SDO frame as the channel expects it: inside a block sub-block the first byte is a
// sequence number, except for an abort (80h), which may interrupt it.
canopen::SdoFrame parseSdoFor(const SdoChannel& ch, const uint8_t* data, int len, bool fromClient);

// Feeds one parsed SDO frame to the channel of `node`; adds warnings to `out` and fills
// out.transfer when a transfer completes or is aborted.
void sdoTrack(SdoChannel& ch, const canopen::SdoFrame& f, bool fromClient, int node, int64_t tNs, Dissection& out);

}  // namespace coscope::dissect
