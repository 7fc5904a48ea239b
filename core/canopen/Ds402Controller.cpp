// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/Ds402Controller.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QTimer>

namespace coscope::canopen {

using ds402::Command;
using ds402::State;

namespace {
QString upperFirst(QString s) {
    if (!s.isEmpty()) s[0] = s[0].toUpper();
    return s;
}
QByteArray u16(uint16_t v) {
    QByteArray b(2, 0);
    b[0] = static_cast<char>(v & 0xFF);
    b[1] = static_cast<char>(v >> 8);
    return b;
}
uint16_t readU16(const QByteArray& b) {
    return b.size() >= 2 ? static_cast<uint16_t>(uint8_t(b[0]) | (uint8_t(b[1]) << 8))
                         : (b.size() == 1 ? uint8_t(b[0]) : 0);
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
    case State::NotReadyToSwitchOn:
        *mask = 0x4F;
        *value = 0x00;
        return true;
    case State::SwitchOnDisabled:
        *mask = 0x4F;
        *value = 0x40;
        return true;
    case State::ReadyToSwitchOn:
        *mask = 0x6F;
        *value = 0x21;
        return true;
    case State::SwitchedOn:
        *mask = 0x6F;
        *value = 0x23;
        return true;
    case State::OperationEnabled:
        *mask = 0x6F;
        *value = 0x27;
        return true;
    case State::QuickStopActive:
        *mask = 0x6F;
        *value = 0x07;
        return true;
    case State::FaultReactionActive:
        *mask = 0x4F;
        *value = 0x0F;
        return true;
    case State::Fault:
        *mask = 0x4F;
        *value = 0x08;
        return true;
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
        parts << QStringLiteral("%1 bit %2 (%3)")
                     .arg((value & m) ? QStringLiteral("missing") : QStringLiteral("unexpected"))
                     .arg(bit)
                     .arg(ds402::statuswordBitName(bit));
    }
    return parts.join(QStringLiteral(", "));
}

QString Ds402Controller::explainMismatch(State s, uint16_t sw) {
    uint16_t mask = 0, value = 0;
    if (!expectedStatusword(s, &mask, &value)) return {};
    // Voltage enabled (bit 4) is needed from Switched on on; remote (bit 9) for any command.
    if (s == State::SwitchedOn || s == State::OperationEnabled) {
        mask |= ds402::sw::VoltageEnabled;
        value |= ds402::sw::VoltageEnabled;
    }
    if (!(sw & ds402::sw::Remote) && !(sw & ds402::sw::Fault)) mask |= ds402::sw::Remote, value |= ds402::sw::Remote;
    QStringList parts;
    for (int bit : {3, 4, 9, 5, 6, 0, 1, 2}) {  // the likely causes first
        const uint16_t m = uint16_t(1u << bit);
        if (!(mask & m) || (sw & m) == (value & m)) continue;
        const bool set = sw & m;
        const QString meaning = ds402::statuswordBitMeaning(bit, set);
        parts << QStringLiteral("%1 (bit %2) is %3%4")
                     .arg(upperFirst(ds402::statuswordBitName(bit)))
                     .arg(bit)
                     .arg(set ? QStringLiteral("on") : QStringLiteral("off"),
                          meaning.isEmpty() ? QString() : QStringLiteral(": ") + meaning);
    }
    return parts.join(QStringLiteral(". "));
}

void Ds402Controller::readState(Ds402Callback done) {
    sdo_.upload(node_, objectIndex(0x6041), 0, [done](const SdoResult& r) {
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
        onSend_(QStringLiteral("%1: %2h = 0x%3 (%4)")
                    .arg(prefix(), QString::number(objectIndex(0x6040), 16).toUpper(),
                         QStringLiteral("%1").arg(cw, 4, 16, QChar(u'0')).toUpper(), why));
    // The bus's record of the drives CoScope enabled (EnabledDrives): an enabling word before it
    // goes out, a disabling one once the drive took it.
    EnabledDrives& record = sdo_.context().enabledDrives();
    if (EnabledDrives::enablesVoltage(cw)) record.noteControlword(node_, axis_, cw);
    sdo_.download(node_, objectIndex(0x6040), 0, u16(cw),
                  [&record, node = node_, axis = axis_, cw, then = std::move(then)](const SdoResult& r) {
                      if (r.ok && !EnabledDrives::enablesVoltage(cw)) record.noteControlword(node, axis, cw);
                      if (then) then(r);
                  });
}

void Ds402Controller::waitForState(State target, State alternative, QElapsedTimer started, Ds402Callback done) {
    QPointer<Ds402Controller> self(this);
    readState([self, target, alternative, started, done](const Ds402Result& r) {
        if (!self) return;
        if (!r.ok) return done(r);
        uint16_t mask = 0, value = 0;
        expectedStatusword(target, &mask, &value);
        if ((r.statusword & mask) == value) {
            Ds402Result out = r;
            out.target = target;
            return done(out);
        }
        if (alternative != State::Unknown && expectedStatusword(alternative, &mask, &value) &&
            (r.statusword & mask) == value)
            return done(r);
        if ((r.statusword & ds402::sw::Fault) && target != State::SwitchOnDisabled && target != State::Fault) {
            // The drive tripped while we waited: say so at once instead of timing out.
            Ds402Result out = r;
            out.ok = false;
            out.target = target;
            out.advice = explainMismatch(target, r.statusword);
            out.error = QStringLiteral("%1 went to %2 instead of %3: statusword 0x%4")
                            .arg(self->prefix(), ds402::stateName(r.state), ds402::stateName(target),
                                 QStringLiteral("%1").arg(r.statusword, 4, 16, QChar(u'0')).toUpper());
            return done(out);
        }
        if (started.elapsed() >= self->timeoutMs_) {
            Ds402Result out = r;
            out.ok = false;
            out.target = target;
            out.advice = explainMismatch(target, r.statusword);
            out.error = QStringLiteral("%1 did not reach %2 within %3 ms: statusword 0x%4 (%5): %6")
                            .arg(self->prefix(), ds402::stateName(target))
                            .arg(self->timeoutMs_)
                            .arg(QStringLiteral("%1").arg(r.statusword, 4, 16, QChar(u'0')).toUpper(),
                                 ds402::stateName(r.state), describeMismatch(target, r.statusword));
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
        writeControlword(0x0000, QStringLiteral("bit 7 low before fault reset"),
                         [self, afterWrite, done](const SdoResult& r) {
                             if (!self) return;
                             if (!r.ok) {
                                 Ds402Result out;
                                 out.error = r.error;
                                 return done(out);
                             }
                             self->writeControlword(ds402::controlwordFor(Command::FaultReset),
                                                    ds402::commandName(Command::FaultReset), afterWrite);
                         });
        return;
    }
    writeControlword(ds402::controlwordFor(command), ds402::commandName(command), afterWrite);
}

void Ds402Controller::runSteps(std::shared_ptr<std::vector<Step>> steps, size_t i, bool disableOnFailure,
                               Ds402Callback done) {
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
    writeControlword(ds402::controlwordFor(Command::DisableVoltage), QStringLiteral("Disable voltage, enable failed"),
                     [r, done](const SdoResult& w) {
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
        case State::FaultReactionActive:
            steps->push_back({Command::FaultReset, State::SwitchOnDisabled});
            [[fallthrough]];
        case State::SwitchOnDisabled:
        case State::NotReadyToSwitchOn:
        case State::QuickStopActive:
        case State::Unknown: steps->push_back({Command::Shutdown, State::ReadyToSwitchOn}); [[fallthrough]];
        case State::ReadyToSwitchOn: steps->push_back({Command::SwitchOn, State::SwitchedOn}); [[fallthrough]];
        case State::SwitchedOn: steps->push_back({Command::EnableOperation, State::OperationEnabled}); break;
        case State::OperationEnabled: return done(r);
        }
        if (r.state == State::QuickStopActive)
            steps->insert(steps->begin(), {Command::DisableVoltage, State::SwitchOnDisabled});
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
    if (onSend_)
        onSend_(QStringLiteral("%1: %2h = %3 (%4)")
                    .arg(prefix(), QString::number(objectIndex(0x6060), 16).toUpper())
                    .arg(mode)
                    .arg(ds402::modeName(mode)));
    sdo_.download(
        node_, objectIndex(0x6060), 0, QByteArray(1, static_cast<char>(mode)), [self, mode, done](const SdoResult& w) {
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
                self->sdo_.upload(
                    self->node_, self->objectIndex(0x6061), 0, [self, mode, done, started, poll](const SdoResult& r) {
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
                            out.error =
                                QStringLiteral(
                                    "%1: modes of operation display %2h shows %3 (%4), not %5 (%6), after %7 ms")
                                    .arg(self->prefix(), QString::number(self->objectIndex(0x6061), 16).toUpper())
                                    .arg(out.mode)
                                    .arg(ds402::modeName(out.mode))
                                    .arg(mode)
                                    .arg(ds402::modeName(mode))
                                    .arg(self->timeoutMs_);
                            *poll = nullptr;
                            return done(out);
                        }
                        QTimer::singleShot(self->pollMs_, self, [poll] {
                            if (*poll) (*poll)();
                        });
                    });
            };
            (*poll)();
        });
}

void Ds402Controller::quickStop(Ds402Callback done) { transition(Command::QuickStop, std::move(done)); }

void Ds402Controller::disableVoltage(Ds402Callback done) {
    QPointer<Ds402Controller> self(this);
    writeControlword(ds402::controlwordFor(Command::DisableVoltage), ds402::commandName(Command::DisableVoltage),
                     [self, done](const SdoResult& w) {
                         if (!self) return;
                         if (!w.ok) {
                             Ds402Result out;
                             out.error = w.error;
                             return done(out);
                         }
                         self->readState(done);
                     });
}

// --- script (dry run)

std::vector<ScriptStep> Ds402Controller::transitionSteps(uint8_t node, int axis, Command command) {
    const uint16_t off = static_cast<uint16_t>(axis * 0x800);
    auto write = [&](uint16_t cw, const QString& why) {
        ScriptStep st;
        st.kind = ScriptStep::Kind::SdoWrite;
        st.node = node;
        st.index = static_cast<uint16_t>(0x6040 + off);
        st.data = u16(cw);
        st.why = why;
        return st;
    };
    std::vector<ScriptStep> out;
    State target = State::Unknown;
    switch (command) {
    case Command::FaultReset:
        out.push_back(
            write(0x0000, QStringLiteral("Controlword bit 7 low first: fault reset acts on its rising edge")));
        out.push_back(write(0x0080, QStringLiteral("Clear the fault (Fault reset, CiA 402 transition 15)")));
        target = State::SwitchOnDisabled;
        break;
    case Command::Shutdown:
        out.push_back(write(0x0006, QStringLiteral("Make the drive ready (Shutdown, transition 2)")));
        target = State::ReadyToSwitchOn;
        break;
    case Command::SwitchOn:
        out.push_back(write(
            0x0007, QStringLiteral("Switch the power stage on, motor not yet energised (Switch on, transition 3)")));
        target = State::SwitchedOn;
        break;
    case Command::EnableOperation:
    case Command::SwitchOnAndEnable:
        out.push_back(
            write(0x000F,
                  QStringLiteral(
                      "Energise the motor: it holds position and follows commands (Enable operation, transition 4)")));
        target = State::OperationEnabled;
        break;
    case Command::DisableOperation:
        out.push_back(write(
            0x0007, QStringLiteral("Stop following commands, power stage stays on (Disable operation, transition 5)")));
        target = State::SwitchedOn;
        break;
    case Command::DisableVoltage:
        out.push_back(write(0x0000, QStringLiteral("Remove power from the motor (Disable voltage)")));
        target = State::SwitchOnDisabled;
        break;
    case Command::QuickStop:
        out.push_back(write(0x0002, QStringLiteral("Brake on the quick stop ramp (Quick stop)")));
        target = State::Unknown;  // Quick stop active or Switch on disabled (605Ah)
        break;
    }
    uint16_t mask = 0, value = 0;
    if (expectedStatusword(target, &mask, &value)) {
        ScriptStep e;
        e.kind = ScriptStep::Kind::SdoExpect;
        e.node = node;
        e.index = static_cast<uint16_t>(0x6041 + off);
        e.data = u16(value);
        e.mask = u16(mask);
        e.why = QStringLiteral("Statusword must show %1").arg(ds402::stateName(target));
        out.push_back(e);
    }
    return out;
}

CommandScript Ds402Controller::enableScript(uint8_t node, int axis, State from, std::optional<int8_t> mode) {
    CommandScript script;
    script.title = QStringLiteral("CiA 402 enable of node %1%2")
                       .arg(node)
                       .arg(axis ? QStringLiteral(" axis %1").arg(axis) : QString());
    const uint16_t off = static_cast<uint16_t>(axis * 0x800);
    if (mode) {
        ScriptStep w;
        w.kind = ScriptStep::Kind::SdoWrite;
        w.node = node;
        w.index = static_cast<uint16_t>(0x6060 + off);
        w.data = QByteArray(1, static_cast<char>(*mode));
        w.why = QStringLiteral("Choose the mode of operation: %1 (6060h)").arg(ds402::modeName(*mode));
        script.steps.push_back(w);
        ScriptStep e = w;
        e.kind = ScriptStep::Kind::SdoExpect;
        e.index = static_cast<uint16_t>(0x6061 + off);
        e.why = QStringLiteral("The drive confirms the mode (modes of operation display 6061h)");
        script.steps.push_back(e);
    }
    State s = from;
    if (from == State::Unknown || from == State::NotReadyToSwitchOn) s = State::SwitchOnDisabled;
    if (from == State::FaultReactionActive) s = State::Fault;
    for (int guard = 0; guard < 6; ++guard) {
        const auto cmd = ds402::nextEnableCommand(s);
        if (!cmd) break;
        for (ScriptStep& st : transitionSteps(node, axis, *cmd)) script.steps.push_back(st);
        switch (*cmd) {
        case Command::FaultReset:
        case Command::DisableVoltage: s = State::SwitchOnDisabled; break;
        case Command::Shutdown: s = State::ReadyToSwitchOn; break;
        case Command::SwitchOn: s = State::SwitchedOn; break;
        default: s = State::OperationEnabled; break;
        }
    }
    return script;
}

}  // namespace coscope::canopen
