// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/HeartbeatMonitor.h"

#include "core/canopen/Nmt.h"

#include <QTimer>

namespace coscope::canopen {

using Status = ErrorControlWatch::Status;

HeartbeatMonitor::HeartbeatMonitor(MasterContext& context, QObject* parent)
    : QObject(parent), context_(context), timer_(new QTimer(this)) {
    std::vector<uint32_t> ids;
    for (uint32_t n = 1; n <= 127; ++n) {
        ids.push_back(0x700 + n);
        ids.push_back(0x80 + n);
    }
    subscription_ =
        context_.dispatcher().subscribe(this, std::move(ids), [this](const std::vector<CanFrame>& f) { onFrames(f); });
    connect(timer_, &QTimer::timeout, this, &HeartbeatMonitor::onCheck);
    timer_->setInterval(20);  // runs while a node is watched
}

HeartbeatMonitor::~HeartbeatMonitor() {
    for (auto& [node, w] : watches_) stopGuarding(w);
    context_.dispatcher().unsubscribe(subscription_);
}

void HeartbeatMonitor::stopGuarding(Watch& w) {
    if (w.job) context_.periodic().remove(w.job);
    w.job = 0;
    if (w.orderWatch) context_.dispatcher().removeWatch(w.orderWatch);
    w.orderWatch = 0;
}

void HeartbeatMonitor::setConsumerTime(uint8_t node, int timeMs) {
    if (timeMs <= 0) return unwatch(node);
    Watch& w = watches_[node];
    stopGuarding(w);
    w = Watch{};
    w.startNs = nowNs();
    w.shown.consumerTimeMs = timeMs;
    setStatus(node, w, Status::Waiting);
    timer_->start();
}

bool HeartbeatMonitor::setGuarding(uint8_t node, int guardTimeMs, int lifeTimeFactor, QString* error) {
    if (guardTimeMs <= 0) {
        unwatch(node);
        return true;
    }
    Watch& w = watches_[node];
    stopGuarding(w);
    w = Watch{};
    w.startNs = nowNs();
    w.shown.guardTimeMs = guardTimeMs;
    w.shown.lifeTimeFactor = std::max(1, lifeTimeFactor);
    w.requests = std::make_shared<std::atomic<uint64_t>>(0);
    w.missed = std::make_shared<std::atomic<uint64_t>>(0);
    // Each request is answered before the next goes out (the guard time is the period; CiA 301
    // §7.2.8.3.2.1): a request of ours followed by another without an answer between was missed.
    w.orderWatch = context_.dispatcher().addWatch({0x700u + node},
                                                  [missed = w.missed, pending = false](const CanFrame& f) mutable {
                                                      if (f.isTx() && f.isRemote()) {
                                                          if (pending) missed->fetch_add(1, std::memory_order_relaxed);
                                                          pending = true;
                                                      } else if (!f.isTx() && !f.isRemote() && f.len >= 1) {
                                                          pending = false;
                                                      }
                                                  });
    // The request: RTR on 700h + node-ID (CiA 301 §7.2.8.3.2.1; DLC 1 as most masters send it).
    PeriodicSender::Job job;
    job.frame.id = 0x700u + node;
    job.frame.len = 1;
    job.frame.flags = CanFrame::Remote;
    job.periodNs = int64_t(guardTimeMs) * 1'000'000;
    job.afterSend = [requests = w.requests](const CanFrame&, uint64_t sent) {
        requests->store(sent, std::memory_order_release);
    };
    QString why;
    w.job = context_.periodic().add(std::move(job), &why);
    if (!w.job) {
        unwatch(node);  // nothing watched: not the node's former watch either
        if (error) *error = why;
        return false;
    }
    setStatus(node, w, Status::Waiting);
    timer_->start();
    return true;
}

void HeartbeatMonitor::unwatch(uint8_t node) {
    auto it = watches_.find(node);
    if (it == watches_.end()) return;
    stopGuarding(it->second);
    watches_.erase(it);
    if (watches_.empty()) timer_->stop();
    table().update(node, [](NodeInfo& info) {
        info.watch = {};
        info.heartbeatLost = false;
    });
    emit nodeChanged(node);
}

ErrorControlWatch HeartbeatMonitor::watch(uint8_t node) const {
    const auto it = watches_.find(node);
    return it == watches_.end() ? ErrorControlWatch{} : it->second.shown;
}

uint64_t HeartbeatMonitor::guardRequests(uint8_t node) const {
    const auto it = watches_.find(node);
    return it != watches_.end() && it->second.requests ? it->second.requests->load(std::memory_order_acquire) : 0;
}

void HeartbeatMonitor::setStatus(uint8_t node, Watch& w, Status status, int addErrors) {
    const Status was = w.shown.status;
    // Unchanged: only the last answer's time (Ok) or the error count moved; no signal.
    if (was == status && !addErrors && status != Status::Ok) return;
    w.shown.status = status;
    if (status == Status::Lost && was != Status::Lost) ++w.shown.lost;
    const ErrorControlWatch shown = w.shown;
    table().update(node, [&](NodeInfo& info) {
        info.watch = shown;
        info.heartbeatLost = status == Status::Lost;
        info.guardingErrors += addErrors;
    });
    if (was == status) return;
    if (status == Status::Lost && was != Status::Lost) emit nodeLost(node);
    if (was == Status::Lost && status == Status::Ok) emit nodeBack(node);
    emit nodeChanged(node);
}

void HeartbeatMonitor::onErrorControl(Watch& w, uint8_t node, uint8_t byte, int64_t now) {
    const uint8_t state = byte & 0x7F;
    const bool toggle = byte & 0x80;
    if (state == static_cast<uint8_t>(NmtState::BootUp)) {
        // After boot-up the toggle starts again at 0 (CiA 301 §7.2.8.3.2.1).
        w.firstAnswer = true;
        w.expectToggle = false;
    }
    if (!w.shown.guarding()) {
        if (w.shown.lastNs && now > w.shown.lastNs) w.periodNs = now - w.shown.lastNs;
        w.shown.lastNs = now;
        setStatus(node, w, Status::Ok);
        return;
    }
    const uint64_t sent = w.requests->load(std::memory_order_acquire);
    if (state == static_cast<uint8_t>(NmtState::BootUp) || sent <= w.answeredUpTo)
        return;  // not an answer to a request of ours
    w.answeredUpTo = sent;
    if (!w.firstAnswer && toggle != w.expectToggle) {
        w.expectToggle = !toggle;
        if (!w.errorReported)
            emit guardingError(node, QStringLiteral("node %1: node guarding answer with toggle bit %2, %3 expected")
                                         .arg(node)
                                         .arg(int(toggle))
                                         .arg(int(!toggle)));
        w.errorReported = true;
        if (w.shown.status != Status::Lost) setStatus(node, w, Status::Late, 1);
        return;
    }
    w.firstAnswer = false;
    w.expectToggle = !toggle;
    w.errorReported = false;
    w.shown.lastNs = now;
    setStatus(node, w, Status::Ok);
}

void HeartbeatMonitor::onFrames(const std::vector<CanFrame>& frames) {
    const int64_t now = nowNs();
    for (const CanFrame& f : frames) {
        const bool errorControl = f.id > 0x700 && f.id <= 0x77F;
        const uint8_t node = static_cast<uint8_t>(errorControl ? f.id - 0x700 : f.id - 0x80);
        if (errorControl && (f.isRemote() || f.len < 1)) continue;
        if (!errorControl && f.len < 2) continue;
        auto w = watches_.find(node);
        const bool guardAnswer = errorControl && w != watches_.end() && w->second.shown.guarding();
        if (!fedByTrace_) feedTable(f, node, errorControl, guardAnswer);
        if (errorControl && w != watches_.end()) onErrorControl(w->second, node, f.data[0], now);
    }
}

// What the trace would have told the node table (the CLI and tests have no trace).
void HeartbeatMonitor::feedTable(const CanFrame& f, uint8_t node, bool errorControl, bool guardAnswer) {
    bool changed = !table().node(node).has_value();
    bool booted = false;
    const uint8_t state = f.data[0] & 0x7F;
    const uint16_t code = errorControl ? 0 : static_cast<uint16_t>(f.data[0] | (f.data[1] << 8));
    table().update(node, [&](NodeInfo& info) {
        info.lastSeenNs = f.timestampNs ? f.timestampNs : nowNs();
        if (errorControl) {
            if (state == static_cast<uint8_t>(NmtState::BootUp)) {
                ++info.bootUps;
                booted = changed = true;
            }
            // After boot-up a node is pre-operational (CiA 301 §7.3.2.2.1), as the node table has it.
            const int now = booted ? 0x7F : state;
            if (info.nmtState != now) changed = true;
            info.nmtState = now;
            info.nmtSource = booted ? NmtSource::BootUp : guardAnswer ? NmtSource::Guarding : NmtSource::Heartbeat;
            info.nmtCommand = 0;
        } else {
            ++info.emcyCount;
            info.lastEmcyCode = code;
            changed = true;
        }
    });
    if (booted) emit bootUp(node);
    if (!errorControl) emit emergency(node, code);
    if (changed) emit nodeChanged(node);
}

void HeartbeatMonitor::onCheck() {
    const int64_t now = nowNs();
    for (auto& [node, w] : watches_) {
        const int64_t since = w.shown.lastNs ? w.shown.lastNs : w.startNs;
        if (!w.shown.guarding()) {
            if (now - since > int64_t(w.shown.consumerTimeMs) * 1'000'000) setStatus(node, w, Status::Lost);
            else if (w.shown.status == Status::Ok && w.periodNs && now - since > w.periodNs * 3 / 2)
                setStatus(node, w, Status::Late);
            continue;
        }
        // Requests missed (a guarding error), as the ingest thread saw them in bus order.
        const uint64_t missedNow = w.missed->load(std::memory_order_relaxed);
        const int missed = static_cast<int>(missedNow - w.missedCounted);
        w.missedCounted = missedNow;
        if (missed > 0) {
            if (!w.errorReported)
                emit guardingError(
                    node, QStringLiteral("node %1: no answer to a node guarding request within the guard time %2 ms")
                              .arg(node)
                              .arg(w.shown.guardTimeMs));
            w.errorReported = true;
        }
        const int64_t life = int64_t(w.shown.guardTimeMs) * w.shown.lifeTimeFactor * 1'000'000;
        if (now - since > life) setStatus(node, w, Status::Lost, missed);
        else if (missed) setStatus(node, w, Status::Late, missed);
    }
}

}  // namespace coscope::canopen
