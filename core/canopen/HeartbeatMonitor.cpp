// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/HeartbeatMonitor.h"

#include "core/canopen/Nmt.h"

#include <QTimer>

namespace coscope::canopen {

HeartbeatMonitor::HeartbeatMonitor(MasterContext& context, QObject* parent)
    : QObject(parent), context_(context), timer_(new QTimer(this)) {
    std::vector<uint32_t> ids;
    for (uint32_t n = 1; n <= 127; ++n) {
        ids.push_back(0x700 + n);
        ids.push_back(0x80 + n);
    }
    subscription_ = context_.dispatcher().subscribe(this, std::move(ids), [this](const std::vector<CanFrame>& f) { onFrames(f); });
    connect(timer_, &QTimer::timeout, this, &HeartbeatMonitor::onCheck);
    timer_->start(10);
}

HeartbeatMonitor::~HeartbeatMonitor() { context_.dispatcher().unsubscribe(subscription_); }

void HeartbeatMonitor::setConsumerTime(uint8_t node, int timeMs) {
    if (timeMs <= 0) consumerMs_.erase(node);
    else consumerMs_[node] = timeMs;
    lastHeartbeatNs_[node] = nowNs();
}

void HeartbeatMonitor::setGuarding(uint8_t node, int guardTimeMs, int lifeTimeFactor) {
    if (guardTimeMs <= 0) {
        guards_.erase(node);
        return;
    }
    Guard g;
    g.guardTimeMs = guardTimeMs;
    g.lifeFactor = std::max(1, lifeTimeFactor);
    g.lastAnswerNs = nowNs();
    guards_[node] = g;
}

void HeartbeatMonitor::onFrames(const std::vector<CanFrame>& frames) {
    for (const CanFrame& f : frames) {
        const bool errorControl = f.id > 0x700 && f.id <= 0x77F;
        const uint8_t node = static_cast<uint8_t>(errorControl ? f.id - 0x700 : f.id - 0x80);
        if (errorControl && (f.isRemote() || f.len < 1)) continue;
        if (!errorControl && f.len < 2) continue;
        bool changed = !table().node(node).has_value();
        bool booted = false;
        const uint8_t state = f.data[0] & 0x7F;
        const bool toggle = f.data[0] & 0x80;
        const uint16_t code = errorControl ? 0 : static_cast<uint16_t>(f.data[0] | (f.data[1] << 8));
        auto g = guards_.find(node);
        const bool guardAnswer = errorControl && g != guards_.end() && g->second.waiting;
        // Guarding answer: the toggle alternates, starting with 0 (CiA 301 §7.2.8.3.2.1).
        const bool wrongToggle = guardAnswer && !g->second.firstAnswer && toggle != g->second.expectToggle;
        if (guardAnswer) {
            g->second.firstAnswer = false;
            g->second.expectToggle = !toggle;
            g->second.waiting = false;
            g->second.lastAnswerNs = nowNs();
        }
        if (errorControl) lastHeartbeatNs_[node] = nowNs();
        table().update(node, [&](NodeInfo& info) {
            info.lastSeenNs = f.timestampNs ? f.timestampNs : nowNs();
            if (errorControl) {
                if (wrongToggle) ++info.guardingErrors;
                if (state == static_cast<uint8_t>(NmtState::BootUp)) {
                    ++info.bootUps;
                    booted = changed = true;
                }
                // After boot-up a node is pre-operational (CiA 301 §7.3.2.2.1), as the node table has it.
                const int now = booted ? 0x7F : state;
                if (info.nmtState != now || info.heartbeatLost) changed = true;
                info.heartbeatLost = false;
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
}

void HeartbeatMonitor::onCheck() {
    const int64_t now = nowNs();
    // Marks the node lost once; true when it was not lost before.
    auto lose = [this](uint8_t node) {
        bool was = false;
        table().update(node, [&](NodeInfo& info) {
            was = info.heartbeatLost;
            info.heartbeatLost = true;
        });
        return !was;
    };
    for (const auto& [node, ms] : consumerMs_) {
        const auto info = table().node(node);
        if ((!info || !info->heartbeatLost) && now - lastHeartbeatNs_[node] > int64_t(ms) * 1'000'000 && lose(node)) {
            emit nodeLost(node);
            emit nodeChanged(node);
        }
    }
    for (auto& [node, g] : guards_) {
        if (now >= g.nextRequestNs) {
            if (g.waiting) table().update(node, [](NodeInfo& info) { ++info.guardingErrors; });  // the previous request got no answer
            CanFrame rtr;
            rtr.id = 0x700u + node;
            rtr.len = 1;
            rtr.flags = CanFrame::Remote;
            QString error;
            if (context_.send(rtr, &error)) g.waiting = true;
            g.nextRequestNs = now + int64_t(g.guardTimeMs) * 1'000'000;
        }
        const int64_t life = int64_t(g.guardTimeMs) * g.lifeFactor * 1'000'000;
        const auto info = table().node(node);
        if ((!info || !info->heartbeatLost) && now - g.lastAnswerNs > life && lose(node)) {
            emit nodeLost(node);
            emit nodeChanged(node);
        }
    }
}

}  // namespace coscope::canopen
