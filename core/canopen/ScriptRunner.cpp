// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/ScriptRunner.h"

#include "core/canopen/CobId.h"
#include "core/canopen/LssMaster.h"
#include "core/canopen/NmtMaster.h"
#include "core/canopen/SdoClient.h"

#include <QTimer>

#include <spdlog/spdlog.h>

namespace coscope::canopen {

namespace {

QString hexValue(const QByteArray& data) {
    const int n = static_cast<int>(data.size());
    if (n == 1 || n == 2 || n == 4) {
        uint32_t v = 0;
        for (int i = 0; i < n; ++i) v |= static_cast<uint32_t>(static_cast<uint8_t>(data[i])) << (8 * i);
        return QStringLiteral("0x%1").arg(v, n * 2, 16, QChar(u'0'));
    }
    return QStringLiteral("%1 bytes %2").arg(n).arg(QString::fromLatin1(data.toHex(' ')));
}

}  // namespace

ScriptRunner::ScriptRunner(MasterContext& context, SdoClient& sdo, QObject* parent)
    : ScriptRunner(context, sdo, nullptr, nullptr, parent) {}

ScriptRunner::ScriptRunner(MasterContext& context, SdoClient& sdo, NmtMaster* nmt, LssMaster* lss, QObject* parent)
    : QObject(parent), context_(&context), sdo_(&sdo), nmt_(nmt), lss_(lss), timer_(new QTimer(this)) {
    if (!nmt_) {
        ownNmt_ = std::make_unique<NmtMaster>(*context_);
        nmt_ = ownNmt_.get();
    }
    if (!lss_) {
        ownLss_ = std::make_unique<LssMaster>(*context_);
        lss_ = ownLss_.get();
    }
    timer_->setSingleShot(true);
}

ScriptRunner::~ScriptRunner() {
    if (subscription_ && context_) context_->dispatcher().unsubscribe(subscription_);
}

// Listen for boot-up/heartbeat of every waited-for node from now on (CiA 301 §7.2.8.3.2).
void ScriptRunner::listenForNodes() {
    std::vector<uint32_t> ids;
    for (const ScriptStep& s : script_.steps)
        if (s.kind == ScriptStep::Kind::WaitForNode && s.node >= 1 && s.node <= 127) ids.push_back(0x700u + s.node);
    if (subscription_) {
        context_->dispatcher().unsubscribe(subscription_);
        subscription_ = 0;
    }
    if (!ids.empty())
        subscription_ = context_->dispatcher().subscribe(
            this, ids, [this](const std::vector<CanFrame>& frames) { onHeartbeats(frames); });
}

// The old bus's services are let go before the owner closes it; the run goes on with the new
// bus's context and SDO client, and NMT / LSS masters of its own on them.
void ScriptRunner::reconnect(int bitRate) {
    if (!reconnector_)
        return stepDone(
            false, QStringLiteral("this run cannot reopen the adapter; reconnect at %1 bit/s by hand").arg(bitRate));
    if (subscription_) context_->dispatcher().unsubscribe(subscription_);
    subscription_ = 0;
    ownNmt_.reset();
    ownLss_.reset();
    nmt_ = nullptr;
    lss_ = nullptr;
    context_ = nullptr;
    sdo_ = nullptr;
    const quint64 gen = generation_;
    QPointer<ScriptRunner> self(this);
    reconnector_(bitRate, [self, gen, bitRate](MasterContext* context, SdoClient* sdo, const QString& error) {
        if (!self || !self->running_ || self->generation_ != gen) return;
        if (!context || !sdo)
            return self->stepDone(false, error.isEmpty() ? QStringLiteral("could not reopen the adapter") : error);
        self->context_ = context;
        self->sdo_ = sdo;
        self->ownNmt_ = std::make_unique<NmtMaster>(*context);
        self->ownLss_ = std::make_unique<LssMaster>(*context);
        self->nmt_ = self->ownNmt_.get();
        self->lss_ = self->ownLss_.get();
        self->listenForNodes();
        self->stepDone(true, QStringLiteral("connected at %1 bit/s").arg(bitRate));
    });
}

bool ScriptRunner::run(const CommandScript& script, ScriptRunCallback done) {
    if (running_) return false;
    script_ = script;
    done_ = std::move(done);
    result_ = ScriptRunResult{};
    running_ = true;
    step_ = 0;
    seen_.clear();
    if (!context_) {  // a reconnect failed in an earlier run: no bus
        running_ = false;
        return false;
    }
    listenForNodes();
    spdlog::info("script run: {} step(s){}", script_.steps.size(),
                 script_.title.isEmpty() ? std::string() : ": " + script_.title.toStdString());
    // Start on the next turn of the event loop so `done` never runs inside run().
    const quint64 gen = ++generation_;
    QTimer::singleShot(0, this, [this, gen] {
        if (gen == generation_ && running_) startStep();
    });
    return true;
}

void ScriptRunner::cancel() {
    if (!running_) return;
    ++generation_;
    timer_->stop();
    timer_->disconnect(this);
    const int step = step_;
    if (step < static_cast<int>(script_.steps.size())) {
        result_.failedStep = step;
        result_.error = QStringLiteral("step %1 (%2): cancelled")
                            .arg(step + 1)
                            .arg(script_.steps[static_cast<size_t>(step)].toLine());
        emit stepFinished(step, false, QStringLiteral("cancelled"));
    } else {
        result_.error = QStringLiteral("cancelled");
    }
    finish(false, true);
}

void ScriptRunner::finish(bool ok, bool cancelled) {
    running_ = false;
    if (subscription_ && context_) context_->dispatcher().unsubscribe(subscription_);
    subscription_ = 0;
    result_.ok = ok;
    result_.cancelled = cancelled;
    if (!ok) spdlog::warn("script run stopped: {}", result_.error.toStdString());
    auto done = std::move(done_);
    done_ = nullptr;
    const ScriptRunResult result = result_;
    emit finished(ok);
    if (done) done(result);
}

void ScriptRunner::stepDone(bool ok, const QString& detail) {
    timer_->stop();
    timer_->disconnect(this);
    ++generation_;
    const ScriptStep& s = script_.steps[static_cast<size_t>(step_)];
    emit stepFinished(step_, ok, detail);
    if (!running_) return;  // a slot cancelled the run
    if (!ok) {
        result_.failedStep = step_;
        result_.error = QStringLiteral("step %1 (%2): %3").arg(step_ + 1).arg(s.toLine(), detail);
        finish(false, false);
        return;
    }
    result_.details.push_back(detail);
    ++result_.stepsDone;
    ++step_;
    const quint64 gen = generation_;
    QTimer::singleShot(0, this, [this, gen] {
        if (gen == generation_ && running_) startStep();
    });
}

void ScriptRunner::startStep() {
    if (step_ >= static_cast<int>(script_.steps.size())) {
        finish(true, false);
        return;
    }
    const ScriptStep& s = script_.steps[static_cast<size_t>(step_)];
    const quint64 gen = ++generation_;
    emit stepStarted(step_);
    if (!running_ || gen != generation_) return;  // a slot cancelled the run
    QPointer<ScriptRunner> self(this);
    // Runs `fn` only while this step is still the one in progress.
    auto current = [self, gen](auto fn) {
        return [self, gen, fn](const auto& r) {
            if (self && self->running_ && self->generation_ == gen) fn(r);
        };
    };
    QString error;
    switch (s.kind) {
    case ScriptStep::Kind::SdoWrite:
        sdo_->download(s.node, s.index, s.sub, s.data, current([this](const SdoResult& r) {
                           stepDone(r.ok, r.ok ? QStringLiteral("written") : r.error);
                       }));
        return;
    case ScriptStep::Kind::SdoRead:
        sdo_->upload(s.node, s.index, s.sub, current([this](const SdoResult& r) {
                         stepDone(r.ok, r.ok ? QStringLiteral("read %1").arg(hexValue(r.data)) : r.error);
                     }));
        return;
    case ScriptStep::Kind::SdoExpect:
        sdo_->upload(
            s.node, s.index, s.sub, current([this](const SdoResult& r) {
                if (!r.ok) return stepDone(false, r.error);
                const ScriptStep& st = script_.steps[static_cast<size_t>(step_)];
                if (st.matches(r.data))
                    return stepDone(true, QStringLiteral("read %1 as expected").arg(hexValue(r.data)));
                stepDone(false, QStringLiteral("node %1 %2 reads %3, expected %4%5")
                                    .arg(st.node)
                                    .arg(objectRef(st.index, st.sub), hexValue(r.data), hexValue(st.data),
                                         st.mask.isEmpty() ? QString()
                                                           : QStringLiteral(" under mask %1").arg(hexValue(st.mask))));
            }));
        return;
    case ScriptStep::Kind::Nmt:
        if (!nmt_->send(s.nmt, s.node, &error)) return stepDone(false, error);
        return stepDone(true, QStringLiteral("sent"));
    case ScriptStep::Kind::LssSwitchGlobal:
        if (!lss_->switchStateGlobal(s.number != 0, &error)) return stepDone(false, error);
        return stepDone(true, QStringLiteral("sent"));
    case ScriptStep::Kind::LssActivateBitTiming:
        if (!lss_->activateBitTiming(static_cast<uint16_t>(s.number), &error)) return stepDone(false, error);
        // The devices switch after the delay and wait the delay again (CiA 305 §6.4.4).
        connect(timer_, &QTimer::timeout, this, [this] { stepDone(true, QStringLiteral("sent")); });
        timer_->start(static_cast<int>(2 * s.number + 20));
        return;
    case ScriptStep::Kind::LssSwitchSelective:
        lss_->switchStateSelective(s.identity, current([this](const LssResult& r) {
                                       stepDone(r.ok, r.ok ? QStringLiteral("the device confirmed") : r.error);
                                   }));
        return;
    case ScriptStep::Kind::LssConfigureNodeId:
        lss_->configureNodeId(static_cast<uint8_t>(s.number), current([this](const LssResult& r) {
                                  stepDone(r.ok, r.ok ? QStringLiteral("the device confirmed") : r.error);
                              }));
        return;
    case ScriptStep::Kind::LssConfigureBitRate:
        lss_->configureBitRate(static_cast<int>(s.number), current([this](const LssResult& r) {
                                   stepDone(r.ok, r.ok ? QStringLiteral("the device confirmed") : r.error);
                               }));
        return;
    case ScriptStep::Kind::LssStore:
        lss_->storeConfiguration(current(
            [this](const LssResult& r) { stepDone(r.ok, r.ok ? QStringLiteral("the device stored it") : r.error); }));
        return;
    case ScriptStep::Kind::Wait:
        connect(timer_, &QTimer::timeout, this, [this] {
            stepDone(true, QStringLiteral("waited %1 ms").arg(script_.steps[static_cast<size_t>(step_)].number));
        });
        timer_->start(static_cast<int>(std::min<uint32_t>(s.number, 3600000)));
        return;
    case ScriptStep::Kind::WaitForNode:
        connect(timer_, &QTimer::timeout, this, [this] {
            const ScriptStep& st = script_.steps[static_cast<size_t>(step_)];
            stepDone(false, QStringLiteral("node %1 sent no %2 within %3 ms")
                                .arg(st.node)
                                .arg(previousStepResets(st.node) ? QStringLiteral("boot-up")
                                                                 : QStringLiteral("boot-up or heartbeat"))
                                .arg(st.number));
        });
        timer_->start(static_cast<int>(std::min<uint32_t>(s.number, 3600000)));
        checkWaitForNode();
        return;
    case ScriptStep::Kind::Reconnect: reconnect(static_cast<int>(s.number)); return;
    }
    stepDone(false, QStringLiteral("unknown step"));
}

bool ScriptRunner::previousStepResets(uint8_t node) const {
    if (step_ <= 0) return false;
    const ScriptStep& p = script_.steps[static_cast<size_t>(step_ - 1)];
    return p.kind == ScriptStep::Kind::Nmt &&
           (p.nmt == NmtCommand::ResetNode || p.nmt == NmtCommand::ResetCommunication) &&
           (p.node == 0 || p.node == node);
}

void ScriptRunner::onHeartbeats(const std::vector<CanFrame>& frames) {
    if (!running_) return;
    for (const CanFrame& f : frames) {
        if (f.isExtended() || f.isRemote() || f.len < 1 || f.id < 0x701 || f.id > 0x77F) continue;
        NodeSeen& n = seen_[static_cast<uint8_t>(f.id - 0x700)];
        const uint8_t state = f.data[0] & 0x7F;  // bit 7 is the guarding toggle
        n.state = state;
        if (state == static_cast<uint8_t>(NmtState::BootUp)) n.bootUpStep = step_;
        else n.heartbeatStep = step_;
    }
    checkWaitForNode();
}

void ScriptRunner::checkWaitForNode() {
    if (!running_ || step_ >= static_cast<int>(script_.steps.size())) return;
    const ScriptStep& s = script_.steps[static_cast<size_t>(step_)];
    if (s.kind != ScriptStep::Kind::WaitForNode || !timer_->isActive()) return;
    const auto it = seen_.find(s.node);
    if (it == seen_.end()) return;
    const int since = std::max(0, step_ - 1);  // arrived after the previous step started
    if (it->second.bootUpStep >= since) return stepDone(true, QStringLiteral("node %1 booted").arg(s.node));
    if (!previousStepResets(s.node) && it->second.heartbeatStep >= since)
        return stepDone(true, QStringLiteral("node %1 is %2").arg(s.node).arg(nmtStateName(it->second.state)));
}

}  // namespace coscope::canopen
