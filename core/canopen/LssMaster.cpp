// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/LssMaster.h"

#include "core/canopen/Lss.h"

#include <QPointer>
#include <QTimer>

#include <algorithm>

namespace coscope::canopen {

namespace {
QString configureError(const QString& what, uint8_t code) {
    // CiA 305 §6.4: 0 success, 1 not supported / out of range, FFh manufacturer specific.
    const QString why = code == 1      ? QStringLiteral("not supported or out of range")
                        : code == 0xFF ? QStringLiteral("manufacturer-specific error")
                                       : QStringLiteral("error %1").arg(code);
    return QStringLiteral("LSS %1 refused by the slave: %2 (error code %3)").arg(what, why).arg(code);
}
}  // namespace

LssMaster::LssMaster(MasterContext& context, QObject* parent)
    : QObject(parent), context_(context), timer_(new QTimer(this)) {
    timer_->setSingleShot(true);
    timer_->setTimerType(Qt::PreciseTimer);
    connect(timer_, &QTimer::timeout, this, &LssMaster::onTimeout);
    subscription_ = context_.dispatcher().subscribe(this, {lss::kSlaveToMaster},
                                                    [this](const std::vector<CanFrame>& f) { onFrames(f); });
}

LssMaster::~LssMaster() { context_.dispatcher().unsubscribe(subscription_); }

CanFrame LssMaster::request(uint8_t cs, std::initializer_list<uint8_t> rest) {
    CanFrame f;
    f.id = lss::kMasterToSlave;
    f.len = 8;
    f.data[0] = cs;
    int i = 1;
    for (uint8_t b : rest) f.data[i++] = b;
    return f;
}

bool LssMaster::switchStateGlobal(bool configuration, QString* error) {
    return context_.send(request(lss::SwitchStateGlobal, {uint8_t(configuration ? 1 : 0)}), error);
}

bool LssMaster::activateBitTiming(uint16_t delayMs, QString* error) {
    return context_.send(request(lss::ActivateBitTiming, {uint8_t(delayMs), uint8_t(delayMs >> 8)}), error);
}

void LssMaster::enqueue(Request r) {
    queue_.push_back(std::move(r));
    QMetaObject::invokeMethod(this, &LssMaster::pump, Qt::QueuedConnection);
}

void LssMaster::pump() {
    while (!active_ && !queue_.empty()) {
        Request r = std::move(queue_.front());
        queue_.pop_front();
        QString error;
        if (!context_.send(r.frame, &error)) {
            // Reported through the same path as a missing answer, with the bus's reason.
            sendError_ = error;
            active_ = std::move(r);
            complete(false, CanFrame{});
            sendError_.clear();
            continue;
        }
        if (!r.expectCs) {
            auto then = r.then;
            if (then) then(true, CanFrame{});
            continue;
        }
        active_ = std::move(r);
        active_->sentAt.start();
        timer_->start(active_->timeoutMs > 0 ? active_->timeoutMs : timeoutMs_);
    }
}

void LssMaster::onFrames(const std::vector<CanFrame>& frames) {
    for (const CanFrame& f : frames) {
        if (!active_ || f.len < 1 || f.data[0] != active_->expectCs) continue;
        if (active_->graceMs < 0) {
            complete(true, f);
            continue;
        }
        // Collecting (fastscan): the first answer starts a short grace window for the other
        // slaves' answers to the same request, which must not count for the next one.
        if (active_->seen) continue;
        active_->seen = true;
        lastRttMs_ = int(active_->sentAt.elapsed());
        timer_->start(std::max(active_->graceMs, lastRttMs_ / 2));
    }
}

void LssMaster::onTimeout() {
    if (active_) complete(active_->seen, CanFrame{});
}

void LssMaster::complete(bool answered, const CanFrame& answer) {
    timer_->stop();
    auto then = std::move(active_->then);
    active_.reset();
    if (then) then(answered, answer);
    pump();
}

void LssMaster::switchStateSelective(const LssIdentity& id, LssCallback done) {
    const uint32_t v[4] = {id.vendorId, id.productCode, id.revision, id.serial};
    for (int i = 0; i < 4; ++i) {
        Request r;
        r.frame = request(static_cast<uint8_t>(lss::SwitchSelectiveVendor + i));
        putLe32(r.frame, 1, v[i]);
        if (i == 3) {
            r.expectCs = lss::SwitchSelectiveResponse;
            r.then = [this, done](bool answered, const CanFrame&) {
                LssResult out;
                out.ok = answered;
                if (!answered)
                    out.error = noAnswer(QStringLiteral("no slave with that identity answered switch state selective"));
                done(out);
            };
        }
        enqueue(std::move(r));
    }
}

void LssMaster::configureNodeId(uint8_t nodeId, LssCallback done) {
    if (!(nodeId >= 1 && nodeId <= 127) && nodeId != 0xFF) {
        LssResult out;
        out.error = QStringLiteral("node-ID %1 is outside 1-127").arg(nodeId);
        QMetaObject::invokeMethod(
            this, [done, out] { done(out); }, Qt::QueuedConnection);
        return;
    }
    Request r;
    r.frame = request(lss::ConfigureNodeId, {nodeId});
    r.expectCs = lss::ConfigureNodeId;
    r.then = [this, done](bool answered, const CanFrame& a) {
        LssResult out;
        if (!answered)
            out.error =
                noAnswer(QStringLiteral("no answer to LSS configure node-ID (is a slave in configuration state?)"));
        else if (a.data[1])
            out.errorCode = a.data[1], out.error = configureError(QStringLiteral("configure node-ID"), a.data[1]);
        else out.ok = true;
        done(out);
    };
    enqueue(std::move(r));
}

void LssMaster::configureBitRate(int bitRate, LssCallback done) {
    const int index = lssTableIndexForBitRate(bitRate);
    if (index < 0) {
        LssResult out;
        out.error = QStringLiteral("%1 bit/s is not in the CiA 305 bit timing table").arg(bitRate);
        QMetaObject::invokeMethod(
            this, [done, out] { done(out); }, Qt::QueuedConnection);
        return;
    }
    Request r;
    r.frame = request(lss::ConfigureBitTiming, {0, uint8_t(index)});
    r.expectCs = lss::ConfigureBitTiming;
    r.then = [this, done](bool answered, const CanFrame& a) {
        LssResult out;
        if (!answered)
            out.error =
                noAnswer(QStringLiteral("no answer to LSS configure bit timing (is a slave in configuration state?)"));
        else if (a.data[1])
            out.errorCode = a.data[1], out.error = configureError(QStringLiteral("configure bit timing"), a.data[1]);
        else out.ok = true;
        done(out);
    };
    enqueue(std::move(r));
}

void LssMaster::storeConfiguration(LssCallback done) {
    Request r;
    r.frame = request(lss::StoreConfiguration);
    r.expectCs = lss::StoreConfiguration;
    r.then = [this, done](bool answered, const CanFrame& a) {
        LssResult out;
        if (!answered)
            out.error =
                noAnswer(QStringLiteral("no answer to LSS store configuration (is a slave in configuration state?)"));
        else if (a.data[1])
            out.errorCode = a.data[1], out.error = configureError(QStringLiteral("store configuration"), a.data[1]);
        else out.ok = true;
        done(out);
    };
    enqueue(std::move(r));
}

void LssMaster::inquire(uint8_t cs, LssCallback done) {
    Request r;
    r.frame = request(cs);
    r.expectCs = cs;
    r.then = [this, done, cs](bool answered, const CanFrame& a) {
        LssResult out;
        if (!answered) {
            out.error = noAnswer(QStringLiteral("no answer to LSS %1 (is a slave in configuration state?)")
                                     .arg(lssCommandName(cs, true)));
        } else {
            out.ok = true;
            out.value = cs == lss::InquireNodeId ? a.data[1] : le32At(a, 1);
        }
        done(out);
    };
    enqueue(std::move(r));
}

void LssMaster::inquireNodeId(LssCallback done) { inquire(lss::InquireNodeId, std::move(done)); }

void LssMaster::inquireIdentity(LssCallback done) {
    auto acc = std::make_shared<LssResult>();
    QPointer<LssMaster> self(this);
    inquire(lss::InquireVendor, [self, acc, done](const LssResult& v) {
        if (!v.ok || !self) return done(v);
        acc->identity.vendorId = v.value;
        self->inquire(lss::InquireProduct, [self, acc, done](const LssResult& p) {
            if (!p.ok || !self) return done(p);
            acc->identity.productCode = p.value;
            self->inquire(lss::InquireRevision, [self, acc, done](const LssResult& r) {
                if (!r.ok || !self) return done(r);
                acc->identity.revision = r.value;
                self->inquire(lss::InquireSerial, [acc, done](const LssResult& s) {
                    if (!s.ok) return done(s);
                    acc->identity.serial = s.value;
                    acc->ok = true;
                    done(*acc);
                });
            });
        });
    });
}

}  // namespace coscope::canopen
