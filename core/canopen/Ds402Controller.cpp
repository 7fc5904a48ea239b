// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/Ds402Controller.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QTimer>

namespace coscope::canopen {

using ds402::Command;
using ds402::State;

namespace {
QByteArray u16(uint16_t v) {
    QByteArray b(2, 0);
    b[0] = static_cast<char>(v & 0xFF);
    b[1] = static_cast<char>(v >> 8);
    return b;
}
uint16_t readU16(const QByteArray& b) {
    return b.size() >= 2 ? static_cast<uint16_t>(uint8_t(b[0]) | (uint8_t(b[1]) << 8)) : (b.size() == 1 ? uint8_t(b[0]) : 0);
}
}  // namespace

Ds402Controller::Ds402Controller(SdoClient& sdo, uint8_t node, int axis, QObject* parent)
    : QObject(parent), sdo_(sdo), node_(node), axis_(axis) {}

QString Ds402Controller::prefix() const {
    return axis_ ? QStringLiteral("node %1 axis %2").arg(node_).arg(axis_) : QStringLiteral("node %1").arg(node_);
}

bool Ds402Controller::expectedStatusword(State s, uint16_t* mask, uint16_t* value) {
    // CiA 402-2 Table 30: bits 0-3, 5, 6.
    switch (s) {
    case State::NotReadyToSwitchOn: *mask = 0x4F; *value = 0x00; return true;
    case State::SwitchOnDisabled: *mask = 0x4F; *value = 0x40; return true;
    case State::ReadyToSwitchOn: *mask = 0x6F; *value = 0x21; return true;
    case State::SwitchedOn: *mask = 0x6F; *value = 0x23; return true;
    case State::OperationEnabled: *mask = 0x6F; *value = 0x27; return true;
    case State::QuickStopActive: *mask = 0x6F; *value = 0x07; return true;
    case State::FaultReactionActive: *mask = 0x4F; *value = 0x0F; return true;
    case State::Fault: *mask = 0x4F; *value = 0x08; return true;
    case State::Unknown: break;
    }
    return false;
}

QString Ds402Controller::describeMismatch(State s, uint16_t sw) {
    uint16_t mask = 0, value = 0;
    if (!expectedStatusword(s, &mask, &value)) return {};
    QStringList parts;
    for (int bit = 0; bit < 16; ++bit) {
        const uint16_t m = uint16_t(1u << bit);
        if (!(mask & m) || (sw & m) == (value & m)) continue;
        parts << QStringLiteral("%1 bit %2 (%3)").arg((value & m) ? QStringLiteral("missing") : QStringLiteral("unexpected")).arg(bit).arg(ds402::statuswordBitName(bit));
    }
    return parts.join(QStringLiteral(", "));
}

void Ds402Controller::readState(Ds402Callback done) {
    sdo_.upload(node_, objectIndex(0x6041), 0, [this, done](const SdoResult& r) {
        Ds402Result out;
        if (!r.ok) {
            out.error = r.error;
            return done(out);
        }
        out.ok = true;
        out.statusword = readU16(r.data);
        out.state = ds402::stateFromStatusword(out.statusword);
        done(out);
    });
}

void Ds402Controller::writeControlword(uint16_t cw, const QString& why, std::function<void(const SdoResult&)> then) {
    if (onSend_)
        onSend_(QStringLiteral("%1: %2h = 0x%3 (%4)").arg(prefix(), QString::number(objectIndex(0x6040), 16).toUpper(), QStringLiteral("%1").arg(cw, 4, 16, QChar(u'0')).toUpper(), why));
    sdo_.download(node_, objectIndex(0x6040), 0, u16(cw), std::move(then));
}

void Ds402Controller::waitForState(State target, State alternative, QElapsedTimer started, Ds402Callback done) {
    QPointer<Ds402Controller> self(this);
    readState([self, target, alternative, started, done](const Ds402Result& r) {
        if (!self) return;
        if (!r.ok) return done(r);
        uint16_t mask = 0, value = 0;
        expectedStatusword(target, &mask, &value);
        if ((r.statusword & mask) == value) return done(r);
        if (alternative != State::Unknown && expectedStatusword(alternative, &mask, &value) && (r.statusword & mask) == value) return done(r);
        if (started.elapsed() >= self->timeoutMs_) {
            Ds402Result out = r;
            out.ok = false;
            out.error = QStringLiteral("%1 did not reach %2 within %3 ms: statusword 0x%4 (%5): %6")
                            .arg(self->prefix(), ds402::stateName(target))
                            .arg(self->timeoutMs_)
                            .arg(QStringLiteral("%1").arg(r.statusword, 4, 16, QChar(u'0')).toUpper(), ds402::stateName(r.state), describeMismatch(target, r.statusword));
            return done(out);
        }
        QTimer::singleShot(self->pollMs_, self, [self, target, alternative, started, done] {
            if (self) self->waitForState(target, alternative, started, done);
        });
    });
}

void Ds402Controller::transition(Command command, Ds402Callback done) {
    State target = State::Unknown;
    switch (command) {
    case Command::Shutdown: target = State::ReadyToSwitchOn; break;
    case Command::SwitchOn:
    case Command::DisableOperation: target = State::SwitchedOn; break;
    case Command::SwitchOnAndEnable:
    case Command::EnableOperation: target = State::OperationEnabled; break;
    case Command::DisableVoltage: target = State::SwitchOnDisabled; break;
    case Command::QuickStop: target = State::QuickStopActive; break;  // or Switch on disabled, below
    case Command::FaultReset: target = State::SwitchOnDisabled; break;
    }
    QPointer<Ds402Controller> self(this);
    // Quick stop ends in Switch on disabled when the drive was not operating (transitions 7,
    // 10) or its quick stop option code (605Ah) is 0-3 (CiA 402-2 §6.2.1).
    const State alternative = command == Command::QuickStop ? State::SwitchOnDisabled : State::Unknown;
    auto afterWrite = [self, target, alternative, done](const SdoResult& r) {
        if (!self) return;
        if (!r.ok) {
            Ds402Result out;
            out.error = r.error;
            return done(out);
        }
        QElapsedTimer t;
        t.start();
        self->waitForState(target, alternative, t, done);
    };
    if (command == Command::FaultReset) {
        // Fault reset acts on the rising edge of bit 7 (CiA 402-2 §6.2.1): first 0, then 80h.
        writeControlword(0x0000, QStringLiteral("bit 7 low before fault reset"), [self, afterWrite, done](const SdoResult& r) {
            if (!self) return;
            if (!r.ok) {
                Ds402Result out;
                out.error = r.error;
                return done(out);
            }
            self->writeControlword(ds402::controlwordFor(Command::FaultReset), ds402::commandName(Command::FaultReset), afterWrite);
        });
        return;
    }
    writeControlword(ds402::controlwordFor(command), ds402::commandName(command), afterWrite);
}

void Ds402Controller::runSteps(std::shared_ptr<std::vector<Step>> steps, size_t i, bool disableOnFailure, Ds402Callback done) {
    if (i >= steps->size()) return readState(done);
    QPointer<Ds402Controller> self(this);
    transition((*steps)[i].command, [self, steps, i, disableOnFailure, done](const Ds402Result& r) {
        if (!self) return;
        if (!r.ok) {
            if (disableOnFailure) return self->failSafe(r, done);
            return done(r);
        }
        self->runSteps(steps, i + 1, disableOnFailure, done);
    });
}

void Ds402Controller::failSafe(Ds402Result r, Ds402Callback done) {
    // Leave the drive disabled (DESIGN.md "Reliability and safety").
    writeControlword(ds402::controlwordFor(Command::DisableVoltage), QStringLiteral("Disable voltage, enable failed"), [r, done](const SdoResult& w) {
        Ds402Result out = r;
        out.ok = false;
        if (!w.ok) out.error += QStringLiteral("; disabling the drive failed too: ") + w.error;
        else out.error += QStringLiteral("; drive disabled");
        done(out);
    });
}

void Ds402Controller::enable(Ds402Callback done) {
    QPointer<Ds402Controller> self(this);
    readState([self, done](const Ds402Result& r) {
        if (!self) return;
        if (!r.ok) return done(r);
        if (r.state == State::NotReadyToSwitchOn) {
            // Still initialising after power-on: it moves to Switch on disabled by itself.
            QElapsedTimer t;
            t.start();
            return self->waitForState(State::SwitchOnDisabled, State::Unknown, t, [self, done](const Ds402Result& w) {
                if (!self) return;
                if (!w.ok) return done(w);
                self->enable(done);
            });
        }
        auto steps = std::make_shared<std::vector<Step>>();
        switch (r.state) {
        case State::Fault:
        case State::FaultReactionActive: steps->push_back({Command::FaultReset, State::SwitchOnDisabled}); [[fallthrough]];
        case State::SwitchOnDisabled:
        case State::NotReadyToSwitchOn:
        case State::QuickStopActive:
        case State::Unknown: steps->push_back({Command::Shutdown, State::ReadyToSwitchOn}); [[fallthrough]];
        case State::ReadyToSwitchOn: steps->push_back({Command::SwitchOn, State::SwitchedOn}); [[fallthrough]];
        case State::SwitchedOn: steps->push_back({Command::EnableOperation, State::OperationEnabled}); break;
        case State::OperationEnabled: return done(r);
        }
        if (r.state == State::QuickStopActive) steps->insert(steps->begin(), {Command::DisableVoltage, State::SwitchOnDisabled});
        self->runSteps(steps, 0, true, done);
    });
}

void Ds402Controller::disable(Ds402Callback done) {
    QPointer<Ds402Controller> self(this);
    readState([self, done](const Ds402Result& r) {
        if (!self) return;
        if (!r.ok) return done(r);
        auto steps = std::make_shared<std::vector<Step>>();
        if (r.state == State::SwitchOnDisabled || r.state == State::Fault) return done(r);
        if (r.state == State::OperationEnabled) steps->push_back({Command::Shutdown, State::ReadyToSwitchOn});
        steps->push_back({Command::DisableVoltage, State::SwitchOnDisabled});
        self->runSteps(steps, 0, false, done);
    });
}

void Ds402Controller::setMode(int8_t mode, Ds402Callback done) {
    QPointer<Ds402Controller> self(this);
    if (onSend_) onSend_(QStringLiteral("%1: %2h = %3 (%4)").arg(prefix(), QString::number(objectIndex(0x6060), 16).toUpper()).arg(mode).arg(ds402::modeName(mode)));
    sdo_.download(node_, objectIndex(0x6060), 0, QByteArray(1, static_cast<char>(mode)), [self, mode, done](const SdoResult& w) {
        if (!self) return;
        if (!w.ok) {
            Ds402Result out;
            out.error = w.error;
            return done(out);
        }
        auto started = std::make_shared<QElapsedTimer>();
        started->start();
        auto poll = std::make_shared<std::function<void()>>();
        *poll = [self, mode, done, started, poll] {
            if (!self) return;
            self->sdo_.upload(self->node_, self->objectIndex(0x6061), 0, [self, mode, done, started, poll](const SdoResult& r) {
                if (!self) return;
                Ds402Result out;
                if (!r.ok) {
                    out.error = r.error;
                    *poll = nullptr;
                    return done(out);
                }
                out.mode = r.data.isEmpty() ? 0 : static_cast<int8_t>(r.data[0]);
                if (out.mode == mode) {
                    out.ok = true;
                    *poll = nullptr;
                    return done(out);
                }
                if (started->elapsed() >= self->timeoutMs_) {
                    out.error = QStringLiteral("%1: modes of operation display %2h shows %3 (%4), not %5 (%6), after %7 ms")
                                    .arg(self->prefix(), QString::number(self->objectIndex(0x6061), 16).toUpper())
                                    .arg(out.mode).arg(ds402::modeName(out.mode)).arg(mode).arg(ds402::modeName(mode)).arg(self->timeoutMs_);
                    *poll = nullptr;
                    return done(out);
                }
                QTimer::singleShot(self->pollMs_, self, [poll] { if (*poll) (*poll)(); });
            });
        };
        (*poll)();
    });
}

}  // namespace coscope::canopen
