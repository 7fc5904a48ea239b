// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/HeartbeatProducer.h"

namespace coscope::canopen {

namespace {

constexpr uint8_t kOperational = 0x05;  // CiA 301 §7.2.8.3.2 Table 54

CanFrame heartbeatFrame(uint8_t node, uint8_t state) {
    CanFrame f;
    f.id = 0x700u + node;  // NMT error control, CiA 301 §7.3.2 Table 43 (predefined connection set)
    f.len = 1;
    f.data[0] = state & 0x7F;  // bit 7 is the guarding toggle; 0 in a heartbeat
    return f;
}

}  // namespace

struct HeartbeatProducer::Shared {
    std::atomic<uint8_t> node{HeartbeatProducer::kDefaultNodeId};
    std::atomic<uint8_t> state{kOperational};
};

HeartbeatProducer::HeartbeatProducer(MasterContext& context) : context_(context), shared_(std::make_shared<Shared>()) {}

HeartbeatProducer::~HeartbeatProducer() { stopJob(); }

bool HeartbeatProducer::setNodeId(uint8_t node) {
    if (node < 1 || node > 127) return false;
    node_ = node;
    shared_->node = node;
    return true;
}

bool HeartbeatProducer::setPeriodMs(uint16_t ms) {
    if (ms == 0) return false;  // 1017h = 0 means "not used"
    periodMs_ = ms;
    if (job_) context_.periodic().setPeriod(job_, int64_t{ms} * 1'000'000);
    return true;
}

void HeartbeatProducer::setState(uint8_t nmtState) { shared_->state = nmtState; }

uint8_t HeartbeatProducer::state() const { return shared_->state; }

CanFrame HeartbeatProducer::frame() const { return heartbeatFrame(shared_->node, shared_->state); }

bool HeartbeatProducer::start(QString* error) {
    stopJob();
    PeriodicSender::Job job;
    job.periodNs = int64_t{periodMs_} * 1'000'000;
    job.maker = [s = shared_] { return heartbeatFrame(s->node, s->state); };
    job_ = context_.periodic().add(std::move(job), error);
    return job_ != 0;
}

void HeartbeatProducer::stop() { stopJob(); }

void HeartbeatProducer::stopJob() {
    if (!job_) return;
    const PeriodicSender::Status s = context_.periodic().take(job_);
    sentBefore_ += s.sent;
    lastError_ = s.error;
    job_ = 0;
}

bool HeartbeatProducer::isRunning() const { return job_ && context_.periodic().status(job_).running; }

uint64_t HeartbeatProducer::sent() const { return sentBefore_ + (job_ ? context_.periodic().status(job_).sent : 0); }

QString HeartbeatProducer::lastError() const { return job_ ? context_.periodic().status(job_).error : lastError_; }

}  // namespace coscope::canopen
