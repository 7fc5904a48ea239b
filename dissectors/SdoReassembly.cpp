// SPDX-License-Identifier: GPL-3.0-or-later
// SDO transfer reassembly (CiA 301 §7.2.4.3): expedited, segmented and block up/download.
#include "dissectors/SdoReassembly.h"

#include "core/canopen/SdoAbort.h"

namespace coscope::dissect {

using canopen::SdoCommand;
using Phase = SdoChannel::Phase;

namespace {

QString obj(uint16_t index, uint8_t sub) {
    return QStringLiteral("%1:%2").arg(index, 4, 16, QLatin1Char('0')).arg(sub, 2, 16, QLatin1Char('0')).toUpper();
}

void begin(SdoChannel& ch, Phase phase, const canopen::SdoFrame& f, int64_t tNs, Dissection& out) {
    if (ch.phase != Phase::Idle)
        out.warn(QStringLiteral("new SDO request for %1 while the transfer of %2 was unfinished (abandoned)")
                     .arg(obj(f.index, f.sub), obj(ch.index, ch.sub)));
    ch = SdoChannel{};
    ch.phase = phase;
    ch.index = f.index;
    ch.sub = f.sub;
    ch.sizeIndicated = f.sizeIndicated;
    ch.size = f.size;
    ch.startNs = tNs;
}

void checkMux(const SdoChannel& ch, const canopen::SdoFrame& f, Dissection& out) {
    if (f.hasMux && (f.index != ch.index || f.sub != ch.sub))
        out.warn(QStringLiteral("response for %1 but the request was for %2")
                     .arg(obj(f.index, f.sub), obj(ch.index, ch.sub)));
}

void finish(SdoChannel& ch, bool upload, bool block, int node, int64_t tNs, Dissection& out, const QString& status) {
    SdoTransferRecord& r = out.transfer;
    r.node = node;
    r.upload = upload;
    r.block = block;
    r.segmented = !ch.expedited && !block;
    r.index = ch.index;
    r.sub = ch.sub;
    r.data = ch.data;
    r.size = static_cast<uint32_t>(ch.data.size());
    r.status = status;
    r.abortCode = 0;
    r.abortText.clear();
    r.name.clear();
    r.valueText.clear();
    r.startNs = ch.startNs;
    r.endNs = tNs;
    if (status == QLatin1String("ok") && ch.sizeIndicated && !ch.expedited && ch.size != r.size) {
        out.warn(QStringLiteral("SDO transfer of %1 carried %2 bytes but announced %3")
                     .arg(obj(ch.index, ch.sub))
                     .arg(r.size)
                     .arg(ch.size));
        r.status = QStringLiteral("size mismatch");
    }
    out.hasTransfer = true;
    ch = SdoChannel{};
}

// Commits the acknowledged segments of a sub-block (CiA 301 §7.2.4.3.12: ackseq = last
// segment received in sequence; later ones are repeated by the sender).
void commitSubBlock(SdoChannel& ch, const canopen::SdoFrame& f, Dissection& out) {
    const int received = ch.expectedSeq - 1;
    const int acked = std::min<int>(f.ackSeq, received);
    if (f.ackSeq != received)
        out.warn(QStringLiteral("block ack acknowledges %1 segments, %2 were sent").arg(f.ackSeq).arg(received));
    ch.data.append(ch.subBlock.left(acked * 7));
    if (acked < received) ch.lastSent = false;  // the last segment will be repeated
    ch.subBlock.clear();
    ch.expectedSeq = 1;
    if (f.blockSize) ch.blockSize = f.blockSize;
}

void finishBlock(SdoChannel& ch, bool upload, int node, int64_t tNs, Dissection& out) {
    QString status = QStringLiteral("ok");
    if (ch.crcSupported) {
        const uint16_t crc = canopen::sdoBlockCrc(reinterpret_cast<const uint8_t*>(ch.data.constData()),
                                                  static_cast<size_t>(ch.data.size()));
        if (crc != ch.endCrc) {
            out.warn(QStringLiteral("SDO block CRC 0x%1 does not match the data (0x%2)")
                         .arg(ch.endCrc, 4, 16, QLatin1Char('0'))
                         .arg(crc, 4, 16, QLatin1Char('0')));
            status = QStringLiteral("crc error");
        }
    }
    finish(ch, upload, true, node, tNs, out, status);
}

}  // namespace

canopen::SdoFrame parseSdoFor(const SdoChannel& ch, const uint8_t* data, int len, bool fromClient) {
    const bool inSub = ch.inSubBlock(fromClient) && !(len >= 1 && data[0] == 0x80);
    return canopen::parseSdo(data, len, fromClient, inSub);
}

void sdoTrack(SdoChannel& ch, const canopen::SdoFrame& f, bool fromClient, int node, int64_t tNs, Dissection& out) {
    auto unexpected = [&] {
        out.warn(QStringLiteral("unexpected SDO %1 (%2)")
                     .arg(canopen::sdoCommandName(f.command),
                          ch.phase == Phase::Idle
                              ? QStringLiteral("no transfer in progress")
                              : QStringLiteral("transfer of %1 in progress").arg(obj(ch.index, ch.sub))));
    };
    auto toggleCheck = [&](bool expected) {
        if (f.toggle != expected)
            out.warn(QStringLiteral("SDO toggle bit %1, expected %2").arg(int(f.toggle)).arg(int(expected)));
    };
    switch (f.command) {
    case SdoCommand::Invalid: return;
    case SdoCommand::Abort: {
        const bool upload = ch.phase == Phase::UploadInitiated || ch.phase == Phase::UploadSegments ||
                            ch.phase == Phase::BlockUploadInitiated || ch.phase == Phase::BlockUploadStarted ||
                            ch.phase == Phase::BlockUploadEnd;
        const bool block = ch.phase >= Phase::BlockDownloadInitiated;
        if (ch.phase == Phase::Idle) {
            ch.index = f.index;
            ch.sub = f.sub;
            ch.startNs = tNs;
        } else if (f.index != ch.index || f.sub != ch.sub) {
            out.warn(QStringLiteral("abort names %1 but the transfer in progress is %2")
                         .arg(obj(f.index, f.sub), obj(ch.index, ch.sub)));
        }
        ch.data.clear();
        finish(ch, upload, block, node, tNs, out, QStringLiteral("aborted"));
        out.transfer.abortCode = f.abortCode;
        return;
    }
    case SdoCommand::InitiateDownloadRequest:
        begin(ch, Phase::DownloadInitiated, f, tNs, out);
        ch.expedited = f.expedited;
        if (f.expedited) ch.data = f.data;
        return;
    case SdoCommand::InitiateDownloadResponse:
        if (ch.phase != Phase::DownloadInitiated) return unexpected();
        checkMux(ch, f, out);
        if (ch.expedited) return finish(ch, false, false, node, tNs, out, QStringLiteral("ok"));
        ch.phase = Phase::DownloadSegments;
        ch.toggle = false;
        ch.lastSent = false;
        return;
    case SdoCommand::DownloadSegmentRequest:
        if (ch.phase != Phase::DownloadSegments) return unexpected();
        toggleCheck(ch.toggle);
        ch.data.append(f.data);
        ch.lastSent = f.last;
        return;
    case SdoCommand::DownloadSegmentResponse:
        if (ch.phase != Phase::DownloadSegments) return unexpected();
        toggleCheck(ch.toggle);
        ch.toggle = !ch.toggle;
        if (ch.lastSent) finish(ch, false, false, node, tNs, out, QStringLiteral("ok"));
        return;
    case SdoCommand::InitiateUploadRequest: begin(ch, Phase::UploadInitiated, f, tNs, out); return;
    case SdoCommand::InitiateUploadResponse:
        if (ch.phase != Phase::UploadInitiated && ch.phase != Phase::BlockUploadInitiated) return unexpected();
        checkMux(ch, f, out);
        ch.expedited = f.expedited;
        ch.sizeIndicated = f.sizeIndicated;
        ch.size = f.size;
        if (f.expedited) {
            ch.data = f.data;
            return finish(ch, true, false, node, tNs, out, QStringLiteral("ok"));
        }
        ch.phase = Phase::UploadSegments;
        ch.toggle = false;
        return;
    case SdoCommand::UploadSegmentRequest:
        if (ch.phase != Phase::UploadSegments) return unexpected();
        toggleCheck(ch.toggle);
        return;
    case SdoCommand::UploadSegmentResponse:
        if (ch.phase != Phase::UploadSegments) return unexpected();
        toggleCheck(ch.toggle);
        ch.toggle = !ch.toggle;
        ch.data.append(f.data);
        if (f.last) finish(ch, true, false, node, tNs, out, QStringLiteral("ok"));
        return;
    case SdoCommand::BlockDownloadInitiate:
        begin(ch, Phase::BlockDownloadInitiated, f, tNs, out);
        ch.crcSupported = f.crcSupported;
        return;
    case SdoCommand::BlockDownloadInitiateResponse:
        if (ch.phase != Phase::BlockDownloadInitiated) return unexpected();
        checkMux(ch, f, out);
        ch.crcSupported = ch.crcSupported && f.crcSupported;
        ch.blockSize = f.blockSize;
        ch.phase = Phase::BlockDownloadSubBlock;
        ch.expectedSeq = 1;
        return;
    case SdoCommand::BlockSegment:
        if (f.seqno != ch.expectedSeq) {
            out.warn(QStringLiteral("block segment %1, expected %2").arg(f.seqno).arg(ch.expectedSeq));
            return;
        }
        if (ch.blockSize && f.seqno > ch.blockSize)
            out.warn(QStringLiteral("block segment %1 beyond the block size %2").arg(f.seqno).arg(ch.blockSize));
        ch.subBlock.append(f.data);
        ++ch.expectedSeq;
        if (f.last) ch.lastSent = true;
        return;
    case SdoCommand::BlockDownloadAck:
        if (ch.phase != Phase::BlockDownloadSubBlock) return unexpected();
        commitSubBlock(ch, f, out);
        if (ch.lastSent) ch.phase = Phase::BlockDownloadEnd;
        return;
    case SdoCommand::BlockDownloadEnd:
        if (ch.phase != Phase::BlockDownloadEnd) return unexpected();
        ch.data.chop(std::min<int>(f.unusedBytes, static_cast<int>(ch.data.size())));
        ch.endCrc = f.crc;
        return;
    case SdoCommand::BlockDownloadEndResponse:
        if (ch.phase != Phase::BlockDownloadEnd) return unexpected();
        return finishBlock(ch, false, node, tNs, out);
    case SdoCommand::BlockUploadInitiate:
        begin(ch, Phase::BlockUploadInitiated, f, tNs, out);
        ch.crcSupported = f.crcSupported;
        ch.blockSize = f.blockSize;
        ch.sizeIndicated = false;
        return;
    case SdoCommand::BlockUploadInitiateResponse:
        if (ch.phase != Phase::BlockUploadInitiated) return unexpected();
        checkMux(ch, f, out);
        ch.crcSupported = ch.crcSupported && f.crcSupported;
        ch.sizeIndicated = f.sizeIndicated;
        ch.size = f.size;
        return;
    case SdoCommand::BlockUploadStart:
        if (ch.phase != Phase::BlockUploadInitiated) return unexpected();
        ch.phase = Phase::BlockUploadStarted;
        ch.expectedSeq = 1;
        return;
    case SdoCommand::BlockUploadAck:
        if (ch.phase != Phase::BlockUploadStarted) return unexpected();
        commitSubBlock(ch, f, out);
        if (ch.lastSent) ch.phase = Phase::BlockUploadEnd;
        return;
    case SdoCommand::BlockUploadEnd:
        if (ch.phase != Phase::BlockUploadEnd) return unexpected();
        ch.data.chop(std::min<int>(f.unusedBytes, static_cast<int>(ch.data.size())));
        ch.endCrc = f.crc;
        return;
    case SdoCommand::BlockUploadEndResponse:
        if (ch.phase != Phase::BlockUploadEnd) return unexpected();
        return finishBlock(ch, true, node, tNs, out);
    }
    (void)fromClient;
}

}  // namespace coscope::dissect
