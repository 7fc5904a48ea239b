// SPDX-License-Identifier: GPL-3.0-or-later
// The CiA 402 wizard: homing (CiA 402-2 §13) and the profile position move (§12), both through
// Ds402Controller::home()/moveTo()/stopMotion(); their pages' values, progress and end, and the
// position move's arming and hold-to-run.
#include "app/gui/wizards/ds402/Ds402Wizard.h"

#include "app/gui/language/CoreText.h"

#include "core/canopen/HomingMethods.h"
#include "core/canopen/SdoClient.h"
#include "core/od/NumberNotation.h"

#include "app/gui/wizards/ds402/Ds402HomingBox.h"
#include "app/gui/wizards/ds402/Ds402ModeBox.h"
#include "app/gui/wizards/ds402/Ds402PositionMoveBox.h"
#include "app/gui/wizards/ds402/Ds402StatusPanel.h"
#include "app/gui/wizards/ds402/Ds402TestMoveBox.h"
#include "app/gui/wizards/ds402/Ds402Units.h"

#include <QPointer>
#include <QTabWidget>
#include <QTimer>

#include <array>
#include <cstdlib>

namespace coscope::gui {

using canopen::Ds402MotionSample;
using canopen::Ds402PositionMove;
using canopen::Ds402Result;
using canopen::Ds402TestMove;
using canopen::SdoResult;
using canopen::ds402::State;
namespace homing = canopen::homing;

namespace {
constexpr int8_t kHomingMode = 6, kProfilePosition = 1;  // 6060h values (CiA 402-2 Table 35)

// A little-endian value of 1, 2 or 4 bytes as the object's type reads it.
int64_t motionValue(const QByteArray& b, bool isSigned) {
    uint32_t v = 0;
    const int n = static_cast<int>(std::min<qsizetype>(4, b.size()));
    for (int i = 0; i < n; ++i) v |= uint32_t(uint8_t(b[i])) << (8 * i);
    if (!isSigned || n == 0) return v;
    const int shift = 32 - 8 * n;
    return static_cast<int32_t>(v << shift) >> shift;
}

bool sameMove(const Ds402PositionMove& a, const Ds402PositionMove& b) {
    return a.target == b.target && a.relative == b.relative && a.velocity == b.velocity &&
           a.acceleration == b.acceleration && a.deceleration == b.deceleration;
}
}  // namespace

void Ds402Wizard::showPage(const QString& name) {
    QWidget* page = name == u"homing"     ? static_cast<QWidget*>(homing_)
                    : name == u"position" ? static_cast<QWidget*>(position_)
                                          : static_cast<QWidget*>(move_);
    pages_->setCurrentWidget(page);
}

bool Ds402Wizard::motionRunning() const { return ctl_ && ctl_->motionActive(); }

bool Ds402Wizard::agreeMode(int8_t needed, const QString& question, const QString& notDone, QString* why) {
    const int8_t current = mode_->driveMode();
    if (current == needed) return true;
    const QString currentName = coreText(canopen::ds402::modeName(current));
    if (confirm(tr("Mode of operation"),
                question.arg(currentName, coreText(canopen::ds402::modeName(needed))).arg(needed)))
        return true;
    if (why) *why = notDone.arg(currentName);
    return false;
}

// --- the pages' values

void Ds402Wizard::setUpMotionPages() {
    const homing::DriveHoming& table = homing::drive(dictionary_);
    const Ds402Units units = Ds402Units::forDictionary(dictionary_);
    homing_->setDrive(table, table.dictionary == dictionary_, units, dictionary_);
    position_->setDrive(units, dictionary_);
    softLimits_.reset();
    position_6064_.reset();
    motionSettingsFor_ = -1;
    position_->showLimits(limitsText());
    readMotionSettings();
}

void Ds402Wizard::readMotionSettings() {
    // Once per chosen drive, when the homing or position page is shown: the values the drive has.
    if (pages_->currentWidget() == move_ || motionSettingsFor_ == selection_ || !ctl_ || !cia402_) return;
    motionSettingsFor_ = selection_;
    struct MotionObject {
        uint16_t index;
        uint8_t sub;
        bool isSigned;
    };
    static constexpr MotionObject kObjects[] = {
        {0x6098, 0, true},  {0x6099, 1, false}, {0x6099, 2, false}, {0x609A, 0, false}, {0x607C, 0, true},
        {0x6081, 0, false}, {0x6083, 0, false}, {0x6084, 0, false}, {0x607D, 1, true},  {0x607D, 2, true}};
    QPointer<Ds402Wizard> self(this);
    const int selection = selection_;
    auto limits = std::make_shared<std::array<std::optional<int32_t>, 2>>();
    for (const MotionObject& o : kObjects)
        readObject(o.index, o.sub, [self, o, selection, limits](const SdoResult& r) {
            if (!self || selection != self->selection_ || !r.ok || r.data.isEmpty()) return;
            const int64_t v = motionValue(r.data, o.isSigned);
            if (o.index == 0x607D) {
                // Software position limits (CiA 402-2 §12.3.5): both read, a real range.
                (*limits)[o.sub - 1] = static_cast<int32_t>(v);
                if ((*limits)[0] && (*limits)[1] && *(*limits)[0] < *(*limits)[1])
                    self->softLimits_ = std::make_pair(*(*limits)[0], *(*limits)[1]);
                self->position_->showLimits(self->limitsText());
            } else if (o.index == 0x6081 || o.index == 0x6083 || o.index == 0x6084) {
                self->position_->showDriveValue(o.index, v);
            } else {
                self->homing_->showDriveValue(o.index, o.sub, v);
            }
        });
}

QString Ds402Wizard::limitsText() const {
    const Ds402Units u = Ds402Units::forDictionary(dictionary_);
    const QString test = tr("Test move limits: at most %1 per move, at most %2.")
                             .arg(inUnit(Ds402TestMove::kMaxDistance, u.distance),
                                  inUnit(Ds402TestMove::kMaxVelocity, u.profileVelocity));
    if (softLimits_)
        return tr("Software position limits (607Dh): %1 to %2.")
                   .arg(inUnit(softLimits_->first, u.position), inUnit(softLimits_->second, u.position)) +
               QStringLiteral(" ") + test;
    return tr("No software position limits (607Dh) read.") + QStringLiteral(" ") + test;
}

void Ds402Wizard::onMotionSample(const Ds402MotionSample& s) {
    position_6064_ = s.position;
    status_->setStatusword(s.statusword);
    if (motion_ == Motion::Homing) {
        status_->setMode(kHomingMode);
        homing_->showSample(s);
    } else if (motion_ == Motion::Position) {
        status_->setMode(kProfilePosition);
        position_->showSample(s);
    }
}

void Ds402Wizard::afterMotionFailure(const QString& text, std::function<void(const QString&)> show) {
    updateButtons();
    if (!ctl_) return show(text);
    // The state the drive ended in and, in fault, its error code and alarm text.
    QPointer<Ds402Wizard> self(this);
    const int selection = selection_;
    ctl_->readState([self, text, show, selection](const Ds402Result& st) {
        if (!self || selection != self->selection_) return;
        self->reading_ = true;
        self->afterState(st, [self, text, show] {
            if (!self) return;
            self->reading_ = false;
            show(self->faultText_.isEmpty() ? text : text + QStringLiteral("\n") + self->faultText_);
            self->updateButtons();
        });
    });
}

// --- homing

bool Ds402Wizard::startHoming(QString* why) {
    auto refuse = [why](const QString& text) {
        if (why) *why = text;
        return false;
    };
    if (const QString r = sendRefusal(); !r.isEmpty()) return refuse(r);
    if (busy_ || ctl_->testMoveActive() || ctl_->motionActive())
        return refuse(tr("Wait for the current step to finish."));
    const std::optional<int> method = homing_->method();
    if (!method) return refuse(tr("Type a homing method number (6098h) or choose one from the list."));
    // The drive's own methods (its manual); CiA 402-2's when its dictionary is not known.
    const homing::DriveHoming& table = homing::drive(dictionary_);
    const bool known = table.dictionary == dictionary_;
    if (known && !table.supports(*method))
        return refuse(tr("Node %1 (%2) has no homing method %3: its methods are %4. Nothing was sent.")
                          .arg(node_)
                          .arg(table.title)
                          .arg(*method)
                          .arg(table.numbers()));
    if (supported_ && !canopen::ds402::modeSupported(*supported_, kHomingMode))
        return refuse(tr("The drive does not list Homing as supported (6502h): it cannot home."));
    if (!agreeMode(kHomingMode, tr("The drive is in %1; homing needs %2: switch the mode of operation (6060h = %3)?"),
                   tr("Homing not started: the mode of operation stays %1."), why))
        return false;
    const homing::Method* m = table.method(*method);
    const QString described = m ? coreText(m->description) : tr("not a CiA 402-2 method");
    const QString enableFirst = state_ == State::OperationEnabled
                                    ? QString()
                                    : tr("The drive is enabled first (Operation enabled): the motor gets power.\n\n");
    if (!confirm(tr("Homing"), tr("Node %1 will home with method %2: %3.\n\n%4The axis may travel to a limit switch, "
                                  "the home switch or an end stop: make sure "
                                  "it is free to move. Stop halts it at any time.\n\nStart homing?")
                                   .arg(node_)
                                   .arg(*method)
                                   .arg(described, enableFirst)))
        return refuse(tr("Homing was not confirmed; nothing was sent."));
    disarm(tr("homing started"));
    canopen::Ds402HomingRequest req = homing_->request();
    req.methodOnlyWhileDisabled = known && table.changeOnlyWhileDisabled;
    sentCommands_ = true;
    motion_ = Motion::Homing;
    homing_->started();
    setMessage(tr("Homing node %1 with method %2…").arg(node_).arg(*method));
    QPointer<Ds402Wizard> self(this);
    ctl_->home(
        req,
        [self](const Ds402MotionSample& s) {
            if (self) self->onMotionSample(s);
        },
        [self](const Ds402Result& r) {
            if (self) self->homingDone(r);
        });
    updateButtons();
    return true;
}

void Ds402Wizard::stopHoming() {
    if (!ctl_ || motion_ != Motion::Homing || !ctl_->motionActive()) return;
    setMessage(tr("Stopping the homing: halt (6040h = 010Fh)…"));
    ctl_->stopMotion(false, tr("Stop pressed"));
}

void Ds402Wizard::homingDone(const Ds402Result& r) {
    motion_ = Motion::None;
    QPointer<Ds402Wizard> self(this);
    if (r.ok) {
        readObject(0x6064, 0, [self, sw = r.statusword](const SdoResult& p) {
            if (!self) return;
            const Ds402Units u = Ds402Units::forDictionary(self->dictionary_);
            const QString where = p.ok ? inUnit(double(motionValue(p.data, true)), u.position)
                                       : tr("not read (%1)").arg(coreText(p.error));
            const QString text =
                tr("Homing attained (statusword %1): position actual 6064h = %2. The drive stays enabled.")
                    .arg(od::hexText(sw, 4), where);
            self->homing_->showResult(text, true);
            self->setMessage(text);
            self->refresh();
            self->updateButtons();
            emit self->homingFinished(true);
        });
        updateButtons();
        return;
    }
    const QString text = !r.stopReason.isEmpty() ? tr("Homing stopped (%1) before home was set.").arg(r.stopReason)
                                                 : tr("Homing failed: %1").arg(coreText(r.error));
    afterMotionFailure(text, [self](const QString& full) {
        if (!self) return;
        self->homing_->showResult(full, false);
        self->setMessage(full, true);
        emit self->homingFinished(false);
    });
}

// --- profile position move

bool Ds402Wizard::armPositionMove(QString* why) {
    auto refuse = [why](const QString& text) {
        if (why) *why = text;
        return false;
    };
    if (const QString r = sendRefusal(); !r.isEmpty()) return refuse(r);
    if (busy_ || ctl_->testMoveActive() || ctl_->motionActive())
        return refuse(tr("Wait for the current step to finish."));
    if (state_ != State::OperationEnabled)
        return refuse(tr("Enable the drive first (Operation enabled), then arm the position move."));
    const Ds402PositionMove m = position_->move();
    const Ds402Units u = Ds402Units::forDictionary(dictionary_);
    if (m.velocity.value_or(0) == 0) return refuse(tr("Set a profile velocity (6081h) above 0."));
    if (*m.velocity > uint32_t(Ds402TestMove::kMaxVelocity))
        return refuse(tr("The profile velocity is above the test move's limit of %1.")
                          .arg(inUnit(Ds402TestMove::kMaxVelocity, u.profileVelocity)));
    if (supported_ && !canopen::ds402::modeSupported(*supported_, kProfilePosition))
        return refuse(tr("The drive does not list Profile position as supported (6502h): no position move."));
    // Where the move would end: from the position now, within the limits.
    busy_ = true;
    updateButtons();
    setMessage(tr("Reading the position (6064h) and the software limits (607Dh)…"));
    QPointer<Ds402Wizard> self(this);
    const int selection = selection_;
    auto limits = std::make_shared<std::array<std::optional<int32_t>, 2>>();
    readObject(0x607D, 1, [limits](const SdoResult& r) {
        if (r.ok) (*limits)[0] = static_cast<int32_t>(motionValue(r.data, true));
    });
    readObject(0x607D, 2, [limits](const SdoResult& r) {
        if (r.ok) (*limits)[1] = static_cast<int32_t>(motionValue(r.data, true));
    });
    readObject(0x6064, 0, [self, selection, limits](const SdoResult& p) {
        if (!self || selection != self->selection_) return;
        self->busy_ = false;
        self->softLimits_.reset();
        if ((*limits)[0] && (*limits)[1] && *(*limits)[0] < *(*limits)[1])
            self->softLimits_ = std::make_pair(*(*limits)[0], *(*limits)[1]);
        self->position_->showLimits(self->limitsText());
        self->updateButtons();
        if (!p.ok)
            return self->setMessage(
                tr("Position move not armed: the position 6064h could not be read (%1).").arg(coreText(p.error)), true);
        // The questions come after the SDO answer has been handled.
        const auto position = static_cast<int32_t>(motionValue(p.data, true));
        QTimer::singleShot(0, self, [self, position] {
            if (self) self->armPosition(position);
        });
    });
    return true;
}

void Ds402Wizard::armPosition(int32_t position) {
    if (!sendRefusal().isEmpty() || state_ != State::OperationEnabled || busy_)
        return setMessage(tr("Position move not armed: the drive is no longer in Operation enabled."), true);
    position_6064_ = position;
    const Ds402PositionMove m = position_->move();
    const Ds402Units u = Ds402Units::forDictionary(dictionary_);
    const int64_t end = m.relative ? int64_t(position) + m.target : int64_t(m.target);
    if (std::llabs(end - position) > Ds402TestMove::kMaxDistance)
        return setMessage(
            tr("Position move not armed: %1 from the position now is more than the test move's limit of %2.")
                .arg(inUnit(double(end - position), u.distance), inUnit(Ds402TestMove::kMaxDistance, u.distance)),
            true);
    if (softLimits_ && (end < softLimits_->first || end > softLimits_->second))
        return setMessage(
            tr("Position move not armed: it would end at %1, outside the software position limits 607Dh (%2 to %3).")
                .arg(inUnit(double(end), u.position), inUnit(softLimits_->first, u.position),
                     inUnit(softLimits_->second, u.position)),
            true);
    QString why;
    if (!agreeMode(kProfilePosition,
                   tr("The drive is in %1; the position move needs %2: switch the mode of operation (6060h = %3)?"),
                   tr("Position move not armed: the mode of operation stays %1."), &why))
        return setMessage(why, true);
    if (!confirm(tr("Position move"), tr("While you hold “Hold to move”, the motor of node %1 will %2.\nReleasing the "
                                         "button halts it. Make sure the axis is free "
                                         "to move.\n\nArm the position move?")
                                          .arg(node_)
                                          .arg(position_->describe(m))))
        return setMessage(tr("Position move not armed."), true);
    armed_ = true;
    armedKind_ = Armed::PositionMove;
    armedMove_ = m;
    armedMode_ = kProfilePosition;
    armedFromMode_ = mode_->driveMode();
    setMessage(tr("Position move armed: hold the “Hold to move” button to move, release it to halt."));
    updateButtons();
}

bool Ds402Wizard::pressHoldToMove(QString* why) {
    auto refuse = [why](const QString& text) {
        if (why) *why = text;
        return false;
    };
    if (const QString r = sendRefusal(); !r.isEmpty()) return refuse(r);
    if (!armed_ || armedKind_ != Armed::PositionMove) return refuse(tr("Arm the position move first."));
    if (busy_ || ctl_->testMoveActive() || ctl_->motionActive())
        return refuse(tr("Wait for the current step to finish."));
    const Ds402PositionMove m = position_->move();
    if (!sameMove(m, armedMove_)) {
        disarm(tr("the move was changed after arming"));
        return refuse(tr("The position move was changed after it was armed: arm it again."));
    }
    const int32_t from = position_6064_.value_or(0);
    const int64_t end = m.relative ? int64_t(from) + m.target : int64_t(m.target);
    if (softLimits_ && (end < softLimits_->first || end > softLimits_->second))
        return refuse(tr("The move would end outside the software position limits 607Dh: not started."));
    holding_ = true;
    motion_ = Motion::Position;
    moveTarget_ = static_cast<int32_t>(end);
    position_->started(from, moveTarget_);
    setMessage(tr("Moving while the button is held…"));
    QPointer<Ds402Wizard> self(this);
    ctl_->moveTo(
        m,
        [self](const Ds402MotionSample& s) {
            if (self) self->onMotionSample(s);
        },
        [self](const Ds402Result& r) {
            if (self) self->positionDone(r);
        });
    updateButtons();
    return true;
}

void Ds402Wizard::releaseHoldToMove() {
    holding_ = false;
    if (ctl_ && motion_ == Motion::Position && ctl_->motionActive())
        ctl_->stopMotion(false, tr("hold-to-run button released"));
}

void Ds402Wizard::positionDone(const Ds402Result& r) {
    motion_ = Motion::None;
    holding_ = false;
    QPointer<Ds402Wizard> self(this);
    const bool halted = !r.ok && !r.stopReason.isEmpty() && r.state == State::OperationEnabled;
    if (r.ok || halted) {
        readObject(0x6064, 0, [self, r, halted](const SdoResult& p) {
            if (!self) return;
            const Ds402Units u = Ds402Units::forDictionary(self->dictionary_);
            if (p.ok) self->position_6064_ = static_cast<int32_t>(motionValue(p.data, true));
            const QString where =
                p.ok ? inUnit(double(*self->position_6064_), u.position) : tr("not read (%1)").arg(coreText(p.error));
            const QString text = halted ? tr("Halted before the target (%1): position actual 6064h = %2, target %3. "
                                             "The drive stays enabled.")
                                              .arg(r.stopReason, where, inUnit(self->moveTarget_, u.position))
                                        : tr("Target reached (statusword %1): position actual 6064h = %2.")
                                              .arg(od::hexText(r.statusword, 4), where);
            self->position_->showResult(text, true);
            self->setMessage(text);
            self->refresh();
            self->updateButtons();
            emit self->positionMoveFinished(r.ok);
        });
        updateButtons();
        return;
    }
    disarm(tr("the position move failed"));
    const QString text = !r.stopReason.isEmpty() ? tr("Position move stopped (%1).").arg(r.stopReason)
                                                 : tr("Position move failed: %1").arg(coreText(r.error));
    afterMotionFailure(text, [self](const QString& full) {
        if (!self) return;
        self->position_->showResult(full, false);
        self->setMessage(full, true);
        emit self->positionMoveFinished(false);
    });
}

}  // namespace coscope::gui
