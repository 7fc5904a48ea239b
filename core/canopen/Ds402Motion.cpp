// SPDX-License-Identifier: GPL-3.0-or-later
// What home() and moveTo() of Ds402Controller share: the set-up chain, the monitoring reads,
// stop (halt or quick stop) at any time, and the fail-safe end (quick stop, disable voltage).
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
constexpr int kMotionPollMs = 50;           // statusword/position/velocity read interval
constexpr int kMotionStopTimeoutMs = 5000;  // time to stand still after a stop
int32_t motionI32(const QByteArray& b) {
    uint32_t v = 0;
    for (int i = 0; i < std::min<qsizetype>(4, b.size()); ++i) v |= uint32_t(uint8_t(b[i])) << (8 * i);
    return static_cast<int32_t>(v);
}
QString hex4(uint32_t v) { return QStringLiteral("%1").arg(v, 4, 16, QChar(u'0')).toUpper(); }
}  // namespace

struct Ds402Controller::Motion {
    bool homing = false;  // else a profile position move
    int timeoutMs = 60000;
    std::function<void(const Ds402MotionSample&)> progress;
    Ds402Callback done;
    // Decides after each monitoring read: empty = go on; "ok" = finished well; else the error.
    std::function<QString(const Ds402MotionSample&)> check;
    // Runs once when check() said "ok" (e.g. bit 4 low), then the motion ends well.
    MotionStep finish;
    QElapsedTimer started;  // since the start controlword
    bool running = false;   // monitoring
    bool stopping = false;  // a stop was asked for
    bool stopSent = false;
    bool quickSent = false;
    QString stopReason;
    Ds402MotionSample last;
};

std::shared_ptr<Ds402Controller::Motion> Ds402Controller::beginMotion(
    bool homing, int timeoutMs, std::function<void(const Ds402MotionSample&)> progress, Ds402Callback done,
    std::function<QString(const Ds402MotionSample&)> check, MotionStep finish) {
    if (motion_ || move_) {
        Ds402Result r;
        r.error = QStringLiteral("%1: a move is already running").arg(prefix());
        done(r);
        return nullptr;
    }
    auto m = std::make_shared<Motion>();
    m->homing = homing;
    m->timeoutMs = timeoutMs > 0 ? timeoutMs : 60000;
    m->progress = std::move(progress);
    m->done = std::move(done);
    m->check = std::move(check);
    m->finish = std::move(finish);
    motion_ = m;
    return m;
}

Ds402Controller::MotionStep Ds402Controller::writeStep(uint16_t base, uint8_t sub, QByteArray data,
                                                       const QString& what) {
    QPointer<Ds402Controller> self(this);
    return [self, base, sub, data, what](std::function<void(const QString&)> next) {
        if (!self) return;
        const uint16_t index = self->objectIndex(base);
        const QString ref = sub ? QStringLiteral("%1h:%2").arg(hex4(index)).arg(sub, 2, 16, QChar(u'0'))
                                : QStringLiteral("%1h").arg(hex4(index));
        if (self->onSend_) self->onSend_(QStringLiteral("%1: %2 = %3").arg(self->prefix(), ref, what));
        self->sdo_.download(self->node_, index, sub, data, [next, ref, what](const SdoResult& r) {
            next(r.ok ? QString() : QStringLiteral("%1 = %2 refused: %3").arg(ref, what, r.error));
        });
    };
}

Ds402Controller::MotionStep Ds402Controller::controlwordStep(uint16_t cw, const QString& why) {
    QPointer<Ds402Controller> self(this);
    return [self, cw, why](std::function<void(const QString&)> next) {
        if (!self) return;
        self->writeControlword(cw, why, [next](const SdoResult& r) { next(r.ok ? QString() : r.error); });
    };
}

Ds402Controller::MotionStep Ds402Controller::modeStep(int8_t mode) {
    QPointer<Ds402Controller> self(this);
    return [self, mode](std::function<void(const QString&)> next) {
        if (!self) return;
        self->setMode(mode, [next](const Ds402Result& r) { next(r.ok ? QString() : r.error); });
    };
}

Ds402Controller::MotionStep Ds402Controller::enableStep() {
    QPointer<Ds402Controller> self(this);
    return [self](std::function<void(const QString&)> next) {
        if (!self) return;
        self->enable([next](const Ds402Result& r) {
            next(r.ok ? QString() : r.advice.isEmpty() ? r.error : r.error + QStringLiteral(" — ") + r.advice);
        });
    };
}

void Ds402Controller::motionSteps(std::shared_ptr<Motion> m, MotionSteps steps, size_t i, size_t liveFrom) {
    if (motion_ != m) return;
    if (m->stopping && i > liveFrom) {
        // The start went out (a hold-to-run released during the set-point handshake): stop it
        // as a running motion, halt and wait for standstill.
        m->running = true;
        m->started.start();
        return stopMotion(m->quickSent, m->stopReason);
    }
    if (m->stopping)
        return motionStopped(m, QStringLiteral("stopped before the motion started (%1)").arg(m->stopReason));
    if (i >= steps->size()) {
        m->running = true;
        m->started.start();
        return motionMonitor(m);
    }
    QPointer<Ds402Controller> self(this);
    (*steps)[i]([self, m, steps, i, liveFrom](const QString& error) {
        if (!self || self->motion_ != m) return;
        if (!error.isEmpty()) return self->motionFail(m, error);
        self->motionSteps(m, steps, i + 1, liveFrom);
    });
}

void Ds402Controller::motionMonitor(std::shared_ptr<Motion> m) {
    if (motion_ != m || m->stopSent) return;
    QPointer<Ds402Controller> self(this);
    auto alive = [self, m] { return self && self->motion_ == m && !m->stopSent; };
    const QString what = m->homing ? QStringLiteral("homing") : QStringLiteral("the move");
    readState([self, m, alive, what](const Ds402Result& st) {
        if (!alive()) return;
        if (!st.ok)
            return self->motionFail(m,
                                    QStringLiteral("the drive stopped answering during %1 (%2)").arg(what, st.error));
        m->last.statusword = st.statusword;
        if (st.statusword & ds402::sw::Fault) {
            // Name the error code 603Fh (the vendor alarm comes by EMCY as well).
            self->sdo_.upload(self->node_, self->objectIndex(0x603F), 0,
                              [self, m, alive, what, sw = st.statusword](const SdoResult& e) {
                                  if (!alive()) return;
                                  self->motionFail(m, QStringLiteral("%1 faulted during %2 (statusword 0x%3%4)")
                                                          .arg(self->prefix(), what, hex4(sw),
                                                               e.ok ? QStringLiteral(", error code 603Fh = %1h")
                                                                          .arg(hex4(uint16_t(motionI32(e.data))))
                                                                    : QString()));
                              });
            return;
        }
        if (st.state != State::OperationEnabled)
            return self->motionFail(m, QStringLiteral("%1 left Operation enabled during %2 (now %3)")
                                           .arg(self->prefix(), what, ds402::stateName(st.state)));
        self->sdo_.upload(self->node_, self->objectIndex(0x6064), 0, [self, m, alive, what](const SdoResult& p) {
            if (!alive()) return;
            if (!p.ok)
                return self->motionFail(m, QStringLiteral("position read failed during %1: %2").arg(what, p.error));
            m->last.position = motionI32(p.data);
            self->sdo_.upload(self->node_, self->objectIndex(0x606C), 0, [self, m, alive, what](const SdoResult& v) {
                if (!alive()) return;
                if (!v.ok)
                    return self->motionFail(m, QStringLiteral("velocity read failed during %1: %2").arg(what, v.error));
                m->last.velocity = motionI32(v.data);
                m->last.ms = m->started.elapsed();
                if (m->progress) m->progress(m->last);
                if (!alive()) return;  // the progress callback may stop it
                const QString verdict = m->check ? m->check(m->last) : QString();
                if (verdict == u"ok") {
                    m->stopSent = true;  // no more monitoring
                    auto end = [self, m](const QString& error) {
                        if (!self || self->motion_ != m) return;
                        if (!error.isEmpty()) return self->motionFail(m, error);
                        Ds402Result r;
                        r.ok = true;
                        r.statusword = m->last.statusword;
                        r.state = ds402::stateFromStatusword(r.statusword);
                        self->motionEnd(m, r);
                    };
                    return m->finish ? m->finish(end) : end({});
                }
                if (!verdict.isEmpty()) return self->motionFail(m, verdict);
                if (m->started.elapsed() > m->timeoutMs)
                    return self->motionFail(m, QStringLiteral("%1 did not finish %2 within %3 ms (statusword 0x%4)")
                                                   .arg(self->prefix(), what)
                                                   .arg(m->timeoutMs)
                                                   .arg(hex4(m->last.statusword)));
                QTimer::singleShot(kMotionPollMs, self, [self, m] {
                    if (self) self->motionMonitor(m);
                });
            });
        });
    });
}

void Ds402Controller::stopMotion(bool quickStop, const QString& reason) {
    auto m = motion_;
    if (!m) return;
    if (!m->stopping) {
        m->stopping = true;
        m->stopReason = reason;
    }
    if (!m->running) {
        // Still setting up: the chain stops before its next step; a quick stop goes out now.
        if (quickStop && !m->quickSent) {
            m->quickSent = true;
            writeControlword(ds402::controlwordFor(Command::QuickStop), QStringLiteral("Quick stop: %1").arg(reason),
                             [](const SdoResult&) {});
        }
        return;
    }
    if (m->stopSent) {
        // A halt is under way and the user asks for more: quick stop at once.
        if (quickStop && !m->quickSent) {
            m->quickSent = true;
            writeControlword(ds402::controlwordFor(Command::QuickStop), QStringLiteral("Quick stop: %1").arg(reason),
                             [](const SdoResult&) {});
        }
        return;
    }
    m->stopSent = true;
    m->quickSent = quickStop;
    QPointer<Ds402Controller> self(this);
    // Halt: bit 8 with bit 4 low, the drive brakes on its ramp and stays enabled (CiA 402-2
    // §12.2; bit 4 low also interrupts homing, §13.1, and AIMOTOR's "1F -> 0F", which ignores
    // halt in homing). Quick stop: 0002h (§6.2, transition 11).
    const uint16_t cw = quickStop ? ds402::controlwordFor(Command::QuickStop) : uint16_t(0x010F);
    writeControlword(
        cw, quickStop ? QStringLiteral("Quick stop: %1").arg(reason) : QStringLiteral("Halt: %1").arg(reason),
        [self, m](const SdoResult& h) {
            if (!self || self->motion_ != m) return;
            if (!h.ok) return self->motionFail(m, QStringLiteral("the stop was refused: ") + h.error);
            auto still = std::make_shared<QElapsedTimer>();
            still->start();
            auto wait = std::make_shared<std::function<void()>>();
            *wait = [self, m, still, wait] {
                if (!self || self->motion_ != m) return;
                self->sdo_.upload(
                    self->node_, self->objectIndex(0x606C), 0, [self, m, still, wait](const SdoResult& v) {
                        if (!self || self->motion_ != m) return;
                        if (!v.ok) {
                            *wait = nullptr;
                            return self->motionFail(m,
                                                    QStringLiteral("velocity read failed while stopping: ") + v.error);
                        }
                        m->last.velocity = motionI32(v.data);
                        m->last.ms = m->started.elapsed();
                        if (std::abs(m->last.velocity) <= 1) {
                            *wait = nullptr;
                            return self->readState([self, m](const Ds402Result& st) {
                                if (!self || self->motion_ != m) return;
                                Ds402Result out = st;
                                out.ok = false;
                                out.stopReason = m->stopReason;
                                out.error = QStringLiteral("%1 stopped (%2)").arg(self->prefix(), m->stopReason);
                                self->motionEnd(m, out);
                            });
                        }
                        if (still->elapsed() > kMotionStopTimeoutMs) {
                            *wait = nullptr;
                            return self->motionFail(
                                m, QStringLiteral("the motor did not stop within %1 ms").arg(kMotionStopTimeoutMs));
                        }
                        QTimer::singleShot(kMotionPollMs, self, [wait] {
                            if (*wait) (*wait)();
                        });
                    });
            };
            (*wait)();
        });
}

void Ds402Controller::motionStopped(std::shared_ptr<Motion> m, const QString& why) {
    Ds402Result out;
    out.ok = false;
    out.stopReason = m->stopReason;
    out.error = QStringLiteral("%1: %2").arg(prefix(), why);
    motionEnd(m, out);
}

void Ds402Controller::motionEnd(std::shared_ptr<Motion> m, Ds402Result r) {
    if (motion_ == m) motion_.reset();
    if (m->done) m->done(r);
}

void Ds402Controller::motionFail(std::shared_ptr<Motion> m, const QString& error) {
    m->stopSent = true;
    // Something went wrong (refused write, homing error, fault, silence, time): quick stop,
    // then no power (DESIGN.md "Reliability and safety").
    QPointer<Ds402Controller> self(this);
    writeControlword(
        ds402::controlwordFor(Command::QuickStop),
        QStringLiteral("Quick stop, %1 failed").arg(m->homing ? QStringLiteral("homing") : QStringLiteral("move")),
        [](const SdoResult&) {});
    writeControlword(
        ds402::controlwordFor(Command::DisableVoltage),
        QStringLiteral("Disable voltage, %1 failed").arg(m->homing ? QStringLiteral("homing") : QStringLiteral("move")),
        [self, m, error](const SdoResult& w) {
            Ds402Result out;
            out.ok = false;
            out.statusword = m->last.statusword;
            out.state = ds402::stateFromStatusword(out.statusword);
            out.stopReason = m->stopReason;
            out.error = error + (w.ok ? QStringLiteral("; drive disabled")
                                      : QStringLiteral("; disabling the drive failed too: ") + w.error);
            if (self) self->motionEnd(m, out);
            else if (m->done) m->done(out);
        });
}

}  // namespace coscope::canopen
