// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/Sdo.h"

#include <cstring>

namespace coscope::canopen {

namespace {
uint32_t le32(const uint8_t* p) { return p[0] | (p[1] << 8) | (p[2] << 16) | (static_cast<uint32_t>(p[3]) << 24); }

void readMux(SdoFrame& f, const uint8_t* d) {
    f.index = static_cast<uint16_t>(d[1] | (d[2] << 8));
    f.sub = d[3];
    f.hasMux = true;
}

// Initiate download request / initiate upload response: x n e s in bits 3..0, then the
// multiplexer, then up to 4 data bytes (expedited) or the size (CiA 301 §7.2.4.3.3/6).
void readInitiate(SdoFrame& f, const uint8_t* b) {
    readMux(f, b);
    f.expedited = b[0] & 0x02;
    f.sizeIndicated = b[0] & 0x01;
    if (f.expedited) {
        const int n = f.sizeIndicated ? 4 - ((b[0] >> 2) & 0x3) : 4;
        f.size = static_cast<uint32_t>(n);
        f.data = QByteArray(reinterpret_cast<const char*>(b + 4), n);
    } else if (f.sizeIndicated) {
        f.size = le32(b + 4);
    }
}

CanFrame frame8(uint32_t id, std::initializer_list<uint8_t> head) {
    CanFrame f;
    f.id = id;
    f.len = 8;
    std::copy(head.begin(), head.end(), f.data.begin());
    return f;
}

void putMux(CanFrame& f, uint16_t index, uint8_t sub) {
    f.data[1] = static_cast<uint8_t>(index);
    f.data[2] = static_cast<uint8_t>(index >> 8);
    f.data[3] = sub;
}

}  // namespace

SdoFrame parseSdo(const uint8_t* d, int len, bool fromClient, bool inSubBlock) {
    SdoFrame f;
    if (len < 1) {
        f.error = QStringLiteral("empty SDO frame");
        return f;
    }
    if (len != 8) f.error = QStringLiteral("SDO frame has %1 bytes; CiA 301 requires 8").arg(len);
    // Read missing bytes as zero so a short frame is still shown as far as it goes.
    uint8_t b[8] = {};
    std::memcpy(b, d, static_cast<size_t>(std::min(len, 8)));
    const uint8_t c0 = b[0];

    if (inSubBlock) {
        f.command = SdoCommand::BlockSegment;
        f.seqno = c0 & 0x7F;
        f.last = c0 & 0x80;
        f.data = QByteArray(reinterpret_cast<const char*>(b + 1), 7);
        if (f.seqno == 0) f.error = QStringLiteral("block segment with sequence number 0");
        return f;
    }
    const int cs = c0 >> 5;
    if (cs == 4) {  // abort transfer, both directions (CiA 301 §7.2.4.3.17)
        f.command = SdoCommand::Abort;
        readMux(f, b);
        f.abortCode = le32(b + 4);
        return f;
    }
    if (fromClient) {
        switch (cs) {
        case 1:  // initiate download: ccs=1 x n e s
            f.command = SdoCommand::InitiateDownloadRequest;
            readInitiate(f, b);
            break;
        case 0:  // download segment: ccs=0 t n c
            f.command = SdoCommand::DownloadSegmentRequest;
            f.toggle = c0 & 0x10;
            f.unusedBytes = (c0 >> 1) & 0x7;
            f.last = c0 & 0x01;
            f.data = QByteArray(reinterpret_cast<const char*>(b + 1), 7 - f.unusedBytes);
            break;
        case 2:
            f.command = SdoCommand::InitiateUploadRequest;
            readMux(f, b);
            break;
        case 3:
            f.command = SdoCommand::UploadSegmentRequest;
            f.toggle = c0 & 0x10;
            break;
        case 5:  // block upload, client side: cs in bits 1..0
            switch (c0 & 0x3) {
            case 0:
                f.command = SdoCommand::BlockUploadInitiate;
                f.crcSupported = c0 & 0x04;
                readMux(f, b);
                f.blockSize = b[4];
                f.protocolSwitch = b[5];
                break;
            case 3: f.command = SdoCommand::BlockUploadStart; break;
            case 2:
                f.command = SdoCommand::BlockUploadAck;
                f.ackSeq = b[1];
                f.blockSize = b[2];
                break;
            case 1: f.command = SdoCommand::BlockUploadEndResponse; break;
            }
            break;
        case 6:  // block download, client side: cs in bit 0
            if ((c0 & 0x1) == 0) {
                f.command = SdoCommand::BlockDownloadInitiate;
                f.crcSupported = c0 & 0x04;
                f.sizeIndicated = c0 & 0x02;
                readMux(f, b);
                if (f.sizeIndicated) f.size = le32(b + 4);
            } else {
                f.command = SdoCommand::BlockDownloadEnd;
                f.unusedBytes = (c0 >> 2) & 0x7;
                f.crc = static_cast<uint16_t>(b[1] | (b[2] << 8));
            }
            break;
        default: f.error = QStringLiteral("unknown client command specifier %1").arg(cs); break;
        }
    } else {
        switch (cs) {
        case 3:
            f.command = SdoCommand::InitiateDownloadResponse;
            readMux(f, b);
            break;
        case 1:
            f.command = SdoCommand::DownloadSegmentResponse;
            f.toggle = c0 & 0x10;
            break;
        case 2:  // initiate upload response: scs=2 x n e s
            f.command = SdoCommand::InitiateUploadResponse;
            readInitiate(f, b);
            break;
        case 0:
            f.command = SdoCommand::UploadSegmentResponse;
            f.toggle = c0 & 0x10;
            f.unusedBytes = (c0 >> 1) & 0x7;
            f.last = c0 & 0x01;
            f.data = QByteArray(reinterpret_cast<const char*>(b + 1), 7 - f.unusedBytes);
            break;
        case 5:  // block download, server side: ss in bits 1..0
            switch (c0 & 0x3) {
            case 0:
                f.command = SdoCommand::BlockDownloadInitiateResponse;
                f.crcSupported = c0 & 0x04;
                readMux(f, b);
                f.blockSize = b[4];
                break;
            case 2:
                f.command = SdoCommand::BlockDownloadAck;
                f.ackSeq = b[1];
                f.blockSize = b[2];
                break;
            case 1: f.command = SdoCommand::BlockDownloadEndResponse; break;
            default: f.error = QStringLiteral("unknown block download server subcommand 3"); break;
            }
            break;
        case 6:  // block upload, server side: ss in bit 0
            if ((c0 & 0x1) == 0) {
                f.command = SdoCommand::BlockUploadInitiateResponse;
                f.crcSupported = c0 & 0x04;
                f.sizeIndicated = c0 & 0x02;
                readMux(f, b);
                if (f.sizeIndicated) f.size = le32(b + 4);
            } else {
                f.command = SdoCommand::BlockUploadEnd;
                f.unusedBytes = (c0 >> 2) & 0x7;
                f.crc = static_cast<uint16_t>(b[1] | (b[2] << 8));
            }
            break;
        default: f.error = QStringLiteral("unknown server command specifier %1").arg(cs); break;
        }
    }
    return f;
}

QString sdoCommandName(SdoCommand c) {
    switch (c) {
    case SdoCommand::Invalid: return QStringLiteral("invalid");
    case SdoCommand::InitiateDownloadRequest: return QStringLiteral("initiate download request");
    case SdoCommand::DownloadSegmentRequest: return QStringLiteral("download segment request");
    case SdoCommand::InitiateUploadRequest: return QStringLiteral("initiate upload request");
    case SdoCommand::UploadSegmentRequest: return QStringLiteral("upload segment request");
    case SdoCommand::BlockUploadInitiate: return QStringLiteral("block upload initiate");
    case SdoCommand::BlockUploadStart: return QStringLiteral("block upload start");
    case SdoCommand::BlockUploadAck: return QStringLiteral("block upload ack");
    case SdoCommand::BlockUploadEndResponse: return QStringLiteral("block upload end response");
    case SdoCommand::BlockDownloadInitiate: return QStringLiteral("block download initiate");
    case SdoCommand::BlockDownloadEnd: return QStringLiteral("block download end");
    case SdoCommand::InitiateDownloadResponse: return QStringLiteral("initiate download response");
    case SdoCommand::DownloadSegmentResponse: return QStringLiteral("download segment response");
    case SdoCommand::InitiateUploadResponse: return QStringLiteral("initiate upload response");
    case SdoCommand::UploadSegmentResponse: return QStringLiteral("upload segment response");
    case SdoCommand::BlockDownloadInitiateResponse: return QStringLiteral("block download initiate response");
    case SdoCommand::BlockDownloadAck: return QStringLiteral("block download ack");
    case SdoCommand::BlockDownloadEndResponse: return QStringLiteral("block download end response");
    case SdoCommand::BlockUploadInitiateResponse: return QStringLiteral("block upload initiate response");
    case SdoCommand::BlockUploadEnd: return QStringLiteral("block upload end");
    case SdoCommand::Abort: return QStringLiteral("abort");
    case SdoCommand::BlockSegment: return QStringLiteral("block segment");
    }
    return {};
}

uint16_t sdoBlockCrc(const uint8_t* data, size_t len, uint16_t crc) {
    for (size_t i = 0; i < len; ++i) {
        crc ^= static_cast<uint16_t>(data[i] << 8);
        for (int b = 0; b < 8; ++b)
            crc = (crc & 0x8000) ? static_cast<uint16_t>((crc << 1) ^ 0x1021) : static_cast<uint16_t>(crc << 1);
    }
    return crc;
}

namespace sdo {

CanFrame initiateDownload(uint8_t node, uint16_t index, uint8_t sub, const QByteArray& data) {
    CanFrame f = frame8(0x600u + node, {});
    putMux(f, index, sub);
    if (data.size() <= 4 && !data.isEmpty()) {
        f.data[0] = static_cast<uint8_t>(0x23 | ((4 - data.size()) << 2));  // ccs=1, e=1, s=1, n
        std::memcpy(f.data.data() + 4, data.constData(), static_cast<size_t>(data.size()));
    } else {
        f.data[0] = 0x21;  // ccs=1, e=0, s=1: size in bytes 4..7
        putLe32(f, 4, static_cast<uint32_t>(data.size()));
    }
    return f;
}

CanFrame downloadSegment(uint8_t node, bool toggle, const QByteArray& chunk, bool last) {
    CanFrame f = frame8(0x600u + node, {});
    const int n = static_cast<int>(std::min<qsizetype>(chunk.size(), 7));
    f.data[0] = static_cast<uint8_t>((toggle ? 0x10 : 0) | ((7 - n) << 1) | (last ? 1 : 0));
    std::memcpy(f.data.data() + 1, chunk.constData(), static_cast<size_t>(n));
    return f;
}

CanFrame initiateUpload(uint8_t node, uint16_t index, uint8_t sub) {
    CanFrame f = frame8(0x600u + node, {0x40});
    putMux(f, index, sub);
    return f;
}

CanFrame uploadSegmentRequest(uint8_t node, bool toggle) {
    return frame8(0x600u + node, {static_cast<uint8_t>(0x60 | (toggle ? 0x10 : 0))});
}

CanFrame abortFromClient(uint8_t node, uint16_t index, uint8_t sub, uint32_t code) {
    CanFrame f = frame8(0x600u + node, {0x80});
    putMux(f, index, sub);
    putLe32(f, 4, code);
    return f;
}

CanFrame abortFromServer(uint8_t node, uint16_t index, uint8_t sub, uint32_t code) {
    CanFrame f = abortFromClient(node, index, sub, code);
    f.id = 0x580u + node;
    return f;
}

CanFrame initiateDownloadResponse(uint8_t node, uint16_t index, uint8_t sub) {
    CanFrame f = frame8(0x580u + node, {0x60});
    putMux(f, index, sub);
    return f;
}

CanFrame downloadSegmentResponse(uint8_t node, bool toggle) {
    return frame8(0x580u + node, {static_cast<uint8_t>(0x20 | (toggle ? 0x10 : 0))});
}

CanFrame initiateUploadResponse(uint8_t node, uint16_t index, uint8_t sub, const QByteArray& data) {
    CanFrame f = frame8(0x580u + node, {});
    putMux(f, index, sub);
    if (data.size() <= 4 && !data.isEmpty()) {
        f.data[0] = static_cast<uint8_t>(0x43 | ((4 - data.size()) << 2));  // scs=2, e=1, s=1, n
        std::memcpy(f.data.data() + 4, data.constData(), static_cast<size_t>(data.size()));
    } else {
        f.data[0] = 0x41;  // scs=2, e=0, s=1
        putLe32(f, 4, static_cast<uint32_t>(data.size()));
    }
    return f;
}

CanFrame uploadSegmentResponse(uint8_t node, bool toggle, const QByteArray& chunk, bool last) {
    CanFrame f = downloadSegment(node, toggle, chunk, last);  // same layout, scs = 0
    f.id = 0x580u + node;
    return f;
}

}  // namespace sdo

}  // namespace coscope::canopen
