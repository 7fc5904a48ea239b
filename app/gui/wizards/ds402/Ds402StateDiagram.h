// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/Ds402.h"

#include <QRectF>
#include <QWidget>

#include <optional>

namespace coscope::gui {

// The CiA 402 power drive state machine (CiA 402-2 §6.2, Figure 19) as a picture: one box per
// state, the current one lit (red when it is a fault state), the numbered transitions as arrows
// and the next step of the enable sequence highlighted.
class Ds402StateDiagram : public QWidget {
    Q_OBJECT
public:
    explicit Ds402StateDiagram(QWidget* parent = nullptr);

    // Unknown = nothing lit (not read yet).
    void setState(canopen::ds402::State state);
    canopen::ds402::State state() const { return state_; }
    // The transition to highlight (number 1-16), none when nullopt.
    void setNextTransition(std::optional<int> number);
    std::optional<int> nextTransition() const { return next_; }
    // Where a state's box is drawn (for tests and tooltips).
    QRectF boxOf(canopen::ds402::State state) const;

    QSize sizeHint() const override { return {520, 330}; }
    QSize minimumSizeHint() const override { return {440, 290}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    canopen::ds402::State state_ = canopen::ds402::State::Unknown;
    std::optional<int> next_;
};

// The transition number (CiA 402-2 Figure 19) a command causes from `from`, if any.
std::optional<int> ds402TransitionNumber(canopen::ds402::State from, canopen::ds402::Command command);

}  // namespace coscope::gui
