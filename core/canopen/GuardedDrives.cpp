// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/GuardedDrives.h"

#include "core/canopen/EnabledDrives.h"
#include "core/canopen/HeartbeatProducer.h"
#include "core/canopen/MasterContext.h"
#include "core/canopen/SdoClient.h"

#include <QPointer>

#include <set>

#include <spdlog/spdlog.h>

namespace coscope::canopen {

namespace {
QString driveName(uint8_t node, int axis) {
    return axis ? QStringLiteral("node %1 axis %2").arg(node).arg(axis) : QStringLiteral("node %1").arg(node);
}
}  // namespace

GuardedDrives::GuardedDrives(MasterContext& context, SdoClient& sdo, HeartbeatProducer& heartbeat, QObject* parent)
    : QObject(parent), context_(context), sdo_(sdo), heartbeat_(heartbeat) {}

GuardedDrives::~GuardedDrives() = default;

void GuardedDrives::setHeartbeat(uint8_t node, uint16_t periodMs) {
    if (node >= 1 && node <= 127) heartbeatNode_ = node;
    if (periodMs > 0) heartbeatMs_ = periodMs;
}

uint16_t GuardedDrives::heartbeatPeriodMs() const {
    return heartbeat_.isRunning() ? heartbeat_.periodMs() : heartbeatMs_;
}
uint8_t GuardedDrives::heartbeatNode() const { return heartbeat_.isRunning() ? heartbeat_.nodeId() : heartbeatNode_; }

void GuardedDrives::set(const Key& key, State state, const QString& text) {
    Entry& e = entries_[key];
    e.state = state;
    e.text = text;
    emit changed(key.first, key.second, state, text);
}

void GuardedDrives::poll() {
    if (closing_) return;
    std::set<Key> enabled;
    for (const EnabledDrives::Drive& d : context_.enabledDrives().drives()) enabled.insert({d.node, d.axis});
    // Newly enabled by CoScope.
    for (const Key& key : enabled) {
        if (entries_.count(key)) continue;
        CanBus* bus = context_.bus();
        if (bus && bus->isListenOnly()) {
            set(key, State::Failed,
                QStringLiteral("%1: the bus is listen-only: CoScope sends nothing, so no heartbeat and no guard")
                    .arg(driveName(key.first, key.second)));
            continue;
        }
        const auto answer = answers_.find(key.first);
        if (answer == answers_.end()) {
            set(key, State::Undecided, {});
            emit consentNeeded(key.first, key.second);
        } else if (answer->second) {
            arm(key);
        } else {
            set(key, State::Declined, {});
        }
    }
    // Left the record (disabled): put back what was changed; forget the rest.
    std::vector<Key> gone;
    for (auto& [key, e] : entries_)
        if (!enabled.count(key)) gone.push_back(key);
    for (const Key& key : gone) {
        Entry& e = entries_[key];
        if (e.state == State::Armed) release(key);
        // A put-back that failed leaves the guard armed: kept (the heartbeat goes on) and put
        // back when the bus closes; never retried by itself.
        else if (e.guard && e.guard->armed()) continue;
        else if (e.state != State::Arming && e.state != State::Releasing) entries_.erase(key);
    }
}

void GuardedDrives::consent(uint8_t node, bool yes) {
    answers_[node] = yes;
    std::vector<Key> waiting;
    for (auto& [key, e] : entries_)
        if (key.first == node && e.state == State::Undecided) waiting.push_back(key);
    for (const Key& key : waiting) {
        if (yes) arm(key);
        else set(key, State::Declined, {});
    }
}

void GuardedDrives::arm(const Key& key) {
    if (closing_) return;
    const auto [node, axis] = key;
    const QString name = driveName(node, axis);
    if (!heartbeat_.isRunning()) {
        if (heartbeatNode_ == node) {
            set(key, State::Failed,
                QStringLiteral(
                    "%1: CoScope's heartbeat node-ID %2 is the drive's own; choose another in the master settings")
                    .arg(name)
                    .arg(node));
            return;
        }
        heartbeat_.setNodeId(heartbeatNode_);
        heartbeat_.setPeriodMs(heartbeatMs_);
        QString why;
        if (!heartbeat_.start(&why)) {
            set(key, State::Failed, QStringLiteral("%1: CoScope's heartbeat cannot start: %2").arg(name, why));
            return;
        }
        startedHeartbeat_ = true;
        spdlog::info("CoScope's heartbeat started for the heartbeat guard: node {}, every {} ms", heartbeatNode_,
                     heartbeatMs_);
    } else if (heartbeat_.nodeId() == node) {
        set(key, State::Failed,
            QStringLiteral(
                "%1: CoScope's heartbeat node-ID %2 is the drive's own; choose another in the master settings")
                .arg(name)
                .arg(node));
        return;
    }
    Entry& e = entries_[key];
    e.guard = std::make_unique<HeartbeatGuard>(sdo_, node, axis);
    e.guard->setAbortOption(abortOption_);
    if (onSend_) e.guard->setSendObserver(onSend_);
    set(key, State::Arming, {});
    QPointer<GuardedDrives> self(this);
    e.guard->arm(heartbeat_, [self, key](const HeartbeatGuardResult& r) {
        if (!self || self->closing_) return;
        if (!r.ok) {
            spdlog::warn("heartbeat guard of {}: {}", driveName(key.first, key.second).toStdString(),
                         r.error.toStdString());
            self->entries_[key].guard.reset();
            self->set(key, State::Failed, r.error);
            self->stopHeartbeatWhenFree();
            return;
        }
        spdlog::info("{}", r.summary.toStdString());
        self->set(key, State::Armed, r.summary);
        self->poll();  // disabled meanwhile: released at once
    });
}

void GuardedDrives::release(const Key& key) {
    Entry& e = entries_[key];
    if (!e.guard) return;
    set(key, State::Releasing, e.text);
    QPointer<GuardedDrives> self(this);
    e.guard->release([self, key](const HeartbeatGuardResult& r) {
        if (!self || self->closing_) return;
        if (!r.ok) {
            // Still armed: the heartbeat goes on (the drive would stop if it stopped).
            spdlog::warn("putting back the heartbeat guard of {}: {}", driveName(key.first, key.second).toStdString(),
                         r.error.toStdString());
            self->set(key, State::Failed, r.error);
            return;
        }
        spdlog::info("{}", r.summary.toStdString());
        self->set(key, State::Released, r.summary);
        self->entries_.erase(key);
        self->stopHeartbeatWhenFree();
        self->poll();  // enabled again meanwhile
    });
}

void GuardedDrives::stopHeartbeatWhenFree() {
    if (!startedHeartbeat_ || holdsHeartbeat()) return;
    heartbeat_.stop();
    startedHeartbeat_ = false;
    spdlog::info("CoScope's heartbeat stopped: no drive watches it any more");
}

std::vector<GuardedDrives::Drive> GuardedDrives::drives() const {
    std::vector<Drive> out;
    for (const auto& [key, e] : entries_) out.push_back({key.first, key.second, e.state, e.text});
    return out;
}

std::vector<uint8_t> GuardedDrives::guardedNodes() const {
    std::vector<uint8_t> out;
    for (const auto& [key, e] : entries_)
        if (e.guard && e.guard->armed() && (out.empty() || out.back() != key.first)) out.push_back(key.first);
    return out;
}

bool GuardedDrives::holdsHeartbeat() const {
    for (const auto& [key, e] : entries_)
        if (e.guard && (e.guard->armed() || e.guard->busy())) return true;
    return false;
}

std::vector<GuardedDrives::PutBack> GuardedDrives::takePutBack() {
    closing_ = true;
    std::vector<PutBack> out;
    for (auto& [key, e] : entries_) {
        if (!e.guard) continue;
        auto writes = e.guard->putBackWrites();
        if (!writes.empty()) out.push_back({key.first, key.second, std::move(writes)});
        e.guard->markPutBack();
    }
    return out;
}

std::vector<PutBackOutcome> putBackDirect(MasterContext& context, std::vector<GuardedDrives::PutBack> putBack,
                                          const DriveDisableOutcome& disabled, int timeoutMs) {
    std::vector<PutBackOutcome> out;
    std::vector<DirectDownload> writes;
    std::vector<size_t> owner;  // writes[i] belongs to out[owner[i]]
    for (auto& p : putBack) {
        PutBackOutcome o{p.node, p.axis, false, false, {}};
        // Still on, as far as CoScope knows: its Disable voltage went unconfirmed.
        bool mayBeOn = false;
        for (const auto& d : disabled.drives)
            if (d.drive.node == p.node && d.drive.axis == p.axis && !(d.seen && d.answered)) mayBeOn = true;
        if (mayBeOn) {
            o.keptArmed = true;
            o.text = QStringLiteral(
                         "%1 may still be enabled: it keeps watching CoScope's heartbeat (1016h, 6007h not put back), "
                         "so it stops by itself when the heartbeat stops")
                         .arg(driveName(p.node, p.axis));
        } else {
            for (auto& w : p.writes) writes.push_back(std::move(w)), owner.push_back(out.size());
        }
        out.push_back(o);
    }
    CanBus* bus = context.bus();
    if (!writes.empty() && (!bus || bus->isListenOnly() || bus->state() != CanBus::State::Open)) {
        for (size_t i = 0; i < writes.size(); ++i)
            out[owner[i]].text =
                QStringLiteral("%1: the old 1016h/6007h could not be put back (the bus is closed); check them")
                    .arg(driveName(out[owner[i]].node, out[owner[i]].axis));
        return out;
    }
    downloadDirect(context, writes, std::chrono::steady_clock::now() + std::chrono::milliseconds(timeoutMs));
    std::map<size_t, QStringList> failures;
    for (size_t i = 0; i < writes.size(); ++i) {
        const QString object = QStringLiteral("%1h").arg(writes[i].index, 4, 16, QChar(u'0')).toUpper();
        if (!writes[i].answered) failures[owner[i]] << QStringLiteral("%1: %2").arg(object, writes[i].error);
    }
    for (size_t k = 0; k < out.size(); ++k) {
        PutBackOutcome& o = out[k];
        if (o.keptArmed) continue;
        o.putBack = !failures.count(k);
        o.text = o.putBack ? QStringLiteral("%1: heartbeat consumer 1016h and 6007h put back before the bus closed")
                                 .arg(driveName(o.node, o.axis))
                           : QStringLiteral("%1: the old 1016h/6007h were not all put back (%2); check them")
                                 .arg(driveName(o.node, o.axis), failures[k].join(QStringLiteral("; ")));
        if (o.putBack) spdlog::info("{}", o.text.toStdString());
        else spdlog::error("{}", o.text.toStdString());
    }
    return out;
}

}  // namespace coscope::canopen
