// SPDX-License-Identifier: GPL-3.0-or-later
// The test move of Ds402Controller (see Ds402TestMove in Ds402Controller.h): set-up writes,
// monitoring, stop on the deceleration ramp and the fail-safe quick stop.
#include "core/canopen/Ds402Controller.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QTimer>

#include <algorithm>
#include <cstdlib>

namespace coscope::canopen {

using ds402::Command;
using ds402::State;

namespace {
QByteArray u32(uint32_t v) {
    QByteArray b(4, 0);
    for (int i = 0; i < 4; ++i) b[i] = static_cast<char>((v >> (8 * i)) & 0xFF);
    return b;
}
int32_t readI32(const QByteArray& b) {
    uint32_t v = 0;
    for (int i = 0; i < std::min<qsizetype>(4, b.size()); ++i) v |= uint32_t(uint8_t(b[i])) << (8 * i);
    return static_cast<int32_t>(v);
}
constexpr int kMovePollMs = 50;       // statusword/position/velocity read interval
constexpr int kStopTimeoutMs = 3000;  // time to stand still after a stop
}  // namespace

QString Ds402TestMove::check() const {
    if (kind == Kind::Jog && (velocity == 0 || std::abs(int64_t(velocity)) > kMaxVelocity))
        return QStringLiteral("jog velocity must be non-zero and at most %1 units/s").arg(kMaxVelocity);
    if (kind == Kind::Relative && (velocity <= 0 || velocity > kMaxVelocity))
        return QStringLiteral("profile velocity must be 1-%1 units/s").arg(kMaxVelocity);
    if (kind == Kind::Relative && (distance == 0 || std::abs(int64_t(distance)) > kMaxDistance))
        return QStringLiteral("relative move must be non-zero and at most %1 units").arg(kMaxDistance);
    if (acceleration == 0 || deceleration == 0) return QStringLiteral("acceleration and deceleration must be above 0");
    if (maxDurationMs <= 0 || maxDurationMs > kMaxDurationMs)
        return QStringLiteral("test move time must be 1-%1 ms").arg(kMaxDurationMs);
    if (watchdogMs < 50) return QStringLiteral("watchdog must be at least 50 ms");
    return {};
}

struct Ds402Controller::Move {
    Ds402TestMove spec;
    std::function<void(const Ds402MotionSample&)> sample;
    Ds402Callback done;
    QElapsedTimer started, fed;
    bool running = false;   // the target was given
    bool stopping = false;  // a stop was asked for or is under way
    bool stopSent = false;
    QString stopReason;
    int polls = 0;
    Ds402MotionSample last;
};

bool Ds402Controller::startTestMove(const Ds402TestMove& spec, std::function<void(const Ds402MotionSample&)> sample,
                                    Ds402Callback done, QString* why) {
    if (move_) {
        if (why) *why = QStringLiteral("a test move is already running");
        return false;
    }
    const QString bad = spec.check();
    if (!bad.isEmpty()) {
        if (why) *why = bad;
        return false;
    }
    auto m = std::make_shared<Move>();
    m->spec = spec;
    m->sample = std::move(sample);
    m->done = std::move(done);
    m->fed.start();
    m->started.start();
    move_ = m;
    QPointer<Ds402Controller> self(this);
    auto alive = [self, m] { return self && self->move_ == m; };
    // The chain of writes; before each one a stop request ends the setup (and stops).
    auto writes = std::make_shared<std::vector<std::pair<QString, std::function<void(SdoCallback)>>>>();
    auto sdoWrite = [self](uint16_t base, QByteArray data) {
        return [self, base, data](SdoCallback cb) {
            self->sdo_.download(self->node_, self->objectIndex(base), 0, data, std::move(cb));
        };
    };
    auto note = [self](uint16_t base, const QString& what) {
        if (self->onSend_)
            self->onSend_(QStringLiteral("%1: %2h = %3")
                              .arg(self->prefix(), QString::number(self->objectIndex(base), 16).toUpper(), what));
    };
    writes->push_back({QStringLiteral("6083h"), [=](SdoCallback cb) {
                           note(0x6083, QStringLiteral("%1 (profile acceleration)").arg(spec.acceleration));
                           sdoWrite(0x6083, u32(spec.acceleration))(cb);
                       }});
    writes->push_back({QStringLiteral("6084h"), [=](SdoCallback cb) {
                           note(0x6084, QStringLiteral("%1 (profile deceleration)").arg(spec.deceleration));
                           sdoWrite(0x6084, u32(spec.deceleration))(cb);
                       }});
    if (spec.kind == Ds402TestMove::Kind::Jog) {
        writes->push_back({QStringLiteral("6040h"), [=](SdoCallback cb) {
                               self->writeControlword(0x000F, QStringLiteral("Enable operation, halt off"), cb);
                           }});
        writes->push_back({QStringLiteral("60FFh"), [=](SdoCallback cb) {
                               note(0x60FF, QStringLiteral("%1 (target velocity)").arg(spec.velocity));
                               sdoWrite(0x60FF, u32(uint32_t(spec.velocity)))(cb);
                           }});
    } else {
        writes->push_back({QStringLiteral("6081h"), [=](SdoCallback cb) {
                               note(0x6081, QStringLiteral("%1 (profile velocity)").arg(spec.velocity));
                               sdoWrite(0x6081, u32(uint32_t(spec.velocity)))(cb);
                           }});
        writes->push_back({QStringLiteral("607Ah"), [=](SdoCallback cb) {
                               note(0x607A, QStringLiteral("%1 (target position, relative)").arg(spec.distance));
                               sdoWrite(0x607A, u32(uint32_t(spec.distance)))(cb);
                           }});
        writes->push_back({QStringLiteral("6040h"), [=](SdoCallback cb) {
                               self->writeControlword(
                                   0x004F, QStringLiteral("Enable operation, relative, new set-point low"), cb);
                           }});
        writes->push_back({QStringLiteral("6040h"), [=](SdoCallback cb) {
                               self->writeControlword(
                                   0x005F, QStringLiteral("New set-point (bit 4 rising), relative (bit 6)"), cb);
                           }});
    }
    auto runWrites = std::make_shared<std::function<void(size_t)>>();
    *runWrites = [selfC = self, mC = m, aliveC = alive, writesC = writes, runWritesC = runWrites](size_t i) {
        // Locals: resetting *runWrites below destroys this closure while it runs.
        const auto self = selfC;
        const auto m = mC;
        const auto alive = aliveC;  // NOLINT(performance-unnecessary-copy-initialization): see above
        const auto writes = writesC;
        const auto runWrites = runWritesC;
        if (!alive()) return;
        if (m->stopping) {
            *runWrites = nullptr;
            return self->stopTestMove(m->stopReason);
        }
        if (i >= writes->size()) {
            *runWrites = nullptr;
            m->running = true;
            m->started.restart();
            QTimer::singleShot(kMovePollMs, self, [self, m] {
                if (self && self->move_ == m) self->moveMonitor();
            });
            return;
        }
        (*writes)[i].second([self, m, alive, runWrites, i](const SdoResult& r) {
            if (!alive()) return;
            if (!r.ok) {
                if (*runWrites) *runWrites = nullptr;
                return self->moveFail(QStringLiteral("test move set-up failed: ") + r.error);
            }
            if (*runWrites) (*runWrites)(i + 1);
        });
    };
    readState([self, m, alive, runWrites](const Ds402Result& r) {
        if (!alive()) return;
        if (!r.ok || r.state != State::OperationEnabled) {
            Ds402Result out = r;
            out.ok = false;
            if (r.ok)
                out.error = QStringLiteral("%1 is in %2, not Operation enabled: enable the drive before a test move")
                                .arg(self->prefix(), ds402::stateName(r.state));
            *runWrites = nullptr;
            auto cb = m->done;
            self->move_.reset();
            return cb(out);
        }
        const int8_t mode = m->spec.kind == Ds402TestMove::Kind::Jog ? 3 : 1;  // pv / pp
        self->setMode(mode, [self, m, alive, runWrites](const Ds402Result& mr) {
            if (!alive()) return;
            if (!mr.ok) {
                *runWrites = nullptr;
                return self->moveFail(QStringLiteral("cannot set the mode for the test move: ") + mr.error);
            }
            (*runWrites)(0);
        });
    });
    return true;
}

void Ds402Controller::feedWatchdog() {
    if (move_) move_->fed.restart();
}

void Ds402Controller::moveMonitor() {
    auto m = move_;
    if (!m || m->stopSent) return;
    QPointer<Ds402Controller> self(this);
    auto alive = [self, m] { return self && self->move_ == m; };
    readState([self, m, alive](const Ds402Result& st) {
        if (!alive() || m->stopSent) return;
        if (!st.ok)
            return self->moveFail(
                QStringLiteral("the drive stopped answering during the test move (%1)").arg(st.error));
        m->last.statusword = st.statusword;
        if (st.statusword & ds402::sw::Fault)
            return self->moveFail(QStringLiteral("the drive faulted during the test move (statusword 0x%1)")
                                      .arg(st.statusword, 4, 16, QChar(u'0')));
        if (st.state != State::OperationEnabled)
            return self->moveFail(QStringLiteral("the drive left Operation enabled during the test move (now %1)")
                                      .arg(ds402::stateName(st.state)));
        self->sdo_.upload(self->node_, self->objectIndex(0x6064), 0, [self, m, alive](const SdoResult& p) {
            if (!alive() || m->stopSent) return;
            if (!p.ok) return self->moveFail(QStringLiteral("position read failed during the test move: ") + p.error);
            m->last.position = readI32(p.data);
            self->sdo_.upload(self->node_, self->objectIndex(0x606C), 0, [self, m, alive](const SdoResult& v) {
                if (!alive() || m->stopSent) return;
                if (!v.ok)
                    return self->moveFail(QStringLiteral("velocity read failed during the test move: ") + v.error);
                m->last.velocity = readI32(v.data);
                m->last.ms = m->started.elapsed();
                ++m->polls;
                if (m->sample) m->sample(m->last);
                if (!self || self->move_ != m) return;  // the sample callback may stop it
                if (m->fed.elapsed() > m->spec.watchdogMs)
                    return self->stopTestMove(
                        QStringLiteral("hold-to-run released (no signal for %1 ms)").arg(m->spec.watchdogMs));
                if (m->started.elapsed() > m->spec.maxDurationMs)
                    return self->stopTestMove(QStringLiteral("time limit of %1 ms reached").arg(m->spec.maxDurationMs));
                if (m->spec.kind == Ds402TestMove::Kind::Relative && m->polls > 2 &&
                    (m->last.statusword & ds402::sw::TargetReached) && std::abs(m->last.velocity) < 1)
                    return self->stopTestMove(QStringLiteral("target reached"));
                QTimer::singleShot(kMovePollMs, self, [self, m] {
                    if (self && self->move_ == m) self->moveMonitor();
                });
            });
        });
    });
}

void Ds402Controller::stopTestMove(const QString& reason) {
    auto m = move_;
    if (!m || m->stopSent) return;
    if (!m->stopping) {
        m->stopping = true;
        m->stopReason = reason;
    }
    if (!m->running) return;  // the set-up chain sees `stopping` and comes back here
    m->stopSent = true;
    QPointer<Ds402Controller> self(this);
    auto alive = [self, m] { return self && self->move_ == m; };
    // Halt (bit 8) with bit 4 low, then target velocity 0 for a jog (CiA 402-2 §12.2, §14.2).
    writeControlword(
        0x010F, QStringLiteral("Halt: stop the test move on the deceleration ramp"),
        [self, m, alive](const SdoResult& h) {
            if (!alive()) return;
            if (!h.ok) return self->moveFail(QStringLiteral("halt failed: ") + h.error);
            auto waitStill = std::make_shared<std::function<void()>>();
            auto still = std::make_shared<QElapsedTimer>();
            still->start();
            *waitStill = [self, m, alive, waitStill, still] {
                if (!alive()) return;
                self->sdo_.upload(
                    self->node_, self->objectIndex(0x606C), 0, [self, m, alive, waitStill, still](const SdoResult& v) {
                        if (!alive()) return;
                        if (!v.ok) {
                            *waitStill = nullptr;
                            return self->moveFail(QStringLiteral("velocity read failed while stopping: ") + v.error);
                        }
                        m->last.velocity = readI32(v.data);
                        m->last.ms = m->started.elapsed();
                        if (m->sample) m->sample(m->last);
                        if (!alive()) return;
                        if (std::abs(m->last.velocity) <= 1) {
                            *waitStill = nullptr;
                            Ds402Result out;
                            out.ok = true;
                            out.stopReason = m->stopReason;
                            out.statusword = m->last.statusword;
                            out.state = ds402::stateFromStatusword(out.statusword);
                            return self->moveStopped(out);
                        }
                        if (still->elapsed() > kStopTimeoutMs) {
                            *waitStill = nullptr;
                            return self->moveFail(
                                QStringLiteral("the motor did not stop within %1 ms of the halt").arg(kStopTimeoutMs));
                        }
                        QTimer::singleShot(kMovePollMs, self, [waitStill] {
                            if (*waitStill) (*waitStill)();
                        });
                    });
            };
            if (m->spec.kind == Ds402TestMove::Kind::Jog) {
                if (self->onSend_)
                    self->onSend_(QStringLiteral("%1: %2h = 0 (target velocity)")
                                      .arg(self->prefix(), QString::number(self->objectIndex(0x60FF), 16).toUpper()));
                self->sdo_.download(
                    self->node_, self->objectIndex(0x60FF), 0, u32(0), [self, alive, waitStill](const SdoResult& z) {
                        if (!alive()) return;
                        if (!z.ok) {
                            *waitStill = nullptr;
                            return self->moveFail(QStringLiteral("target velocity 0 failed: ") + z.error);
                        }
                        (*waitStill)();
                    });
            } else {
                (*waitStill)();
            }
        });
}

void Ds402Controller::moveStopped(Ds402Result r) {
    auto m = move_;
    if (!m) return;
    move_.reset();
    if (m->done) m->done(r);
}

void Ds402Controller::moveFail(const QString& error) {
    auto m = move_;
    if (!m) return;
    m->stopSent = true;
    // Something is wrong (fault, silent drive, refused write): quick stop, then no power.
    QPointer<Ds402Controller> self(this);
    writeControlword(ds402::controlwordFor(Command::QuickStop), QStringLiteral("Quick stop, test move failed"),
                     [](const SdoResult&) {});
    writeControlword(ds402::controlwordFor(Command::DisableVoltage),
                     QStringLiteral("Disable voltage, test move failed"), [self, m, error](const SdoResult& w) {
                         Ds402Result out;
                         out.ok = false;
                         out.statusword = m->last.statusword;
                         out.state = ds402::stateFromStatusword(out.statusword);
                         out.stopReason = error;
                         out.error = error + (w.ok ? QStringLiteral("; drive disabled")
                                                   : QStringLiteral("; disabling the drive failed too: ") + w.error);
                         if (self && self->move_ == m) self->move_.reset();
                         if (m->done) m->done(out);
                     });
}

}  // namespace coscope::canopen
