// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/logio/LogReader.h"
#include "core/logio/LogWriter.h"

#include <vector>

namespace coscope::logio {

// libpcap and pcapng captures of SocketCAN (LINKTYPE_CAN_SOCKETCAN = 227, tcpdump.org
// link-layer types): each packet is a struct can_frame / canfd_frame with the can_id in
// big-endian order (flags EFF 0x80000000, RTR 0x40000000, ERR 0x20000000), then len, the FD
// flags byte (BRS 0x01, ESI 0x02, FDF 0x04; linux/can.h), 2 reserved bytes and the data.
// pcap: both byte orders, microsecond (a1b2c3d4) and nanosecond (a1b23c4d) magic.
// pcapng (draft-ietf-opsawg-pcapng): SHB (either byte order), IDB with if_tsresol and
// if_name, EPB, SPB and the obsolete packet block. Record numbers count packets from 1.
// A packet comment (opt_comment) in CoScope's gap form (CaptureGapText.h) is a gap of
// the capture before that packet (LogReader::gaps()).
class PcapReader : public LogReader {
public:
    QString formatName() const override { return QStringLiteral("pcap"); }

protected:
    bool readHeader() override;
    size_t readFrames(CanFrame* out, size_t max) override;

private:
    struct Interface {
        uint16_t linkType = 0;
        uint64_t unitsPerSecond = 1000000;  // if_tsresol, default microseconds
        uint8_t bus = 0;
    };
    bool readExact(char* dst, qint64 n);
    // Up to n bytes from the input, buffered in large chunks (no per-packet device reads);
    // the pointer stays valid until the next call. *got < n only at the end of the input.
    const unsigned char* take(qint64 n, qint64* got);
    int readPcapRecord(CanFrame& frame);   // 1 frame, 0 skipped, -1 end
    int readPcapngBlock(CanFrame& frame);  // 1 frame, 0 skipped, -1 end
    bool parseSectionHeader(const unsigned char* first8);
    void parseInterface(const QByteArray& body);
    bool decodePacket(const unsigned char* p, uint32_t capLen, const Interface& itf, CanFrame& frame);
    uint32_t parsePacketOptions(const unsigned char* p, uint32_t len);  // returns epb_flags
    uint32_t u32(const unsigned char* p) const;
    uint16_t u16(const unsigned char* p) const;
    int64_t toNs(uint64_t ticks, uint64_t ups) const;

    bool ng_ = false;
    bool swapped_ = false;  // file byte order is big-endian
    Interface pcapItf_;     // classic pcap: the one link type
    std::vector<Interface> interfaces_;
    uint64_t packet_ = 0;
    QByteArray buf_;  // read-ahead: [pos_, end_) of data_ not consumed yet
    const unsigned char* data_ = nullptr;
    qsizetype pos_ = 0;
    qsizetype end_ = 0;
    bool eof_ = false;
    std::vector<CaptureGap> pendingGaps_;  // the next frame returned follows these
};

// Writes pcapng (SHB, one IDB per bus with link type 227 and nanosecond resolution, EPBs),
// which Wireshark and tshark open and dissect as SocketCAN.
class PcapngWriter : public LogWriter {
public:
    QString formatName() const override { return QStringLiteral("pcapng"); }
    // A gap goes into the next packet block as its comment (opt_comment, which Wireshark shows
    // as the packet comment), in the wording of CaptureGapText.h.
    bool keepsGaps() const override { return true; }

    // The blocks a reader needs before the packet blocks: the section header, then each
    // interface block with the number of frames written before it. A journal's pager puts them
    // in front of one chunk's packet blocks to read that chunk alone.
    struct HeaderBlock {
        uint64_t beforeFrame = 0;
        QByteArray bytes;
        int bus = -1;  // the interface block's bus (CanFrame::bus); -1: the section header
    };
    const std::vector<HeaderBlock>& headerBlocks() const { return headerBlocks_; }

protected:
    void writeHeader(const CanFrame* first) override;
    void writeFrame(const CanFrame& frame, const QString& summary) override;
    void writeGap(int64_t lostNs, int64_t backNs) override;

private:
    void writeInterface(uint8_t bus);
    std::vector<int> interfaceOfBus_;  // bus -> interface id, -1 = none yet
    uint32_t interfaces_ = 0;
    std::vector<QByteArray> comments_;  // for the next packet block, one a gap
    std::vector<HeaderBlock> headerBlocks_;
};

}  // namespace coscope::logio
