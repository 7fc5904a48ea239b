// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/SyncProducer.h"

#include "core/canopen/SdoClient.h"

#include <atomic>
#include <mutex>

namespace coscope::canopen {

namespace {

// 1005h (CiA 301 §7.5.2.5): bit 29 frame (0 = 11-bit, 1 = 29-bit CAN-ID), bit 30 gen.
constexpr uint32_t kFrameBit = 1u << 29;
constexpr uint32_t kId29Mask = 0x1FFFFFFF;
constexpr uint32_t kId11Mask = 0x7FF;

CanFrame syncFrame(uint32_t cobId1005h, uint8_t counter) {
    CanFrame f;
    if (cobId1005h & kFrameBit) {
        f.id = cobId1005h & kId29Mask;
        f.flags |= CanFrame::Extended;
    } else {
        f.id = cobId1005h & kId11Mask;
    }
    if (counter) {  // with a counter the SYNC carries one byte (CiA 301 §7.2.5.2.1)
        f.len = 1;
        f.data[0] = counter;
    }
    return f;
}

}  // namespace

// What the maker on the sender thread reads; the owner's thread writes it.
struct SyncProducer::Shared {
    std::atomic<uint32_t> cobId{0x80};
    std::atomic<uint8_t> overflow{0};
    std::atomic<bool> restartCounter{false};
    uint8_t counter = 1;  // sender thread only (and start() while no job runs)
    std::mutex hookMutex;
    PeriodicSender::AfterSend onEachSync;
};

SyncProducer::SyncProducer(MasterContext& context, QObject* parent)
    : QObject(parent), context_(context), shared_(std::make_shared<Shared>()) {}

SyncProducer::~SyncProducer() { stopJob(); }

bool SyncProducer::setCobId(uint32_t cobId1005h) {
    if (!(cobId1005h & kFrameBit) && (cobId1005h & kId29Mask & ~kId11Mask)) return false;
    cobId_ = cobId1005h & (kFrameBit | kId29Mask);
    shared_->cobId = cobId_;
    return true;
}

void SyncProducer::setPeriodUs(uint32_t us) {
    periodUs_ = us;
    if (job_ && us > 0) context_.periodic().setPeriod(job_, int64_t{us} * 1000);
}

bool SyncProducer::setCounterOverflow(uint8_t overflow) {
    if (overflow == 1 || overflow > 240) return false;  // CiA 301 §7.5.2.22: 1 and 241..255 reserved
    overflow_ = overflow;
    shared_->overflow = overflow;
    shared_->restartCounter = true;
    return true;
}

void SyncProducer::setOnEachSync(PeriodicSender::AfterSend hook) {
    std::lock_guard lock(shared_->hookMutex);
    shared_->onEachSync = std::move(hook);
}

CanFrame SyncProducer::frame(uint8_t counter) const { return syncFrame(cobId_, counter); }

bool SyncProducer::start(QString* error, uint64_t count) {
    if (periodUs_ == 0) {
        if (error) *error = QStringLiteral("SYNC period is 0");
        return false;
    }
    stopJob();
    shared_->counter = 1;
    shared_->restartCounter = false;
    PeriodicSender::Job job;
    job.periodNs = int64_t{periodUs_} * 1000;
    job.count = count;
    job.maker = [s = shared_] {
        if (s->restartCounter.exchange(false)) s->counter = 1;
        const uint8_t overflow = s->overflow;
        const CanFrame f = syncFrame(s->cobId, overflow ? s->counter : 0);
        // Counter 1..overflow, then 1 again (CiA 301 §7.2.5.2.1).
        if (overflow) s->counter = s->counter >= overflow ? 1 : static_cast<uint8_t>(s->counter + 1);
        return f;
    };
    job.afterSend = [s = shared_](const CanFrame& f, uint64_t sent) {
        PeriodicSender::AfterSend hook;
        {
            std::lock_guard lock(s->hookMutex);
            hook = s->onEachSync;
        }
        if (hook) hook(f, sent);
    };
    job.onStopped = [this](const QString& why) {
        if (!why.isEmpty())
            QMetaObject::invokeMethod(
                this, [this, why] { emit stoppedOnError(why); }, Qt::QueuedConnection);
    };
    job_ = context_.periodic().add(std::move(job), error);
    return job_ != 0;
}

void SyncProducer::stop() { stopJob(); }

void SyncProducer::stopJob() {
    if (!job_) return;
    // The job (stopped or not) goes; its count and error stay here.
    const PeriodicSender::Status s = context_.periodic().take(job_);
    sentBefore_ += s.sent;
    lastError_ = s.error;
    job_ = 0;
}

bool SyncProducer::isRunning() const { return job_ && context_.periodic().status(job_).running; }

uint64_t SyncProducer::sent() const { return sentBefore_ + (job_ ? context_.periodic().status(job_).sent : 0); }

QString SyncProducer::lastError() const { return job_ ? context_.periodic().status(job_).error : lastError_; }

void SyncProducer::writeCommunicationCyclePeriod(SdoClient& sdo, uint8_t node,
                                                 std::function<void(const SdoResult&)> done) const {
    QByteArray v(4, 0);
    for (int i = 0; i < 4; ++i) v[i] = static_cast<char>(periodUs_ >> (8 * i));
    sdo.download(node, 0x1006, 0, v, std::move(done));
}

}  // namespace coscope::canopen
