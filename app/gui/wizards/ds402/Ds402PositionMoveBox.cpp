// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/ds402/Ds402PositionMoveBox.h"

#include "app/gui/od/IntegerSpinBox.h"
#include "app/gui/wizards/ds402/Ds402BitLamps.h"
#include "app/gui/wizards/ds402/Ds402MotionPlot.h"

#include "eds/DictionaryLibrary.h"

#include <QCheckBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace coscope::gui {

namespace {
constexpr uint16_t kPpNewSetPoint = 1u << 4;                                                   // 6040h bit 4
constexpr uint16_t kPpAcknowledge = 1u << 12, kPpReached = 1u << 10, kPpFollowing = 1u << 13;  // 6041h in PP
constexpr uint16_t kProfileIndex[] = {0x6081, 0x6083, 0x6084};
enum PositionLamp { LampNewSetPoint, LampAcknowledge, LampReached, LampFollowing };
}  // namespace

Ds402PositionMoveBox::Ds402PositionMoveBox(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("positionMoveBox"));
    auto* layout = new QHBoxLayout(this);
    auto* form = new QFormLayout;
    target_ = new IntegerSpinBox(this);
    target_->setObjectName(QStringLiteral("positionTarget"));
    target_->setType(od::DataType::Integer32);
    target_->setIntValue(1000);
    relative_ = new QCheckBox(tr("Relative (6040h bit 6)"), this);
    relative_->setObjectName(QStringLiteral("positionRelative"));
    relative_->setChecked(true);
    auto* targetRow = new QHBoxLayout;
    targetRow->addWidget(target_, 1);
    targetRow->addWidget(relative_);
    form->addRow(tr("Target (607Ah):"), targetRow);
    const QString labels[] = {tr("Profile velocity (6081h):"), tr("Acceleration (6083h):"),
                              tr("Deceleration (6084h):")};
    const char* names[] = {"positionVelocity", "positionAcceleration", "positionDeceleration"};
    const qint64 defaults[] = {2000, 10000, 10000};  // the test move's own ramps
    for (size_t i = 0; i < fields_.size(); ++i) {
        fields_[i] = new IntegerSpinBox(this);
        fields_[i]->setObjectName(QString::fromLatin1(names[i]));
        fields_[i]->setType(od::DataType::Unsigned32);
        fields_[i]->setIntValue(defaults[i]);
        connect(fields_[i], &IntegerSpinBox::textEdited, this, [this, i] { typed_[i] = true; });
        form->addRow(labels[i], fields_[i]);
    }
    limits_ = new QLabel(this);
    limits_->setObjectName(QStringLiteral("positionLimits"));
    limits_->setWordWrap(true);
    form->addRow(limits_);
    arm_ = new QPushButton(tr("Arm position move…"), this);
    arm_->setObjectName(QStringLiteral("armPositionMove"));
    connect(arm_, &QPushButton::clicked, this, &Ds402PositionMoveBox::armClicked);
    hold_ = new QPushButton(tr("Hold to move"), this);
    hold_->setObjectName(QStringLiteral("holdToMove"));
    hold_->setMinimumHeight(40);
    hold_->setToolTip(
        tr("The motor moves only while this button is held down; releasing it halts the motor (6040h bit 8)."));
    connect(hold_, &QPushButton::pressed, this, &Ds402PositionMoveBox::holdPressed);
    connect(hold_, &QPushButton::released, this, &Ds402PositionMoveBox::holdReleased);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(arm_);
    buttons->addWidget(hold_, 1);
    form->addRow(buttons);
    layout->addLayout(form, 3);

    auto* right = new QVBoxLayout;
    lamps_ = new Ds402BitLamps(this);
    lamps_->setObjectName(QStringLiteral("positionBits"));
    lamps_->add(tr("6040h bit 4: new set-point"));
    lamps_->add(tr("6041h bit 12: set-point acknowledge"));
    lamps_->add(tr("6041h bit 10: target reached"));
    lamps_->add(tr("6041h bit 13: following error"), true);
    right->addWidget(lamps_);
    handshake_ = new QLabel(this);
    handshake_->setObjectName(QStringLiteral("positionHandshake"));
    handshake_->setWordWrap(true);
    right->addWidget(handshake_);
    way_ = new QProgressBar(this);
    way_->setObjectName(QStringLiteral("positionWay"));
    way_->setRange(0, 1000);
    way_->setValue(0);
    way_->setTextVisible(true);
    right->addWidget(way_);
    result_ = new QLabel(this);
    result_->setObjectName(QStringLiteral("positionResult"));
    result_->setWordWrap(true);
    result_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    right->addWidget(result_);
    plot_ = new Ds402MotionPlot(this);
    plot_->setPlaceholder(tr("The move's motion shows here"));
    right->addWidget(plot_, 1);
    layout->addLayout(right, 2);
    showHandshake();
    setButtons(false, false);
}

void Ds402PositionMoveBox::setDrive(const Ds402Units& units, const QString& dictionary) {
    units_ = units;
    typed_.fill(false);
    const eds::DictionaryPtr od =
        dictionary.isEmpty() ? nullptr : eds::DictionaryLibrary::shared().loadShared(dictionary);
    auto limitsOf = [&](uint16_t index) {
        const od::SubObject* e = od ? od->entry(index, 0) : nullptr;
        return e ? e->limits() : od::Limits{};
    };
    const qint64 target = target_->intValue();
    target_->setType(od::DataType::Integer32, limitsOf(0x607A));
    target_->setIntValue(target);
    target_->setSuffix(rawUnitSuffix(units.distance));
    const od::Unit* unitOf[] = {&units.profileVelocity, &units.profileAcceleration, &units.profileAcceleration};
    for (size_t i = 0; i < fields_.size(); ++i) {
        const qint64 v = fields_[i]->intValue();
        fields_[i]->setType(od::DataType::Unsigned32, limitsOf(kProfileIndex[i]));
        fields_[i]->setIntValue(v);
        fields_[i]->setSuffix(rawUnitSuffix(*unitOf[i]));
    }
    plot_->setUnits(units.position, units.velocity);
    plot_->clear();
    lamps_->clear();
    result_->clear();
    phase_ = 0;
    way_->setValue(0);
    showHandshake();
}

void Ds402PositionMoveBox::showDriveValue(uint16_t index, int64_t value) {
    for (size_t i = 0; i < fields_.size(); ++i)
        if (kProfileIndex[i] == index && value > 0 && !typed_[i]) fields_[i]->setIntValue(value);
}

void Ds402PositionMoveBox::showLimits(const QString& text) { limits_->setText(text); }

canopen::Ds402PositionMove Ds402PositionMoveBox::move() const {
    canopen::Ds402PositionMove m;
    m.target = static_cast<int32_t>(target_->intValue());
    m.relative = relative_->isChecked();
    m.velocity = static_cast<uint32_t>(fields_[0]->intValue());
    m.acceleration = static_cast<uint32_t>(fields_[1]->intValue());
    m.deceleration = static_cast<uint32_t>(fields_[2]->intValue());
    return m;
}

QString Ds402PositionMoveBox::describe(const canopen::Ds402PositionMove& m) const {
    const QString speed = inUnit(double(m.velocity.value_or(0)), units_.profileVelocity);
    if (m.relative)
        return tr("move by %1 (relative, 607Ah = %2) at up to %3 (6081h)")
            .arg(inUnit(m.target, units_.distance))
            .arg(m.target)
            .arg(speed);
    return tr("move to position %1 (absolute, 607Ah = %2) at up to %3 (6081h)")
        .arg(inUnit(m.target, units_.distance))
        .arg(m.target)
        .arg(speed);
}

void Ds402PositionMoveBox::setButtons(bool armEnabled, bool holdEnabled) {
    arm_->setEnabled(armEnabled);
    hold_->setEnabled(holdEnabled);
}

void Ds402PositionMoveBox::started(int32_t from, int32_t to) {
    from_ = from;
    to_ = to;
    phase_ = 0;
    lamps_->clear();
    plot_->clear();
    result_->clear();
    way_->setValue(0);
    way_->setFormat(tr("%1 → %2").arg(inUnit(from, units_.position), inUnit(to, units_.position)));
    showHandshake();
}

void Ds402PositionMoveBox::showControlword(uint16_t cw) {
    const bool wasSet = controlword_ & kPpNewSetPoint;
    controlword_ = cw;
    lamps_->set(LampNewSetPoint, cw & kPpNewSetPoint);
    // The controller raises bit 4 for the set-point and lowers it only once it read bit 12
    // (CiA 402-2 §12.2): bit 4 going low after it was high is the acknowledge it saw.
    if ((cw & kPpNewSetPoint) && phase_ < 1) phase_ = 1;
    if (!(cw & kPpNewSetPoint) && wasSet && phase_ == 1 && !(cw & 0x0100)) {
        phase_ = 2;
        lamps_->set(LampAcknowledge, true);
    }
    showHandshake();
}

void Ds402PositionMoveBox::showSample(const canopen::Ds402MotionSample& s) {
    lamps_->set(LampAcknowledge, s.statusword & kPpAcknowledge);
    lamps_->set(LampReached, s.statusword & kPpReached);
    lamps_->set(LampFollowing, s.statusword & kPpFollowing);
    if (phase_ == 2 && (s.statusword & kPpReached) && !(s.statusword & kPpAcknowledge)) phase_ = 3;
    plot_->addSample(double(s.ms), double(s.position), double(s.velocity));
    const double span = double(to_) - double(from_);
    const double done = span == 0 ? 1.0 : (double(s.position) - double(from_)) / span;
    way_->setValue(static_cast<int>(std::lround(std::clamp(done, 0.0, 1.0) * 1000)));
    way_->setFormat(
        tr("%1 of %2 → %3")
            .arg(inUnit(s.position, units_.position), inUnit(from_, units_.position), inUnit(to_, units_.position)));
    showHandshake();
}

void Ds402PositionMoveBox::showHandshake() {
    auto mark = [this](int phase) { return phase_ >= phase ? QStringLiteral("✔") : QStringLiteral("○"); };
    handshake_->setText(tr("Set-point handshake: %1 new set-point (bit 4 = 1) → %2 acknowledged (bit 12), bit 4 = 0 → "
                           "%3 target reached (bit 10)")
                            .arg(mark(1), mark(2), mark(3)));
}

void Ds402PositionMoveBox::showResult(const QString& text, bool ok) {
    if (ok && phase_ >= 2) phase_ = 3;
    showHandshake();
    result_->setText(text);
    result_->setStyleSheet(ok ? QStringLiteral("color: #1b7a30; font-weight: bold;")
                              : QStringLiteral("color: #a00000; font-weight: bold;"));
}

QString Ds402PositionMoveBox::resultText() const { return result_->text(); }
QString Ds402PositionMoveBox::handshakeText() const { return handshake_->text(); }

}  // namespace coscope::gui
