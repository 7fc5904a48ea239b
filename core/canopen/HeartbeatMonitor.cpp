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
        NodeInfo& info = table_[node];
        const bool wasPresent = info.present;
        info.present = true;
        info.lastSeenNs = f.timestampNs ? f.timestampNs : nowNs();
        bool changed = !wasPresent;
        if (errorControl) {
            if (f.isRemote() || f.len < 1) continue;
            const uint8_t state = f.data[0] & 0x7F;
            const bool toggle = f.data[0] & 0x80;
            auto g = guards_.find(node);
            if (g != guards_.end() && g->second.waiting) {
                // Guarding answer: the toggle alternates, starting with 0 (CiA 301 §7.2.8.3.2.1).
                if (!g->second.firstAnswer && toggle != g->second.expectToggle) ++info.guardingErrors;
                g->second.firstAnswer = false;
                g->second.expectToggle = !toggle;
                g->second.waiting = false;
                g->second.lastAnswerNs = nowNs();
            }
            lastHeartbeatNs_[node] = nowNs();
            if (state == static_cast<uint8_t>(NmtState::BootUp)) {
                ++info.bootUps;
                emit bootUp(node);
                changed = true;
            }
            if (!info.nmtState || *info.nmtState != state) changed = true;
            if (info.heartbeatLost) changed = true;
            info.heartbeatLost = false;
            info.nmtState = state;
        } else {
            if (f.len < 2) continue;
            const uint16_t code = static_cast<uint16_t>(f.data[0] | (f.data[1] << 8));
            ++info.emcyCount;
            info.lastEmcyCode = code;
            emit emergency(node, code);
            changed = true;
        }
        if (changed) emit nodeChanged(node);
    }
}

void HeartbeatMonitor::onCheck() {
    const int64_t now = nowNs();
    for (const auto& [node, ms] : consumerMs_) {
        NodeInfo& info = table_[node];
        if (!info.heartbeatLost && now - lastHeartbeatNs_[node] > int64_t(ms) * 1'000'000) {
            info.heartbeatLost = true;
            emit nodeLost(node);
            emit nodeChanged(node);
        }
    }
    for (auto& [node, g] : guards_) {
        NodeInfo& info = table_[node];
        if (now >= g.nextRequestNs) {
            if (g.waiting) ++info.guardingErrors;  // the previous request got no answer
            CanFrame rtr;
            rtr.id = 0x700u + node;
            rtr.len = 1;
            rtr.flags = CanFrame::Remote;
            QString error;
            if (context_.send(rtr, &error)) g.waiting = true;
            g.nextRequestNs = now + int64_t(g.guardTimeMs) * 1'000'000;
        }
        const int64_t life = int64_t(g.guardTimeMs) * g.lifeFactor * 1'000'000;
        if (!info.heartbeatLost && now - g.lastAnswerNs > life) {
            info.heartbeatLost = true;
            emit nodeLost(node);
            emit nodeChanged(node);
        }
    }
}

}  // namespace coscope::canopen
