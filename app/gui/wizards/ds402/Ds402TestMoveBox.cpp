// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/ds402/Ds402TestMoveBox.h"

#include "app/gui/wizards/ds402/Ds402MotionPlot.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QPushButton>
#include <QSpinBox>

#include <cmath>

namespace coscope::gui {

using canopen::Ds402TestMove;

namespace {
// A spin box in the drive's unit `u`, showing `raw` drive units.
void showInUnit(QDoubleSpinBox* box, const od::Unit& u, double maxRaw, double raw) {
    box->setDecimals(unitDecimals(u));
    box->setRange(-maxRaw * u.factor, maxRaw * u.factor);
    box->setSingleStep(std::max(1.0, 100.0 * u.factor));
    box->setSuffix(QStringLiteral(" ") + u.text);
    box->setValue(raw * u.factor);
}
}  // namespace

Ds402TestMoveBox::Ds402TestMoveBox(QWidget* parent) : QGroupBox(tr("Test move (optional, small limits)"), parent) {
    auto* layout = new QHBoxLayout(this);
    auto* form = new QFormLayout;
    kind_ = new QComboBox(this);
    kind_->addItem(tr("Jog (profile velocity, 60FFh)"), 0);
    kind_->addItem(tr("Short move (profile position, 607Ah relative)"), 1);
    connect(kind_, &QComboBox::currentIndexChanged, this, &Ds402TestMoveBox::applyUnits);
    form->addRow(tr("Kind:"), kind_);
    // In the drive's units (applyUnits): 2000 and 5000 drive units to begin with.
    velocity_ = new QDoubleSpinBox(this);
    velocity_->setObjectName(QStringLiteral("testVelocity"));
    form->addRow(tr("Velocity:"), velocity_);
    distance_ = new QDoubleSpinBox(this);
    distance_->setObjectName(QStringLiteral("testDistance"));
    form->addRow(tr("Distance:"), distance_);
    velocityShownIn_ = units_.jogVelocity;
    distanceShownIn_ = units_.distance;
    showInUnit(velocity_, velocityShownIn_, Ds402TestMove::kMaxVelocity, 2000);
    showInUnit(distance_, distanceShownIn_, Ds402TestMove::kMaxDistance, 5000);
    duration_ = new QSpinBox(this);
    duration_->setRange(100, Ds402TestMove::kMaxDurationMs);
    duration_->setValue(3000);
    duration_->setSuffix(tr(" ms max"));
    form->addRow(tr("Time limit:"), duration_);
    arm_ = new QPushButton(tr("Arm test move…"), this);
    arm_->setObjectName(QStringLiteral("armTestMove"));
    connect(arm_, &QPushButton::clicked, this, &Ds402TestMoveBox::armClicked);
    hold_ = new QPushButton(tr("Hold to run"), this);
    hold_->setObjectName(QStringLiteral("holdToRun"));
    hold_->setMinimumHeight(40);
    hold_->setToolTip(tr("The motor moves only while this button is held down; releasing it stops the motor."));
    connect(hold_, &QPushButton::pressed, this, &Ds402TestMoveBox::holdPressed);
    connect(hold_, &QPushButton::released, this, &Ds402TestMoveBox::holdReleased);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(arm_);
    buttons->addWidget(hold_);
    form->addRow(buttons);
    layout->addLayout(form, 1);
    plot_ = new Ds402MotionPlot(this);
    layout->addWidget(plot_, 1);
}

void Ds402TestMoveBox::setMove(const Ds402TestMove& m) {
    setKind(m.kind);
    velocity_->setValue(m.velocity * velocityShownIn_.factor);
    distance_->setValue(m.distance * distanceShownIn_.factor);
    duration_->setValue(m.maxDurationMs);
}

Ds402TestMove Ds402TestMoveBox::move() const {
    // The spin boxes show the drive's units; the drive gets raw numbers (display = raw × factor).
    const auto velocity = static_cast<int32_t>(std::llround(velocity_->value() / velocityShownIn_.factor));
    Ds402TestMove m;
    m.kind = kind_->currentIndex() == 0 ? Ds402TestMove::Kind::Jog : Ds402TestMove::Kind::Relative;
    m.velocity = m.kind == Ds402TestMove::Kind::Jog ? velocity : std::abs(velocity);
    m.distance = static_cast<int32_t>(std::llround(distance_->value() / distanceShownIn_.factor));
    m.maxDurationMs = duration_->value();
    m.acceleration = m.deceleration = static_cast<uint32_t>(std::max(1000, std::abs(velocity) * 5));
    return m;
}

QString Ds402TestMoveBox::describe(const Ds402TestMove& m) const {
    if (m.kind == Ds402TestMove::Kind::Jog)
        return tr("turn at %1 (profile velocity, 60FFh = %2)")
            .arg(inUnit(m.velocity, velocityShownIn_))
            .arg(m.velocity);
    return tr("move %1 at up to %2 (profile position, relative: 607Ah = %3, 6081h = %4)")
        .arg(inUnit(m.distance, distanceShownIn_), inUnit(m.velocity, velocityShownIn_))
        .arg(m.distance)
        .arg(m.velocity);
}

void Ds402TestMoveBox::setKind(Ds402TestMove::Kind kind) {
    kind_->setCurrentIndex(kind == Ds402TestMove::Kind::Jog ? 0 : 1);
}

void Ds402TestMoveBox::setUnits(const Ds402Units& units) {
    units_ = units;
    applyUnits();
}

void Ds402TestMoveBox::applyUnits() {
    // The same speed and distance, shown in the unit of the object the move kind writes.
    const double velocity = velocity_->value() / velocityShownIn_.factor,
                 distance = distance_->value() / distanceShownIn_.factor;
    velocityShownIn_ = kind_->currentIndex() == 0 ? units_.jogVelocity : units_.profileVelocity;
    distanceShownIn_ = units_.distance;
    showInUnit(velocity_, velocityShownIn_, Ds402TestMove::kMaxVelocity, velocity);
    showInUnit(distance_, distanceShownIn_, Ds402TestMove::kMaxDistance, distance);
    plot_->setUnits(units_.position, units_.velocity);
}

void Ds402TestMoveBox::setButtons(bool armEnabled, bool holdEnabled) {
    arm_->setEnabled(armEnabled);
    hold_->setEnabled(holdEnabled);
}

}  // namespace coscope::gui
