// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/SdoServer.h"

#include "core/canopen/Sdo.h"
#include "core/canopen/SdoAbort.h"
#include "core/sim/VirtualDevice.h"

#include <algorithm>

namespace coscope::sim {

using namespace canopen;

namespace {
constexpr int64_t kTransferTimeoutNs = 2'000'000'000;  // server gives up on a silent client
constexpr uint8_t kServerBlockSize = 127;              // segments per sub-block (CiA 301: 1-127)
constexpr int kMaxDownload = 16 * 1024 * 1024;         // the largest value taken (a program image)
}  // namespace

SdoServer::SdoServer(VirtualDevice& device) : dev_(device) {}

void SdoServer::reset() {
    phase_ = Phase::Idle;
    buffer_.clear();
    delayed_.clear();
}

CanFrame SdoServer::frame8(std::initializer_list<uint8_t> head) const {
    CanFrame f = CanFrame::classic(0x580u + dev_.nodeId(), {0, 0, 0, 0, 0, 0, 0, 0});
    int i = 0;
    for (uint8_t b : head) f.data[static_cast<size_t>(i++)] = b;
    return f;
}

void SdoServer::respond(const CanFrame& frame) {
    SdoFaults& faults = dev_.sdoFaults();
    if (faults.dropResponses > 0) {
        --faults.dropResponses;
        return;
    }
    if (faults.delayMs > 0 || !delayed_.empty()) {
        delayed_.push_back({dev_.now() + int64_t(std::max(0, faults.delayMs)) * 1'000'000, frame});
        return;
    }
    dev_.send(frame);
}

void SdoServer::tick(int64_t nowNs) {
    while (!delayed_.empty() && delayed_.front().dueNs <= nowNs) {
        dev_.send(delayed_.front().frame);
        delayed_.pop_front();
    }
    if (phase_ != Phase::Idle && nowNs - lastActivityNs_ > kTransferTimeoutNs) abort(sdoabort::Timeout);
}

void SdoServer::abortMux(uint16_t index, uint8_t sub, uint32_t code) {
    phase_ = Phase::Idle;
    buffer_.clear();
    respond(sdo::abortFromServer(dev_.nodeId(), index, sub, code));
}

void SdoServer::abort(uint32_t code) { abortMux(index_, sub_, code); }

void SdoServer::onRequest(const CanFrame& f, int64_t nowNs) {
    lastActivityNs_ = nowNs;
    // In a sub-block every frame is a segment, except a client abort (80h has no seqno 0).
    const bool inSubBlock = phase_ == Phase::BlockDownloadSub && !(f.len == 8 && f.data[0] == 0x80);
    const SdoFrame r = parseSdo(f.data.data(), f.len, true, inSubBlock);
    if (r.command == SdoCommand::Abort) {  // the client gives up: forget the transfer
        phase_ = Phase::Idle;
        buffer_.clear();
        return;
    }
    if (r.command == SdoCommand::Invalid) {
        abort(sdoabort::InvalidCommand);
        return;
    }
    SdoFaults& faults = dev_.sdoFaults();
    if (r.hasMux && faults.abortOn) {
        const auto& [ai, as, code] = *faults.abortOn;
        if (ai == r.index && as == r.sub) {
            abortMux(r.index, r.sub, code);
            return;
        }
    }
    switch (r.command) {
    case SdoCommand::InitiateDownloadRequest: {
        index_ = r.index;
        sub_ = r.sub;
        if (r.expedited) {
            QByteArray data = r.data;
            // Expedited without size: the value fills the data type (CiA 301 §7.2.4.3.3).
            const od::SubObject* e = dev_.entry(r.index, r.sub);
            if (!r.sizeIndicated && e && od::byteSize(e->dataType) > 0 && data.size() > od::byteSize(e->dataType))
                data.truncate(od::byteSize(e->dataType));
            if (const uint32_t code = dev_.writeFromSdo(r.index, r.sub, data)) {
                abortMux(r.index, r.sub, code);
                return;
            }
            phase_ = Phase::Idle;
            respond(sdo::initiateDownloadResponse(dev_.nodeId(), r.index, r.sub));
            return;
        }
        // Segmented: check the target before taking the data.
        const od::Object* obj = dev_.dictionary().object(r.index);
        const od::SubObject* e = obj ? obj->sub(r.sub) : nullptr;
        if (!obj || !e) {
            abortMux(r.index, r.sub, obj ? sdoabort::NoSubIndex : sdoabort::NoObject);
            return;
        }
        if (!od::isWritable(e->access)) {
            abortMux(r.index, r.sub, sdoabort::ReadOnly);
            return;
        }
        buffer_.clear();
        sizeIndicated_ = r.sizeIndicated;
        expectedSize_ = r.size;
        toggle_ = false;
        phase_ = Phase::DownloadSegments;
        respond(sdo::initiateDownloadResponse(dev_.nodeId(), r.index, r.sub));
        return;
    }
    case SdoCommand::DownloadSegmentRequest: {
        if (phase_ != Phase::DownloadSegments) {
            abort(sdoabort::InvalidCommand);
            return;
        }
        if (r.toggle != toggle_) {
            abort(sdoabort::ToggleBit);
            return;
        }
        buffer_.append(r.data);
        if (buffer_.size() > kMaxDownload) {
            abort(sdoabort::OutOfMemory);
            return;
        }
        if (faults.abortDownloadAfter && buffer_.size() >= faults.abortDownloadAfter->first) {
            abort(faults.abortDownloadAfter->second);
            return;
        }
        bool t = toggle_;
        if (faults.wrongToggle) {
            faults.wrongToggle = false;
            t = !t;
        }
        toggle_ = !toggle_;
        if (r.last) {
            if (sizeIndicated_ && uint32_t(buffer_.size()) != expectedSize_) {
                abort(uint32_t(buffer_.size()) > expectedSize_ ? sdoabort::LengthTooHigh : sdoabort::LengthTooLow);
                return;
            }
            if (const uint32_t code = dev_.writeFromSdo(index_, sub_, buffer_)) {
                abort(code);
                return;
            }
            phase_ = Phase::Idle;
            buffer_.clear();
        }
        respond(sdo::downloadSegmentResponse(dev_.nodeId(), t));
        return;
    }
    case SdoCommand::InitiateUploadRequest: startUpload(r.index, r.sub); return;
    case SdoCommand::UploadSegmentRequest: {
        if (phase_ != Phase::UploadSegments) {
            abort(sdoabort::InvalidCommand);
            return;
        }
        if (r.toggle != toggle_) {
            abort(sdoabort::ToggleBit);
            return;
        }
        const QByteArray chunk = buffer_.mid(offset_, 7);
        offset_ += static_cast<int>(chunk.size());
        const bool last = offset_ >= buffer_.size();
        bool t = toggle_;
        if (faults.wrongToggle) {
            faults.wrongToggle = false;
            t = !t;
        }
        toggle_ = !toggle_;
        if (last) phase_ = Phase::Idle;
        respond(sdo::uploadSegmentResponse(dev_.nodeId(), t, chunk, last));
        return;
    }
    case SdoCommand::BlockDownloadInitiate: {
        if (faults.declineBlock) {
            abortMux(r.index, r.sub, sdoabort::InvalidCommand);
            return;
        }
        const od::Object* obj = dev_.dictionary().object(r.index);
        const od::SubObject* e = obj ? obj->sub(r.sub) : nullptr;
        if (!obj || !e) {
            abortMux(r.index, r.sub, obj ? sdoabort::NoSubIndex : sdoabort::NoObject);
            return;
        }
        if (!od::isWritable(e->access)) {
            abortMux(r.index, r.sub, sdoabort::ReadOnly);
            return;
        }
        index_ = r.index;
        sub_ = r.sub;
        buffer_.clear();
        sizeIndicated_ = r.sizeIndicated;
        expectedSize_ = r.size;
        crc_ = r.crcSupported;
        blockSize_ = kServerBlockSize;
        seq_ = 0;
        lastSegmentSeen_ = false;
        phase_ = Phase::BlockDownloadSub;
        // scs 5, sc 1 (server does CRC), ss 0; byte 4 blksize (CiA 301 §7.2.4.3.9).
        respond(frame8({0xA4, uint8_t(r.index), uint8_t(r.index >> 8), r.sub, blockSize_}));
        return;
    }
    case SdoCommand::BlockSegment: {
        if (phase_ != Phase::BlockDownloadSub) return;
        if (r.seqno == seq_ + 1) {
            ++seq_;
            buffer_.append(r.data.left(7));
            if (r.last) lastSegmentSeen_ = true;
            if (faults.abortDownloadAfter && buffer_.size() >= faults.abortDownloadAfter->first) {
                abort(faults.abortDownloadAfter->second);
                return;
            }
        }
        // End of the sub-block: blksize segments or the last one; ackseq = last in-order segment.
        if (r.seqno >= blockSize_ || r.last) {
            const uint8_t ack = seq_;
            respond(frame8({0xA2, ack, blockSize_}));
            seq_ = 0;
            if (lastSegmentSeen_ && r.last && r.seqno == ack) phase_ = Phase::BlockDownloadEnd;
            else lastSegmentSeen_ = false;
        }
        return;
    }
    case SdoCommand::BlockDownloadEnd: {
        if (phase_ != Phase::BlockDownloadEnd) {
            abort(sdoabort::InvalidCommand);
            return;
        }
        buffer_.chop(std::min<qsizetype>(r.unusedBytes, buffer_.size()));
        if (sizeIndicated_ && uint32_t(buffer_.size()) != expectedSize_) {
            abort(uint32_t(buffer_.size()) > expectedSize_ ? sdoabort::LengthTooHigh : sdoabort::LengthTooLow);
            return;
        }
        const uint16_t crc = sdoBlockCrc(reinterpret_cast<const uint8_t*>(buffer_.constData()), size_t(buffer_.size()));
        if (faults.blockCrcError || (crc_ && crc != r.crc)) {
            faults.blockCrcError = false;
            abort(sdoabort::CrcError);
            return;
        }
        if (const uint32_t code = dev_.writeFromSdo(index_, sub_, buffer_)) {
            abort(code);
            return;
        }
        phase_ = Phase::Idle;
        buffer_.clear();
        respond(frame8({0xA1}));
        return;
    }
    case SdoCommand::BlockUploadInitiate: {
        if (faults.declineBlock) {
            abortMux(r.index, r.sub, sdoabort::InvalidCommand);
            return;
        }
        if (r.blockSize < 1 || r.blockSize > 127) {
            abortMux(r.index, r.sub, sdoabort::InvalidBlockSize);
            return;
        }
        startBlockUpload(r.index, r.sub, r.blockSize, r.protocolSwitch, r.crcSupported);
        return;
    }
    case SdoCommand::BlockUploadStart:
        if (phase_ != Phase::BlockUploadInitiated) {
            abort(sdoabort::InvalidCommand);
            return;
        }
        phase_ = Phase::BlockUploadSub;
        sendSubBlock();
        return;
    case SdoCommand::BlockUploadAck: {
        if (phase_ != Phase::BlockUploadSub) {
            abort(sdoabort::InvalidCommand);
            return;
        }
        if (r.blockSize < 1 || r.blockSize > 127) {
            abort(sdoabort::InvalidBlockSize);
            return;
        }
        // Segments up to ackseq arrived; the rest of the sub-block is sent again (§7.2.4.3.13).
        offset_ = std::min<int>(subBlockStart_ + r.ackSeq * 7, static_cast<int>(buffer_.size()));
        blockSize_ = r.blockSize;
        const int segmentsTotal = buffer_.isEmpty() ? 1 : static_cast<int>((buffer_.size() + 6) / 7);
        const int acked = (subBlockStart_ / 7) + r.ackSeq;
        if (acked >= segmentsTotal) {
            const int lastLen = buffer_.isEmpty() ? 0 : static_cast<int>(buffer_.size() - (segmentsTotal - 1) * 7);
            uint16_t crc =
                crc_ ? sdoBlockCrc(reinterpret_cast<const uint8_t*>(buffer_.constData()), size_t(buffer_.size())) : 0;
            if (faults.blockCrcError) {
                faults.blockCrcError = false;
                crc = static_cast<uint16_t>(crc ^ 0x5A5A);
            }
            phase_ = Phase::BlockUploadEnd;
            // scs 6, n unused bytes of the last segment, ss 1; bytes 1-2 CRC (§7.2.4.3.14).
            respond(frame8({static_cast<uint8_t>(0xC1 | ((7 - lastLen) << 2)), uint8_t(crc), uint8_t(crc >> 8)}));
            return;
        }
        sendSubBlock();
        return;
    }
    case SdoCommand::BlockUploadEndResponse:
        if (phase_ == Phase::BlockUploadEnd) {
            phase_ = Phase::Idle;
            buffer_.clear();
        }
        return;
    default: abort(sdoabort::InvalidCommand); return;
    }
}

void SdoServer::startUpload(uint16_t index, uint8_t sub) {
    index_ = index;
    sub_ = sub;
    uint32_t code = 0;
    auto data = dev_.readForSdo(index, sub, &code);
    if (!data) {
        abortMux(index, sub, code);
        return;
    }
    if (!data->isEmpty() && data->size() <= 4) {
        phase_ = Phase::Idle;
        respond(sdo::initiateUploadResponse(dev_.nodeId(), index, sub, *data));
        return;
    }
    buffer_ = *data;
    offset_ = 0;
    toggle_ = false;
    phase_ = Phase::UploadSegments;
    respond(sdo::initiateUploadResponse(dev_.nodeId(), index, sub, buffer_));
}

void SdoServer::startBlockUpload(uint16_t index, uint8_t sub, uint8_t blockSize, uint8_t pst, bool crc) {
    uint32_t code = 0;
    auto data = dev_.readForSdo(index, sub, &code);
    if (!data) {
        abortMux(index, sub, code);
        return;
    }
    // Protocol switch threshold: at most pst bytes go by segmented/expedited upload (§7.2.4.3.11).
    if (pst > 0 && data->size() <= pst) {
        startUpload(index, sub);
        return;
    }
    index_ = index;
    sub_ = sub;
    buffer_ = *data;
    offset_ = subBlockStart_ = 0;
    blockSize_ = blockSize;
    crc_ = crc;
    phase_ = Phase::BlockUploadInitiated;
    // scs 6, sc 1, s 1, ss 0; bytes 4-7 size.
    const auto n = static_cast<uint32_t>(buffer_.size());
    respond(frame8({0xC6, uint8_t(index), uint8_t(index >> 8), sub, uint8_t(n), uint8_t(n >> 8), uint8_t(n >> 16),
                    uint8_t(n >> 24)}));
}

void SdoServer::sendSubBlock() {
    subBlockStart_ = offset_;
    int pos = offset_;
    for (uint8_t seq = 1; seq <= blockSize_; ++seq) {
        const int n = std::min<int>(7, static_cast<int>(buffer_.size()) - pos);
        const bool last = pos + n >= buffer_.size();
        CanFrame f = frame8({static_cast<uint8_t>((last ? 0x80 : 0) | seq)});
        for (int i = 0; i < n; ++i) f.data[1 + static_cast<size_t>(i)] = static_cast<uint8_t>(buffer_[pos + i]);
        respond(f);
        pos += n;
        if (last) break;
    }
}

}  // namespace coscope::sim
