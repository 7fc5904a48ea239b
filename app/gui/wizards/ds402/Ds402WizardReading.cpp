// SPDX-License-Identifier: GPL-3.0-or-later
// The CiA 402 wizard: choosing the drive and reading its state (6041h, 6061h, 6502h, 603Fh).
#include "app/gui/wizards/ds402/Ds402Wizard.h"

#include "app/gui/language/CoreText.h"
#include "app/gui/wizards/common/BusLossAdvice.h"

#include "core/canopen/SdoClient.h"
#include "eds/DictionaryLibrary.h"

#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/common/WizardFramesPane.h"
#include "app/gui/wizards/ds402/Ds402FaultText.h"
#include "app/gui/wizards/ds402/Ds402FramesTabs.h"
#include "app/gui/wizards/ds402/Ds402ModeBox.h"
#include "app/gui/wizards/ds402/Ds402PositionMoveBox.h"
#include "app/gui/wizards/ds402/Ds402StateDiagram.h"
#include "app/gui/wizards/ds402/Ds402StatusPanel.h"
#include "app/gui/wizards/ds402/Ds402StepBar.h"
#include "app/gui/wizards/ds402/Ds402TestMoveBox.h"
#include "app/gui/wizards/ds402/Ds402VendorNotes.h"

#include <QComboBox>
#include <QLabel>
#include <QPointer>
#include <QRegularExpression>
#include <QTimer>

#include <spdlog/spdlog.h>

namespace coscope::gui {

using canopen::Ds402Result;
using canopen::Ds402TestMove;
using canopen::SdoResult;
using canopen::ds402::State;
namespace sw = canopen::ds402::sw;

namespace {
constexpr uint16_t kCia402 = 402;  // 1000h low word: device profile number (CiA 301 §7.5.2.1)

uint32_t le32(const QByteArray& b) {
    uint32_t v = 0;
    for (int i = 0; i < std::min<qsizetype>(4, b.size()); ++i) v |= uint32_t(uint8_t(b[i])) << (8 * i);
    return v;
}
}  // namespace

// --- choosing the drive

void Ds402Wizard::findFirstDrive(int attempt) {
    if (node_ > 0 || attempt > 60) return;
    if (!workspace_->canTransmit() || !workspace_->sdo()) {
        if (workspace_->bus() && workspace_->bus()->isListenOnly()) return;
        QTimer::singleShot(500, this, [this, attempt] { findFirstDrive(attempt + 1); });
        return;
    }
    std::vector<int> ids;
    for (const canopen::NodeInfo& n : workspace_->nodes().snapshot()) ids.push_back(n.node);
    std::sort(ids.begin(), ids.end());
    if (ids.empty()) {
        QTimer::singleShot(500, this, [this, attempt] { findFirstDrive(attempt + 1); });
        return;
    }
    setMessage(tr("Looking for a CiA 402 drive (device type 1000h = …0192h)…"));
    // Ask the nodes one after the other for their device type.
    auto ask = std::make_shared<std::function<void(size_t)>>();
    QPointer<Ds402Wizard> self(this);
    *ask = [self, ids, ask, attempt](size_t i) {
        if (!self || self->node_ > 0) return;
        if (i >= ids.size() || !self->workspace_->sdo()) {
            *ask = nullptr;
            self->setMessage(tr("No CiA 402 drive answered yet; trying again."));
            QTimer::singleShot(1000, self, [self, attempt] {
                if (self) self->findFirstDrive(attempt + 1);
            });
            return;
        }
        self->workspace_->sdo()->upload(static_cast<uint8_t>(ids[i]), 0x1000, 0,
                                        [self, ids, ask, i](const SdoResult& r) {
                                            if (!self || self->node_ > 0 || !*ask) return;
                                            if (r.ok && (le32(r.data) & 0xFFFF) == kCia402) {
                                                *ask = nullptr;
                                                return self->selectNode(ids[i]);
                                            }
                                            (*ask)(i + 1);
                                        });
    };
    (*ask)(0);
}

void Ds402Wizard::selectNode(int node) {
    if (ctl_ && ctl_->testMoveActive()) ctl_->stopTestMove(tr("another drive was chosen"));
    if (ctl_ && ctl_->motionActive()) ctl_->stopMotion(true, tr("another drive was chosen"));
    motion_ = Motion::None;
    if (node != node_) safeDisable(tr("another drive was chosen"));
    node_ = node;
    sentCommands_ = false;
    armed_ = false;
    supported_.reset();
    mode_->forget(false);
    state_ = State::Unknown;
    visited_.clear();
    faultText_.clear();
    controlWarning_.clear();
    cia402_ = true;
    diagram_->setState(State::Unknown);
    status_->clear();
    const auto info = workspace_->nodes().node(node);
    dictionary_ = info ? info->dictionary : QString();
    ++selection_;
    reading_ = false;  // answers to reads for the earlier choice are dropped
    settleTries_ = 0;
    // The node list of the combo: every node seen, this one selected.
    nodeCombo_->clear();
    for (const canopen::NodeInfo& n : workspace_->nodes().snapshot())
        nodeCombo_->addItem(
            n.dictionary.isEmpty() ? tr("Node %1").arg(n.node) : tr("Node %1 — %2").arg(n.node).arg(n.dictionary),
            n.node);
    if (nodeCombo_->findData(node) < 0) nodeCombo_->addItem(tr("Node %1").arg(node), node);
    nodeCombo_->setCurrentIndex(nodeCombo_->findData(node));
    tabs_->frames()->setNode(node);
    tabs_->frames()->markStart();
    makeController();
    if (dictionary_.isEmpty() && ctl_) {
        // The node table has no dictionary yet (the network was not scanned): match one as the
        // node scan does, by the identity object 1018h sub 1 vendor-ID, sub 2 product code
        // (CiA 301 §7.5.2.21), or without one by 1000h and 1008h, so the vendor notes and alarm
        // texts are known.
        setMessage(tr("Reading the identity of node %1 (1018h)…").arg(node));
        auto device = std::make_shared<eds::DeviceIdentity>();
        QPointer<Ds402Wizard> self(this);
        const int selection = selection_;
        readObject(0x1000, 0, [device](const SdoResult& r) {
            if (r.ok) device->deviceType = le32(r.data);
        });
        readObject(0x1008, 0, [device](const SdoResult& r) {
            if (r.ok) device->deviceName = QString::fromLatin1(r.data).section(QChar(0), 0, 0);
        });
        readObject(0x1018, 1, [device](const SdoResult& r) {
            if (r.ok) device->vendorId = le32(r.data);
        });
        readObject(0x1018, 2, [self, device, selection](const SdoResult& r) {
            if (!self || selection != self->selection_) return;
            if (r.ok) device->productCode = le32(r.data);
            if (const auto* e = eds::DictionaryLibrary::shared().match(*device)) self->dictionary_ = e->name;
            self->setMessage({});
            self->startReading();
        });
        return;
    }
    startReading();
}

void Ds402Wizard::startReading() {
    move_->setUnits(Ds402Units::forDictionary(dictionary_));
    setUpMotionPages();
    const auto notes = ds402VendorNotes(dictionary_);
    vendor_->setText(notes ? QStringLiteral("<b>%1:</b> %2").arg(notes->vendor, notes->before.toHtmlEscaped())
                           : QString());
    if (notes && notes->notCia402) {
        cia402_ = false;
        setMessage(tr("Node %1 is a %2: %3").arg(node_).arg(notes->vendor, notes->before), true);
        setProperty("screenshotReady", true);
        updateButtons();
        emit stateRead(false);
        return;
    }
    setMessage({});  // e.g. "Looking for a CiA 402 drive…" is over
    refresh();
    poll_->start();
}

void Ds402Wizard::makeController() {
    ctl_.reset();
    ctlSdo_ = nullptr;
    if (node_ <= 0 || !workspace_->sdo() || !workspace_->canTransmit()) return;
    ctlSdo_ = workspace_->sdo();
    ctl_ = std::make_unique<canopen::Ds402Controller>(*ctlSdo_, static_cast<uint8_t>(node_));
    ctl_->setTimeout(1000);
    motion_ = Motion::None;
    ctl_->setSendObserver([this](const QString& line) {
        spdlog::info("ds402 wizard: {}", line.toStdString());
        // The set-point handshake of a position move, as the controller sends it.
        static const QRegularExpression controlword(QStringLiteral("6040h = 0x([0-9A-F]{4})"));
        if (const auto m = controlword.match(line); m.hasMatch() && motion_ == Motion::Position)
            position_->showControlword(static_cast<uint16_t>(m.captured(1).toUInt(nullptr, 16)));
    });
}

void Ds402Wizard::stopOnBusLoss() {
    if (node_ <= 0 || (!ctl_ && state_ == State::Unknown)) {
        dropController(tr("Bus lost. CoScope reconnects by itself; press “Read state” when the bus is back."));
        return;
    }
    const bool moving = ctl_ && (ctl_->testMoveActive() || ctl_->motionActive());
    const bool mayBeEnabled = moving || state_ == State::OperationEnabled || state_ == State::SwitchedOn ||
                              state_ == State::QuickStopActive || state_ == State::FaultReactionActive || sentCommands_;
    const QString last = state_ == State::Unknown
                             ? tr("CiA 402 state unknown")
                             : tr("%1 (statusword %2h)")
                                   .arg(coreText(canopen::ds402::stateName(state_)),
                                        QString::number(statusword_, 16).rightJustified(4, u'0').toUpper());
    const QString text =
        BusLossAdvice::driveMessage(workspace_->bus() ? workspace_->bus()->errorString() : QString(), node_,
                                    BusLossAdvice::lastNmtState(workspace_->nodes(), node_), last, mayBeEnabled);
    stoppedByLoss_ = true;
    spdlog::warn("ds402 wizard: bus lost with node {} last in {} (statusword {:04X}h){}", node_,
                 canopen::ds402::stateName(state_).toStdString(), statusword_,
                 mayBeEnabled ? ", may still be enabled" : "");
    dropController(text);
}

void Ds402Wizard::dropController(const QString& why) {
    poll_->stop();
    feed_->stop();
    holding_ = false;
    busy_ = reading_ = false;
    ctl_.reset();
    ctlSdo_ = nullptr;
    motion_ = Motion::None;
    // Nothing read any more: show no state rather than the last one (it may be long gone).
    ++selection_;  // answers still under way are dropped
    state_ = State::Unknown;
    statusword_ = 0;
    armed_ = false;
    diagram_->setState(State::Unknown);
    diagram_->setNextTransition(std::nullopt);
    status_->clear();
    mode_->forget();
    steps_->setNote(node_ > 0 ? tr("The state of node %1 is not known: not connected.").arg(node_) : QString());
    if (!why.isEmpty()) setMessage(why, true);
    updateButtons();
}

void Ds402Wizard::readObject(uint16_t index, uint8_t sub, std::function<void(const SdoResult&)> done) {
    if (!ctlSdo_ || ctlSdo_ != workspace_->sdo()) {
        SdoResult r;
        r.error = tr("not connected");
        return done(r);
    }
    QPointer<Ds402Wizard> self(this);
    ctlSdo_->upload(static_cast<uint8_t>(node_), index, sub, [self, done](const SdoResult& r) {
        if (self) done(r);
    });
}

// --- reading the state

void Ds402Wizard::refresh() {
    // No controller (the connection changed or the window was closed and shown again): choose
    // the same drive again, which reads it afresh.
    if (!ctl_ && node_ > 0 && workspace_->canTransmit() && workspace_->sdo()) return selectNode(node_);
    // Never while a step runs: the step reads 6041h itself and its result is the state shown.
    if (!ctl_ || reading_ || busy_ || !cia402_) return;
    reading_ = true;
    QPointer<Ds402Wizard> self(this);
    const int selection = selection_;
    ctl_->readState([self, selection](const Ds402Result& r) {
        if (!self || selection != self->selection_) return;
        if (r.ok && r.state == State::NotReadyToSwitchOn && self->settleTries_ < kSettleTries) {
            // Still initialising: it goes to Switch on disabled by itself (CiA 402-2 §6.2,
            // transition 1). Read again soon instead of showing a state without a next step.
            ++self->settleTries_;
            self->showState(r.state, r.statusword);
            self->setMessage(tr("The drive is initialising (Not ready to switch on); waiting for Switch on disabled…"));
            QTimer::singleShot(kSettleMs, self, [self] {
                if (!self) return;
                self->reading_ = false;
                self->refresh();
            });
            return;
        }
        if (self->settleTries_ > 0 && r.ok) self->setMessage(tr("The drive finished initialising."));
        self->settleTries_ = 0;
        self->afterState(r, [self, ok = r.ok, selection] {
            if (!self || selection != self->selection_) return;
            self->reading_ = false;
            self->updateButtons();
            emit self->stateRead(ok);
        });
    });
}

void Ds402Wizard::afterState(const Ds402Result& r, std::function<void()> then) {
    if (!r.ok) {
        if (r.error.contains(QStringLiteral("06020000")) ||
            r.error.contains(QStringLiteral("does not exist"), Qt::CaseInsensitive)) {
            cia402_ = false;
            poll_->stop();
            setMessage(tr("Node %1 has no statusword 6041h: it is not a CiA 402 drive (%2).")
                           .arg(node_)
                           .arg(coreText(r.error)),
                       true);
            setProperty("screenshotReady", true);
        } else {
            setMessage(
                tr("Cannot read the drive's state: %1. Check that the drive is powered and connected, and its node-ID.")
                    .arg(coreText(r.error)),
                true);
        }
        return then();
    }
    showState(r.state, r.statusword);
    QPointer<Ds402Wizard> self(this);
    // 6061h: the mode the drive runs in; 6502h once: the modes it supports.
    readObject(0x6061, 0, [self, then](const SdoResult& m) {
        if (m.ok && !m.data.isEmpty()) self->showDriveMode(static_cast<int8_t>(m.data[0]));
        auto afterModes = [self, then] {
            if (!self) return;
            const bool fault = self->statusword_ & sw::Fault;
            if (!fault) {
                self->faultText_.clear();
                self->status_->setFaultText({});
                self->setProperty("screenshotReady", true);
                return then();
            }
            // In fault: 603Fh error code and the newest 1003h entry for the vendor alarm.
            self->readObject(0x603F, 0, [self, then](const SdoResult& e) {
                const uint16_t code = e.ok ? static_cast<uint16_t>(le32(e.data)) : 0;
                self->readObject(0x1003, 1, [self, then, code, e](const SdoResult& h) {
                    const Ds402Fault f = describeDs402Fault(self->dictionary_, code, h.ok ? le32(h.data) : 0);
                    self->faultText_ =
                        e.ok ? f.text() : tr("Error code 603Fh could not be read: %1").arg(coreText(e.error));
                    self->status_->setFaultText(self->faultText_);
                    self->setProperty("screenshotReady", true);
                    then();
                });
            });
        };
        if (self->supported_) return afterModes();
        self->readObject(0x6502, 0, [self, afterModes](const SdoResult& s) {
            self->supported_ = s.ok ? le32(s.data) : 0x3EDu;  // unknown: offer the standard modes
            self->fillModes();
            // Vendor pre-condition: the control-mode parameter (Delta P1-01, AIMOTOR H02-00).
            const auto notes = ds402VendorNotes(self->dictionary_);
            if (!notes || !notes->controlIndex) return afterModes();
            self->readObject(notes->controlIndex, notes->controlSub,
                             [self, afterModes, n = *notes](const SdoResult& c) {
                                 if (c.ok && static_cast<int64_t>(le32(c.data)) != n.controlValue)
                                     self->controlWarning_ = tr("%1 is %2, not %3: the drive is not in CANopen control "
                                                                "and will ignore the controlword. Set %1 = %3 first.")
                                                                 .arg(n.controlName)
                                                                 .arg(le32(c.data))
                                                                 .arg(n.controlValue);
                                 if (!self->controlWarning_.isEmpty()) self->setMessage(self->controlWarning_, true);
                                 afterModes();
                             });
        });
    });
}

void Ds402Wizard::showState(State s, uint16_t swd) {
    // Out of Operation enabled (stopped, disabled, faulted): whatever comes back, the arming is over.
    if (s != State::OperationEnabled)
        disarm(s == State::Fault || s == State::FaultReactionActive ? tr("the drive faulted")
                                                                    : tr("the drive left Operation enabled"));
    statusword_ = swd;
    if (s != state_ || visited_.isEmpty()) visited_ << s;
    state_ = s;
    diagram_->setState(s);
    status_->setStatusword(swd);
    const auto next = canopen::ds402::nextEnableCommand(s);
    diagram_->setNextTransition(next ? ds402TransitionNumber(s, *next) : std::nullopt);
    steps_->explain(s, cia402_);
    updateButtons();
}

void Ds402Wizard::fillModes() {
    const bool readBefore = mode_->setSupported(supported_.value_or(0));
    // The jog needs profile velocity; otherwise the short profile-position move.
    const bool pv = supported_ && canopen::ds402::modeSupported(*supported_, 3);
    move_->setKind(pv ? Ds402TestMove::Kind::Jog : Ds402TestMove::Kind::Relative);
    if (readBefore) showDriveMode(mode_->driveMode());  // as read anew: the box shows the drive's mode
}

void Ds402Wizard::showDriveMode(int8_t mode) {
    // Armed in another mode, the move switches (as agreed) to its own; any other mode ends the arming.
    if (mode == armedMode_) armedFromMode_ = mode;
    else if (mode != armedFromMode_) disarm(tr("the mode of operation changed"));
    status_->setModeText(tr("Mode of operation (6061h): %1").arg(coreText(canopen::ds402::modeName(mode))));
    status_->setMode(mode);
    if (!mode_->showDriveMode(mode)) return;
    // The test move follows the kind the drive's mode runs (PV: jog, PP: short move).
    if (mode == 3) move_->setKind(Ds402TestMove::Kind::Jog);
    if (mode == 1) move_->setKind(Ds402TestMove::Kind::Relative);
}

}  // namespace coscope::gui
