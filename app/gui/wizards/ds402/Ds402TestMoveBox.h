// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/Ds402Controller.h"

#include "app/gui/wizards/ds402/Ds402Units.h"

#include <QGroupBox>

class QComboBox;
class QDoubleSpinBox;
class QPushButton;
class QSpinBox;

namespace coscope::gui {

class Ds402MotionPlot;

// The optional test move of the CiA 402 wizard: a jog in profile velocity (60FFh) or a short
// relative move in profile position (607Ah/6081h), within small limits and in the drive's own
// units, run only while "Hold to run" is held down, with a live plot of position and velocity.
class Ds402TestMoveBox : public QGroupBox {
    Q_OBJECT
public:
    explicit Ds402TestMoveBox(QWidget* parent = nullptr);

    // The move as set, in raw drive units (display = raw × factor).
    canopen::Ds402TestMove move() const;
    void setMove(const canopen::Ds402TestMove& move);
    // What `move` does, for the confirmation: "turn at 150 rpm (profile velocity, 60FFh = 1500)".
    QString describe(const canopen::Ds402TestMove& move) const;
    void setKind(canopen::Ds402TestMove::Kind kind);
    // The drive's units (from its dictionary); the speed and distance set stay the same.
    void setUnits(const Ds402Units& units);
    void setButtons(bool armEnabled, bool holdEnabled);

    QPushButton* armButton() const { return arm_; }
    QPushButton* holdButton() const { return hold_; }
    Ds402MotionPlot* plot() const { return plot_; }

signals:
    void armClicked();
    void holdPressed();
    void holdReleased();

private:
    void applyUnits();

    Ds402Units units_ = Ds402Units::forDictionary({});
    od::Unit velocityShownIn_, distanceShownIn_;  // what the spin boxes show now
    QComboBox* kind_ = nullptr;
    QDoubleSpinBox* velocity_ = nullptr;
    QDoubleSpinBox* distance_ = nullptr;
    QSpinBox* duration_ = nullptr;
    QPushButton* arm_ = nullptr;
    QPushButton* hold_ = nullptr;
    Ds402MotionPlot* plot_ = nullptr;
};

}  // namespace coscope::gui
