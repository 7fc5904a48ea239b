// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/SdoClient.h"

#include "core/canopen/Sdo.h"
#include "core/canopen/SdoAbort.h"
#include "core/canopen/SdoBlockFrames.h"

#include <QCoreApplication>
#include <QTimer>

#include <spdlog/spdlog.h>

#include <algorithm>

namespace coscope::canopen {

QString objectRef(uint16_t index, uint8_t sub) {
    return QStringLiteral("%1:%2").arg(index, 4, 16, QChar(u'0')).arg(sub, 2, 16, QChar(u'0')).toUpper();
}

// Where a transfer is (not in an anonymous namespace: SdoClient::Transfer holds one).
enum class SdoClientPhase : uint8_t {
    UploadInitiate,
    UploadSegment,
    DownloadInitiate,
    DownloadSegment,
    BlockUploadInitiate,
    BlockUploadSub,
    BlockUploadEnd,
    BlockDownloadInitiate,
    BlockDownloadSub,
    BlockDownloadEnd,
};
namespace {
using Phase = SdoClientPhase;
constexpr int kSegment = 7;  // data bytes per segment (CiA 301 §7.2.4.3.4, §7.2.4.3.12)
}  // namespace

struct SdoClient::Transfer {
    SdoResult result;
    QByteArray data;  // download: what to write; upload: what arrived so far
    SdoCallback done;
    SdoOptions options;
    Phase phase = Phase::UploadInitiate;
    bool toggle = false;
    qsizetype offset = 0;  // download: bytes confirmed / sent
    bool sizeKnown = false;
    uint32_t size = 0;
    bool crc = false;       // both sides agreed on CRC
    uint8_t blockSize = 0;  // segments per sub-block
    uint8_t seq = 0;        // block: last good seqno received (upload) / sent (download)
    bool lastSent = false;  // block download: this sub-block holds the last segment
};

struct SdoClient::NodeQueue {
    uint8_t node = 0;
    std::deque<std::unique_ptr<Transfer>> waiting;
    std::unique_ptr<Transfer> active;
    QTimer* timer = nullptr;
};

SdoClient::SdoClient(MasterContext& context, QObject* parent) : QObject(parent), context_(context) {
    subscription_ =
        context_.dispatcher().subscribe(this, {}, [this](const std::vector<CanFrame>& frames) { onFrames(frames); });
}

SdoClient::~SdoClient() { context_.dispatcher().unsubscribe(subscription_); }

quint64 SdoClient::upload(uint8_t node, uint16_t index, uint8_t sub, SdoCallback done, SdoOptions options) {
    auto t = std::make_unique<Transfer>();
    t->result.upload = true;
    t->result.node = node;
    t->result.index = index;
    t->result.sub = sub;
    t->done = std::move(done);
    t->options = options;
    return enqueue(std::move(t));
}

quint64 SdoClient::download(uint8_t node, uint16_t index, uint8_t sub, QByteArray data, SdoCallback done,
                            SdoOptions options) {
    auto t = std::make_unique<Transfer>();
    t->result.upload = false;
    t->result.node = node;
    t->result.index = index;
    t->result.sub = sub;
    t->data = std::move(data);
    t->done = std::move(done);
    t->options = options;
    return enqueue(std::move(t));
}

quint64 SdoClient::enqueue(std::unique_ptr<Transfer> t) {
    const uint8_t node = t->result.node;
    t->result.id = nextId_++;
    const quint64 id = t->result.id;
    auto& slot = queues_[node];
    if (!slot) {
        slot = std::make_unique<NodeQueue>();
        slot->node = node;
        slot->timer = new QTimer(this);
        slot->timer->setSingleShot(true);
        slot->timer->setTimerType(Qt::PreciseTimer);  // a coarse timer may fire 5% early
        connect(slot->timer, &QTimer::timeout, this, [this, node] { onTimeout(node); });
    }
    if (node < 1 || node > 127) {
        // Rejected before anything is sent; reported asynchronously like every other outcome.
        SdoResult r = t->result;
        r.error = QStringLiteral("node-ID %1 is outside 1-127").arg(node);
        SdoCallback done = std::move(t->done);
        QMetaObject::invokeMethod(
            this,
            [done, r] {
                if (done) done(r);
            },
            Qt::QueuedConnection);
        return id;
    }
    slot->waiting.push_back(std::move(t));
    // Start from the event loop so the caller has the id before any callback can run.
    QMetaObject::invokeMethod(
        this, [this, node] { pump(node); }, Qt::QueuedConnection);
    return id;
}

int SdoClient::pendingCount() const {
    int n = 0;
    for (const auto& [node, q] : queues_) n += static_cast<int>(q->waiting.size()) + (q->active ? 1 : 0);
    return n;
}

void SdoClient::cancelAll() {
    for (auto& [node, q] : queues_) {
        auto waiting = std::move(q->waiting);
        q->waiting.clear();
        if (q->active) abortTransfer(*q, sdoabort::GeneralError, QStringLiteral("cancelled"));
        for (auto& t : waiting) {
            t->result.error = QStringLiteral("node %1 %2 %3: cancelled")
                                  .arg(t->result.node)
                                  .arg(t->result.upload ? QStringLiteral("read") : QStringLiteral("write"),
                                       objectRef(t->result.index, t->result.sub));
            if (t->done) t->done(t->result);
        }
    }
}

bool SdoClient::cancel(quint64 id) {
    for (auto& [node, q] : queues_) {
        if (q->active && q->active->result.id == id) {
            abortTransfer(*q, sdoabort::GeneralError, QStringLiteral("cancelled"));
            return true;
        }
        for (auto it = q->waiting.begin(); it != q->waiting.end(); ++it) {
            if ((*it)->result.id != id) continue;
            std::unique_ptr<Transfer> t = std::move(*it);
            q->waiting.erase(it);
            t->result.error = QStringLiteral("node %1 %2 %3: cancelled")
                                  .arg(t->result.node)
                                  .arg(t->result.upload ? QStringLiteral("read") : QStringLiteral("write"),
                                       objectRef(t->result.index, t->result.sub));
            if (t->done) t->done(t->result);
            return true;
        }
    }
    return false;
}

void SdoClient::pump(uint8_t node) {
    auto it = queues_.find(node);
    if (it == queues_.end()) return;
    NodeQueue& q = *it->second;
    if (q.active || q.waiting.empty()) return;
    q.active = std::move(q.waiting.front());
    q.waiting.pop_front();
    updateSubscription();
    start(q);
}

void SdoClient::updateSubscription() {
    std::vector<uint32_t> ids;
    for (const auto& [node, q] : queues_)
        if (q->active) ids.push_back(0x580u + node);
    if (ids == subscribedIds_) return;
    subscribedIds_ = ids;
    context_.dispatcher().setCobIds(subscription_, std::move(ids));
}

void SdoClient::start(NodeQueue& q) {
    Transfer& t = *q.active;
    const bool block = t.options.protocol == SdoOptions::Protocol::Block;
    if (t.result.upload) {
        if (!block) return startUploadSegmented(q);
        t.phase = Phase::BlockUploadInitiate;
        t.blockSize = std::clamp<uint8_t>(t.options.blockSize, 1, 127);
        sendStep(q, sdo::blockUploadInitiate(q.node, t.result.index, t.result.sub, t.blockSize));
    } else {
        if (!block) return startDownloadSegmented(q);
        t.phase = Phase::BlockDownloadInitiate;
        sendStep(
            q, sdo::blockDownloadInitiate(q.node, t.result.index, t.result.sub, static_cast<uint32_t>(t.data.size())));
    }
}

void SdoClient::startUploadSegmented(NodeQueue& q) {
    Transfer& t = *q.active;
    t.phase = Phase::UploadInitiate;
    t.data.clear();
    sendStep(q, sdo::initiateUpload(q.node, t.result.index, t.result.sub));
}

void SdoClient::startDownloadSegmented(NodeQueue& q) {
    Transfer& t = *q.active;
    t.phase = Phase::DownloadInitiate;
    t.offset = 0;
    t.toggle = false;
    sendStep(q, sdo::initiateDownload(q.node, t.result.index, t.result.sub, t.data));
}

bool SdoClient::sendStep(NodeQueue& q, const CanFrame& frame) {
    QString error;
    if (!context_.send(frame, &error)) {
        finish(q, false, error);
        return false;
    }
    ++q.active->result.framesSent;
    armTimer(q);
    return true;
}

void SdoClient::armTimer(NodeQueue& q) {
    const int ms = q.active->options.timeoutMs > 0 ? q.active->options.timeoutMs : defaultTimeoutMs_;
    q.timer->start(ms);
}

void SdoClient::onFrames(const std::vector<CanFrame>& frames) {
    for (const CanFrame& f : frames) {
        if (f.id < 0x581 || f.id > 0x5FF) continue;
        auto it = queues_.find(static_cast<uint8_t>(f.id - 0x580));
        if (it == queues_.end() || !it->second->active) continue;  // late answer to a finished transfer
        onFrame(*it->second, f);
    }
}

void SdoClient::onFrame(NodeQueue& q, const CanFrame& frame) {
    Transfer& t = *q.active;
    ++t.result.framesReceived;
    switch (t.phase) {
    case Phase::BlockUploadInitiate:
    case Phase::BlockUploadSub:
    case Phase::BlockUploadEnd: return handleBlockUpload(q, frame);
    case Phase::BlockDownloadInitiate:
    case Phase::BlockDownloadSub:
    case Phase::BlockDownloadEnd: return handleBlockDownload(q, frame);
    default: return handleSegmented(q, frame);
    }
}

void SdoClient::handleSegmented(NodeQueue& q, const CanFrame& frame) {
    Transfer& t = *q.active;
    const SdoFrame f = parseSdo(frame.data.data(), frame.len, false);
    if (f.command == SdoCommand::Abort) return serverAbort(q, f.abortCode);
    const auto muxMismatch = [&] { return f.index != t.result.index || f.sub != t.result.sub; };
    switch (t.phase) {
    case Phase::UploadInitiate:
        if (f.command != SdoCommand::InitiateUploadResponse) break;
        if (muxMismatch())
            return abortTransfer(q, sdoabort::GeneralError,
                                 QStringLiteral("the server answered for %1").arg(objectRef(f.index, f.sub)));
        if (f.expedited) {
            t.data = f.data;
            return finish(q, true);
        }
        t.sizeKnown = f.sizeIndicated;
        t.size = f.size;
        t.toggle = false;
        t.phase = Phase::UploadSegment;
        sendStep(q, sdo::uploadSegmentRequest(q.node, false));
        return;
    case Phase::UploadSegment:
        if (f.command != SdoCommand::UploadSegmentResponse) break;
        if (f.toggle != t.toggle)
            return abortTransfer(q, sdoabort::ToggleBit,
                                 QStringLiteral("toggle bit not alternated in an upload segment"));
        t.data.append(f.data);
        if (t.sizeKnown && static_cast<uint32_t>(t.data.size()) > t.size)
            return abortTransfer(q, sdoabort::LengthTooHigh,
                                 QStringLiteral("the server sent %1 bytes, more than the %2 it announced")
                                     .arg(t.data.size())
                                     .arg(t.size));
        if (f.last) {
            if (t.sizeKnown && static_cast<uint32_t>(t.data.size()) != t.size)
                return abortTransfer(
                    q, sdoabort::LengthTooLow,
                    QStringLiteral("the server sent %1 bytes of the %2 it announced").arg(t.data.size()).arg(t.size));
            return finish(q, true);
        }
        t.toggle = !t.toggle;
        sendStep(q, sdo::uploadSegmentRequest(q.node, t.toggle));
        return;
    case Phase::DownloadInitiate:
        if (f.command != SdoCommand::InitiateDownloadResponse) break;
        if (muxMismatch())
            return abortTransfer(q, sdoabort::GeneralError,
                                 QStringLiteral("the server answered for %1").arg(objectRef(f.index, f.sub)));
        if (!t.data.isEmpty() && t.data.size() <= 4) return finish(q, true);  // expedited
        t.phase = Phase::DownloadSegment;
        t.toggle = false;
        sendNextDownloadSegment(q);
        return;
    case Phase::DownloadSegment:
        if (f.command != SdoCommand::DownloadSegmentResponse) break;
        if (f.toggle != t.toggle)
            return abortTransfer(q, sdoabort::ToggleBit,
                                 QStringLiteral("toggle bit not alternated in a download segment response"));
        if (t.options.progress) t.options.progress(std::min(t.offset, t.data.size()), t.data.size());
        if (t.offset >= t.data.size()) return finish(q, true);
        t.toggle = !t.toggle;
        sendNextDownloadSegment(q);
        return;
    default: break;
    }
    abortTransfer(q, sdoabort::InvalidCommand,
                  QStringLiteral("unexpected %1 from the server").arg(sdoCommandName(f.command)));
}

void SdoClient::sendNextDownloadSegment(NodeQueue& q) {
    Transfer& t = *q.active;
    const QByteArray chunk = t.data.mid(t.offset, kSegment);
    t.offset += chunk.size();
    const bool last = t.offset >= t.data.size();
    if (last) t.offset = t.data.size() + (chunk.isEmpty() ? 1 : 0);  // an empty value still needs its one segment
    sendStep(q, sdo::downloadSegment(q.node, t.toggle, chunk, last));
}

void SdoClient::handleBlockUpload(NodeQueue& q, const CanFrame& frame) {
    Transfer& t = *q.active;
    // In a sub-block every frame is a segment except an abort (byte 0 = 80h: seqno 0 is invalid).
    const bool inSub = t.phase == Phase::BlockUploadSub && frame.data[0] != 0x80;
    const SdoFrame f = parseSdo(frame.data.data(), frame.len, false, inSub);
    if (f.command == SdoCommand::Abort) {
        if (t.phase == Phase::BlockUploadInitiate && f.abortCode == sdoabort::InvalidCommand) {
            // The server does not do block transfer: nothing moved yet, so go on segmented.
            spdlog::info("SDO node {} {}: block upload declined, using segmented upload", q.node,
                         objectRef(t.result.index, t.result.sub).toStdString());
            t.result.fellBackToSegmented = true;
            return startUploadSegmented(q);
        }
        return serverAbort(q, f.abortCode);
    }
    switch (t.phase) {
    case Phase::BlockUploadInitiate:
        if (f.command == SdoCommand::InitiateUploadResponse) {  // protocol switch by the server (pst)
            t.phase = Phase::UploadInitiate;
            return handleSegmented(q, frame);
        }
        if (f.command != SdoCommand::BlockUploadInitiateResponse) break;
        if (f.index != t.result.index || f.sub != t.result.sub)
            return abortTransfer(q, sdoabort::GeneralError,
                                 QStringLiteral("the server answered for %1").arg(objectRef(f.index, f.sub)));
        t.crc = f.crcSupported;
        t.sizeKnown = f.sizeIndicated;
        t.size = f.size;
        t.seq = 0;
        t.data.clear();
        t.phase = Phase::BlockUploadSub;
        sendStep(q, sdo::blockUploadStart(q.node));
        return;
    case Phase::BlockUploadSub: {
        if (f.command != SdoCommand::BlockSegment) break;
        const bool inOrder = f.seqno == t.seq + 1;
        if (inOrder) {
            t.seq = f.seqno;
            t.data.append(f.data);
        }
        const bool endOfSubBlock = f.seqno >= t.blockSize || f.last;
        if (!endOfSubBlock) {
            armTimer(q);
            return;
        }
        // Acknowledge the last segment received in order; the server repeats the rest
        // (CiA 301 §7.2.4.3.14).
        const bool done = f.last && inOrder;
        const uint8_t ack = t.seq;
        t.seq = 0;
        if (done) t.phase = Phase::BlockUploadEnd;
        sendStep(q, sdo::blockUploadAck(q.node, ack, t.blockSize));
        return;
    }
    case Phase::BlockUploadEnd: {
        if (f.command != SdoCommand::BlockUploadEnd) break;
        if (f.unusedBytes > t.data.size())
            return abortTransfer(q, sdoabort::InvalidCommand,
                                 QStringLiteral("block end says %1 unused bytes").arg(f.unusedBytes));
        t.data.chop(f.unusedBytes);
        if (t.crc) {
            const uint16_t crc =
                sdoBlockCrc(reinterpret_cast<const uint8_t*>(t.data.constData()), static_cast<size_t>(t.data.size()));
            if (crc != f.crc)
                return abortTransfer(q, sdoabort::CrcError,
                                     QStringLiteral("CRC error: the server sent %1, the data gives %2")
                                         .arg(f.crc, 4, 16, QChar(u'0'))
                                         .arg(crc, 4, 16, QChar(u'0')));
        }
        if (t.sizeKnown && static_cast<uint32_t>(t.data.size()) != t.size)
            return abortTransfer(
                q, t.data.size() > t.size ? sdoabort::LengthTooHigh : sdoabort::LengthTooLow,
                QStringLiteral("the server sent %1 bytes of the %2 it announced").arg(t.data.size()).arg(t.size));
        QString error;
        if (!context_.send(sdo::blockUploadEndResponse(q.node), &error)) return finish(q, false, error);
        ++t.result.framesSent;
        return finish(q, true);
    }
    default: break;
    }
    abortTransfer(q, sdoabort::InvalidCommand,
                  QStringLiteral("unexpected %1 from the server").arg(sdoCommandName(f.command)));
}

void SdoClient::sendDownloadSubBlock(NodeQueue& q) {
    Transfer& t = *q.active;
    qsizetype at = t.offset;
    t.seq = 0;
    t.lastSent = false;
    for (uint8_t s = 1; s <= t.blockSize; ++s) {
        const int len = static_cast<int>(std::min<qsizetype>(kSegment, t.data.size() - at));
        const bool last = at + kSegment >= t.data.size();
        if (!sendStep(q, sdo::blockSegment(q.node, s, last, t.data.constData() + at, std::max(len, 0)))) return;
        at += std::max(len, 0);
        t.seq = s;
        if (last) {
            t.lastSent = true;
            break;
        }
    }
}

void SdoClient::handleBlockDownload(NodeQueue& q, const CanFrame& frame) {
    Transfer& t = *q.active;
    const SdoFrame f = parseSdo(frame.data.data(), frame.len, false);
    if (f.command == SdoCommand::Abort) {
        if (t.phase == Phase::BlockDownloadInitiate && f.abortCode == sdoabort::InvalidCommand) {
            // Declined before any data was sent: the write goes segmented (it is not a retry).
            spdlog::info("SDO node {} {}: block download declined, using segmented download", q.node,
                         objectRef(t.result.index, t.result.sub).toStdString());
            t.result.fellBackToSegmented = true;
            return startDownloadSegmented(q);
        }
        return serverAbort(q, f.abortCode);
    }
    switch (t.phase) {
    case Phase::BlockDownloadInitiate:
        if (f.command != SdoCommand::BlockDownloadInitiateResponse) break;
        if (f.index != t.result.index || f.sub != t.result.sub)
            return abortTransfer(q, sdoabort::GeneralError,
                                 QStringLiteral("the server answered for %1").arg(objectRef(f.index, f.sub)));
        if (f.blockSize < 1 || f.blockSize > 127)
            return abortTransfer(q, sdoabort::InvalidBlockSize,
                                 QStringLiteral("invalid block size %1").arg(f.blockSize));
        t.crc = f.crcSupported;
        t.blockSize = f.blockSize;
        t.offset = 0;
        t.phase = Phase::BlockDownloadSub;
        sendDownloadSubBlock(q);
        return;
    case Phase::BlockDownloadSub: {
        if (f.command != SdoCommand::BlockDownloadAck) break;
        if (f.ackSeq > t.seq)
            return abortTransfer(q, sdoabort::InvalidSequence,
                                 QStringLiteral("acknowledged segment %1 of %2 sent").arg(f.ackSeq).arg(t.seq));
        const bool allAcked = t.lastSent && f.ackSeq == t.seq;
        t.offset = std::min<qsizetype>(t.offset + qsizetype(f.ackSeq) * kSegment, t.data.size());
        if (t.options.progress) t.options.progress(t.offset, t.data.size());
        if (allAcked) {
            const qsizetype size = t.data.size();
            const int lastLen = size == 0 ? 0 : static_cast<int>((size - 1) % kSegment) + 1;
            const uint16_t crc =
                t.crc ? sdoBlockCrc(reinterpret_cast<const uint8_t*>(t.data.constData()), static_cast<size_t>(size))
                      : 0;
            t.phase = Phase::BlockDownloadEnd;
            sendStep(q, sdo::blockDownloadEnd(q.node, static_cast<uint8_t>(kSegment - lastLen), crc));
            return;
        }
        if (f.blockSize < 1 || f.blockSize > 127)
            return abortTransfer(q, sdoabort::InvalidBlockSize,
                                 QStringLiteral("invalid block size %1").arg(f.blockSize));
        t.blockSize = f.blockSize;
        sendDownloadSubBlock(q);
        return;
    }
    case Phase::BlockDownloadEnd:
        if (f.command != SdoCommand::BlockDownloadEndResponse) break;
        return finish(q, true);
    default: break;
    }
    abortTransfer(q, sdoabort::InvalidCommand,
                  QStringLiteral("unexpected %1 from the server").arg(sdoCommandName(f.command)));
}

void SdoClient::onTimeout(uint8_t node) {
    auto it = queues_.find(node);
    if (it == queues_.end() || !it->second->active) return;
    // The answer may be waiting in this thread's queue already: a thread that was busy for longer
    // than the timeout (a slow machine, a sanitizer build, a long repaint) sees the timer and the
    // answer together, and may take the timer first. The timeout is about the server, not about
    // us: deliver what has arrived, then decide.
    const Transfer* waiting = it->second->active.get();
    QCoreApplication::sendPostedEvents(this, QEvent::MetaCall);
    it = queues_.find(node);
    if (it == queues_.end() || it->second->active.get() != waiting || it->second->timer->isActive())
        return;  // answered
    NodeQueue& q = *it->second;
    Transfer& t = *q.active;
    const int ms = t.options.timeoutMs > 0 ? t.options.timeoutMs : defaultTimeoutMs_;
    t.result.timedOut = true;
    t.result.abortCode = sdoabort::Timeout;
    QString ignored;
    context_.send(sdo::abortFromClient(node, t.result.index, t.result.sub, sdoabort::Timeout), &ignored);
    finish(q, false,
           QStringLiteral("node %1 did not answer %2 %3 within %4 ms (SDO protocol timed out, 0x05040000)")
               .arg(node)
               .arg(t.result.upload ? QStringLiteral("read of") : QStringLiteral("write of"),
                    objectRef(t.result.index, t.result.sub))
               .arg(ms));
}

void SdoClient::serverAbort(NodeQueue& q, uint32_t code) {
    Transfer& t = *q.active;
    t.result.abortCode = code;
    t.result.serverAborted = true;
    finish(q, false,
           QStringLiteral("node %1 aborted %2: %3")
               .arg(q.node)
               .arg(objectRef(t.result.index, t.result.sub), context_.abortText(q.node, code)));
}

void SdoClient::abortTransfer(NodeQueue& q, uint32_t code, const QString& why) {
    Transfer& t = *q.active;
    t.result.abortCode = code;
    QString ignored;
    if (context_.send(sdo::abortFromClient(q.node, t.result.index, t.result.sub, code), &ignored))
        ++t.result.framesSent;
    finish(q, false,
           QStringLiteral("node %1 %2 %3: %4; transfer aborted with 0x%5")
               .arg(q.node)
               .arg(t.result.upload ? QStringLiteral("read") : QStringLiteral("write"),
                    objectRef(t.result.index, t.result.sub), why)
               .arg(QStringLiteral("%1").arg(code, 8, 16, QChar(u'0')).toUpper()));
}

void SdoClient::finish(NodeQueue& q, bool ok, const QString& error) {
    q.timer->stop();
    std::unique_ptr<Transfer> t = std::move(q.active);
    t->result.ok = ok;
    if (ok && t->result.upload) t->result.data = t->data;
    if (!ok) {
        t->result.error = error.startsWith(QStringLiteral("node "))
                              ? error
                              : QStringLiteral("node %1 %2 %3: %4")
                                    .arg(q.node)
                                    .arg(t->result.upload ? QStringLiteral("read") : QStringLiteral("write"),
                                         objectRef(t->result.index, t->result.sub), error);
        spdlog::debug("SDO {}", t->result.error.toStdString());
    }
    updateSubscription();
    const uint8_t node = q.node;
    if (ok && !t->result.upload) emit written(node, t->result.index, t->result.sub, t->data);
    if (t->done) t->done(t->result);
    pump(node);
}

}  // namespace coscope::canopen
