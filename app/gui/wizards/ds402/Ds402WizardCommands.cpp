// SPDX-License-Identifier: GPL-3.0-or-later
// The CiA 402 wizard: what its buttons do (steps, mode, test move, quick stop, disable, dry run)
// and the disable on close, quit or a lost connection.
#include "app/gui/wizards/ds402/Ds402Wizard.h"

#include "app/gui/language/CoreText.h"

#include "core/canopen/SdoClient.h"

#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/ds402/Ds402FramesTabs.h"
#include "app/gui/wizards/ds402/Ds402ModeBox.h"
#include "app/gui/wizards/ds402/Ds402MotionPlot.h"
#include "app/gui/wizards/ds402/Ds402StatusPanel.h"
#include "app/gui/wizards/ds402/Ds402StepBar.h"
#include "app/gui/wizards/ds402/Ds402TestMoveBox.h"
#include "app/gui/wizards/ds402/Ds402VendorNotes.h"

#include <QMessageBox>
#include <QPointer>
#include <QTimer>

#include <spdlog/spdlog.h>

namespace coscope::gui {

using canopen::Ds402Result;
using canopen::Ds402TestMove;
using canopen::SdoResult;
using canopen::ds402::Command;
using canopen::ds402::State;

namespace {
QString hex4(uint32_t v) { return QStringLiteral("%1").arg(v, 4, 16, QChar(u'0')).toUpper(); }
}  // namespace

// --- steps

bool Ds402Wizard::confirm(const QString& title, const QString& text) {
    if (autoConfirm_) return true;
    return QMessageBox::question(this, title, text, QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel) ==
           QMessageBox::Yes;
}

QString Ds402Wizard::checkAdvice() const {
    QStringList out;
    if (const auto notes = ds402VendorNotes(dictionary_)) out << notes->before;
    out << tr("Check main power, the enable and safe torque off (STO) inputs, and the drive's own display.");
    return out.join(u' ');
}

bool Ds402Wizard::runStep(Command command, QString* why) {
    if (const QString r = sendRefusal(); !r.isEmpty()) {
        if (why) *why = r;
        return false;
    }
    if (busy_) {
        if (why) *why = tr("Wait for the current step to finish.");
        return false;
    }
    if (command == Command::EnableOperation &&
        !confirm(
            tr("Enable operation"),
            tr("Enable operation energises the motor of node %1: it will hold its position and follow commands.\n\n"
               "Make sure the machine is safe to move and people are clear.\n\nSend 6040h = 000Fh now?")
                .arg(node_))) {
        if (why) *why = tr("Enable operation was not confirmed; nothing was sent.");
        return false;
    }
    disarm(tr("a state machine step"));
    busy_ = true;
    sentCommands_ = true;
    const QString name = coreText(canopen::ds402::commandName(command));
    setMessage(tr("%1: sending… (%2)").arg(name, ds402StepExplanation(command)));
    updateButtons();
    QPointer<Ds402Wizard> self(this);
    ctl_->transition(command, [self, command, name](const Ds402Result& r) {
        if (!self) return;
        if (r.ok) {
            self->busy_ = false;
            self->showState(r.state, r.statusword);
            self->setMessage(tr("%1 done: the drive is now in %2 (statusword %3h).")
                                 .arg(name, coreText(canopen::ds402::stateName(r.state)), hex4(r.statusword)));
            self->poll_->start();  // the next idle read one full interval from now
            emit self->stepFinished(true);
            return;
        }
        // Failed: say which step and what the drive answered, then leave it disabled.
        if (r.statusword || r.state != State::Unknown) self->showState(r.state, r.statusword);
        QString text = tr("Step “%1” failed: %2.").arg(name, coreText(r.error));
        if (!r.advice.isEmpty())
            text += QStringLiteral("\n") + coreJoined(r.advice, QStringLiteral(". ")) + QStringLiteral(".");
        self->setMessage(text, true);
        if (!self->ctl_) return;
        self->ctl_->disableVoltage([self, text, command](const Ds402Result& d0) {
            if (!self) return;
            self->settleFaultReaction(d0, 0, [self, text, command](const Ds402Result& d) {
                if (!self) return;
                self->busy_ = false;
                QString t = text + (d.ok ? tr("\nThe drive was sent Disable voltage (6040h = 0000h) and is now in %1.")
                                               .arg(coreText(canopen::ds402::stateName(d.state)))
                                         : tr("\nDISABLING FAILED: %1").arg(coreText(d.error)));
                if (d.ok) self->showState(d.state, d.statusword);
                self->reading_ = true;
                self->afterState(d, [self, t] {
                    if (!self) return;
                    self->reading_ = false;
                    QString full = t;
                    if (!self->faultText_.isEmpty()) full += QStringLiteral("\n") + self->faultText_;
                    full += QStringLiteral("\n") + tr("What to check: ") + self->checkAdvice();
                    self->setMessage(full, true);
                    self->updateButtons();
                    emit self->stepFinished(false);
                });
                (void)command;
            });
        });
    });
    return true;
}

void Ds402Wizard::settleFaultReaction(const Ds402Result& r, int tries, std::function<void(const Ds402Result&)> done) {
    // Fault reaction active ends in Fault by itself once the drive has braked (CiA 402-2 §6.2,
    // transition 14): show where it ends, not the passing state.
    if (!r.ok || r.state != State::FaultReactionActive || tries >= kSettleTries || !ctl_) return done(r);
    QPointer<Ds402Wizard> self(this);
    QTimer::singleShot(kSettleMs, this, [self, tries, done] {
        if (!self || !self->ctl_) return;
        self->ctl_->readState([self, tries, done](const Ds402Result& again) {
            if (self) self->settleFaultReaction(again, tries + 1, done);
        });
    });
}

bool Ds402Wizard::chooseMode(int8_t mode, QString* why) {
    if (const QString r = sendRefusal(); !r.isEmpty()) {
        if (why) *why = r;
        return false;
    }
    if (busy_ || ctl_->testMoveActive()) {
        if (why) *why = tr("Wait for the current step to finish.");
        return false;
    }
    if (supported_ && !canopen::ds402::modeSupported(*supported_, mode)) {
        if (why)
            *why = tr("The drive does not list %1 as supported (6502h = %2h).")
                       .arg(coreText(canopen::ds402::modeName(mode)))
                       .arg(QStringLiteral("%1").arg(*supported_, 8, 16, QChar(u'0')).toUpper());
        return false;
    }
    disarm(tr("the mode of operation is being changed"));
    busy_ = true;
    updateButtons();
    setMessage(tr("Setting the mode of operation: 6060h = %1 (%2), then checking 6061h…")
                   .arg(mode)
                   .arg(coreText(canopen::ds402::modeName(mode))));
    QPointer<Ds402Wizard> self(this);
    ctl_->setMode(mode, [self, mode](const Ds402Result& r) {
        if (!self) return;
        self->busy_ = false;
        if (r.ok) {
            self->showDriveMode(r.mode);
            self->mode_->showVerified(r.mode);
            self->setMessage(tr("Mode set and verified: the drive shows %1 in 6061h.")
                                 .arg(coreText(canopen::ds402::modeName(r.mode))));
        } else {
            self->setMessage(
                tr("Could not set %1: %2").arg(coreText(canopen::ds402::modeName(mode)), coreText(r.error)), true);
        }
        self->updateButtons();
        emit self->modeFinished(r.ok);
    });
    return true;
}

// --- test move

void Ds402Wizard::setTestMove(const Ds402TestMove& m) { move_->setMove(m); }

Ds402TestMove Ds402Wizard::testMove() const { return move_->move(); }

bool Ds402Wizard::testMoveRunning() const { return ctl_ && ctl_->testMoveActive(); }

bool Ds402Wizard::armTestMove(QString* why) {
    if (const QString r = sendRefusal(); !r.isEmpty()) {
        if (why) *why = r;
        return false;
    }
    if (state_ != State::OperationEnabled) {
        if (why) *why = tr("Enable the drive first (Operation enabled), then arm the test move.");
        return false;
    }
    const Ds402TestMove m = testMove();
    if (const QString bad = m.check(); !bad.isEmpty()) {
        if (why) *why = bad;
        return false;
    }
    // The move runs in profile velocity (jog) or profile position (short move), never switching
    // the drive's mode silently: refused when the drive lacks that mode (6502h), asked otherwise.
    const int8_t needed = m.kind == Ds402TestMove::Kind::Jog ? 3 : 1;
    const int8_t current = mode_->driveMode();
    if (supported_ && !canopen::ds402::modeSupported(*supported_, needed)) {
        if (why)
            *why = tr("The test move needs %1, which the drive does not list as supported (6502h): no test move in %2.")
                       .arg(coreText(canopen::ds402::modeName(needed)), coreText(canopen::ds402::modeName(current)));
        return false;
    }
    if (!agreeMode(needed, tr("The drive is in %1; the test move needs %2: switch the mode of operation (6060h = %3)?"),
                   tr("Test move not armed: the mode of operation stays %1."), why))
        return false;
    const QString what = move_->describe(m);
    if (!confirm(tr("Test move"),
                 tr("While you hold “Hold to run”, the motor of node %1 will %2, for at most %3 ms.\n"
                    "Releasing the button stops it. Make sure the axis is free to move.\n\nArm the test move?")
                     .arg(node_)
                     .arg(what)
                     .arg(m.maxDurationMs))) {
        if (why) *why = tr("Test move not armed.");
        return false;
    }
    // Agreed: the move itself writes 6060h and checks 6061h before it starts (Ds402Controller).
    arm(m, current);
    return true;
}

void Ds402Wizard::arm(const Ds402TestMove& m, int8_t driveMode) {
    armed_ = true;
    armedKind_ = Armed::TestMove;
    armedMode_ = m.kind == Ds402TestMove::Kind::Jog ? 3 : 1;
    armedFromMode_ = driveMode;
    setMessage(armedMode_ == driveMode
                   ? tr("Test move armed: hold the “Hold to run” button to move, release it to stop.")
                   : tr("Test move armed: holding the “Hold to run” button first switches the mode of operation to %1, "
                        "then moves; "
                        "release it to stop.")
                         .arg(coreText(canopen::ds402::modeName(armedMode_))));
    updateButtons();
}

void Ds402Wizard::disarm(const QString& why) {
    if (!armed_) return;
    armed_ = false;
    spdlog::info("ds402 wizard: test move of node {} no longer armed ({})", node_, why.toStdString());
    setMessage(armedKind_ == Armed::TestMove
                   ? tr("The test move is no longer armed (%1): arm it again to move.").arg(why)
                   : tr("The position move is no longer armed (%1): arm it again to move.").arg(why));
    updateButtons();
}

bool Ds402Wizard::pressHoldToRun(QString* why) {
    if (const QString r = sendRefusal(); !r.isEmpty()) {
        if (why) *why = r;
        return false;
    }
    if (!armed_ || armedKind_ != Armed::TestMove) {
        if (why) *why = tr("Arm the test move first.");
        return false;
    }
    if (busy_ || ctl_->testMoveActive() || ctl_->motionActive()) {
        if (why) *why = tr("Wait for the current step to finish.");
        return false;
    }
    holding_ = true;
    move_->plot()->clear();
    const Ds402TestMove m = testMove();
    QPointer<Ds402Wizard> self(this);
    QString error;
    const bool started = ctl_->startTestMove(
        m,
        [self](const canopen::Ds402MotionSample& s) {
            if (!self) return;
            self->move_->plot()->addSample(double(s.ms), double(s.position), double(s.velocity));
            self->status_->setStatusword(s.statusword ? s.statusword : self->statusword_);
        },
        [self](const Ds402Result& r) {
            if (!self) return;
            self->feed_->stop();
            self->holding_ = false;
            if (r.ok)
                self->setMessage(
                    tr("Test move stopped: %1. The drive stays enabled; press Disable when done.").arg(r.stopReason));
            else {
                self->disarm(tr("the test move failed"));
                self->setMessage(tr("Test move failed: %1").arg(coreText(r.error)), true);
            }
            self->refresh();
            self->updateButtons();
            emit self->testMoveFinished(r.ok);
        },
        &error);
    if (!started) {
        holding_ = false;
        if (why) *why = error;
        return false;
    }
    feed_->start();
    setMessage(tr("Moving while the button is held…"));
    updateButtons();
    return true;
}

void Ds402Wizard::releaseHoldToRun() {
    holding_ = false;
    feed_->stop();
    if (ctl_ && ctl_->testMoveActive()) ctl_->stopTestMove(tr("hold-to-run button released"));
}

// --- always there

void Ds402Wizard::quickStop() {
    if (!ctl_ && !closing_) makeController();  // the window shows a drive: Quick stop works whatever came before
    if (!ctl_) return setMessage(tr("Quick stop: %1").arg(sendRefusal()), true);
    holding_ = false;
    disarm(tr("Quick stop"));
    sentCommands_ = true;
    setMessage(tr("Quick stop: sending 6040h = 0002h…"));
    if (ctl_->motionActive())
        return ctl_->stopMotion(true, tr("Quick stop"));  // homing or a position move: its end is shown
    QPointer<Ds402Wizard> self(this);
    ctl_->quickStop([self](const Ds402Result& r) {
        if (self) self->showStopped(r, tr("Quick stop done: the drive is in %1."), tr("Quick stop"));
    });
}

void Ds402Wizard::disableDrive() {
    if (!ctl_ && !closing_) makeController();
    if (!ctl_) return setMessage(tr("Disable: %1").arg(sendRefusal()), true);
    holding_ = false;
    disarm(tr("Disable"));
    setMessage(tr("Disabling: Shutdown, then Disable voltage…"));
    QPointer<Ds402Wizard> self(this);
    auto done = [self](const Ds402Result& r) {
        if (self) self->showStopped(r, tr("The drive is disabled (%1): the motor has no power."), tr("Disable"));
    };
    // During a test move: no power at once (the move's monitor sees it and stops too); homing or
    // a position move is quick-stopped first.
    if (ctl_->motionActive()) ctl_->stopMotion(true, tr("Disable"));
    if (ctl_->testMoveActive() || ctl_->motionActive()) ctl_->disableVoltage(done);
    else ctl_->disable(done);
}

void Ds402Wizard::showStopped(const Ds402Result& r, const QString& doneText, const QString& what) {
    if (r.ok) {
        showState(r.state, r.statusword);
        setMessage(doneText.arg(coreText(canopen::ds402::stateName(r.state))));
    } else {
        setMessage(tr("%1: %2").arg(what, coreText(r.error)), true);
    }
    refresh();
}

canopen::CommandScript Ds402Wizard::dryRun() {
    std::optional<int8_t> mode = mode_->chosen();
    if (mode == mode_->driveMode()) mode.reset();
    canopen::CommandScript script =
        canopen::Ds402Controller::enableScript(static_cast<uint8_t>(std::max(node_, 1)), 0, state_, mode);
    tabs_->showDryRun(script);
    setMessage(tr("Dry run: %n step(s) the enable would send from %1 — nothing was sent. “Save as script…” keeps them "
                  "for coscope-cli script run.",
                  nullptr, int(script.steps.size()))
                   .arg(coreText(canopen::ds402::stateName(state_))));
    return script;
}

bool Ds402Wizard::safeDisable(const QString& why) {
    if (!ctlSdo_ || ctlSdo_ != workspace_->sdo() || !workspace_->canTransmit() || node_ <= 0 || !cia402_) return false;
    const bool moving = ctl_ && (ctl_->testMoveActive() || ctl_->motionActive());
    const bool powered = state_ == State::OperationEnabled || state_ == State::SwitchedOn ||
                         state_ == State::QuickStopActive || (sentCommands_ && state_ == State::ReadyToSwitchOn);
    if (!moving && !powered) return false;
    spdlog::info("ds402 wizard: disabling node {} ({})", node_, why.toStdString());
    const auto n = static_cast<uint8_t>(node_);
    // Fire and forget (the wizard may be gone when the answers come): the SDO client sends in
    // order. Once the drive took it, the bus's record of enabled drives forgets it (the context
    // outlives the client, whose callbacks stop with it).
    canopen::EnabledDrives* record = &ctlSdo_->context().enabledDrives();
    if (moving) {
        record->noteControlword(n, 0, 0x0002);
        ctlSdo_->download(n, 0x6040, 0, QByteArray::fromHex("0200"), [](const SdoResult&) {});  // quick stop
    }
    ctlSdo_->download(n, 0x6040, 0, QByteArray::fromHex("0000"), [record, n](const SdoResult& r) {  // disable voltage
        if (r.ok) record->noteControlword(n, 0, 0x0000);
    });
    return true;
}

}  // namespace coscope::gui
