// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"

#include <QByteArray>

#include <cstdint>
#include <deque>

namespace coscope::sim {

class VirtualDevice;

// The SDO server of a virtual device (CiA 301 §7.2.4): one channel (600h/580h + node-ID),
// expedited, segmented and block transfers in both directions with CRC, protocol switch for
// small block uploads, SDO timeouts, and the fault knobs of SdoFaults.
class SdoServer {
public:
    explicit SdoServer(VirtualDevice& device);

    void onRequest(const CanFrame& frame, int64_t nowNs);
    void tick(int64_t nowNs);  // sends delayed responses, times transfers out
    void reset();              // NMT reset communication: abandons any transfer

private:
    enum class Phase : uint8_t {
        Idle,
        DownloadSegments,
        UploadSegments,
        BlockDownloadSub,
        BlockDownloadEnd,
        BlockUploadInitiated,
        BlockUploadSub,
        BlockUploadEnd
    };

    void respond(const CanFrame& frame);
    void abort(uint32_t code);
    void abortMux(uint16_t index, uint8_t sub, uint32_t code);
    void startUpload(uint16_t index, uint8_t sub);
    void startBlockUpload(uint16_t index, uint8_t sub, uint8_t blockSize, uint8_t pst, bool crc);
    void sendSubBlock();
    void finishDownload();
    CanFrame frame8(std::initializer_list<uint8_t> head) const;

    VirtualDevice& dev_;
    Phase phase_ = Phase::Idle;
    uint16_t index_ = 0;
    uint8_t sub_ = 0;
    QByteArray buffer_;
    int offset_ = 0;             // bytes sent (upload) so far
    uint32_t expectedSize_ = 0;  // download: indicated size (0 = not indicated)
    bool sizeIndicated_ = false;
    bool toggle_ = false;
    bool crc_ = false;
    uint8_t blockSize_ = 0;
    uint8_t seq_ = 0;        // block download: last good sequence number
    int subBlockStart_ = 0;  // block upload: offset of the sub-block being sent
    bool lastSegmentSeen_ = false;
    int64_t lastActivityNs_ = 0;
    struct Delayed {
        int64_t dueNs;
        CanFrame frame;
    };
    std::deque<Delayed> delayed_;
};

}  // namespace coscope::sim
