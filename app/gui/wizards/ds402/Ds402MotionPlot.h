// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/wizards/ds402/Ds402Units.h"

#include <QWidget>

#include <vector>

namespace coscope::gui {

// The test move's live plot: position actual (6064h) and velocity actual (606Ch) over time,
// each scaled to its own range, from the samples the controller reads while the move runs; the
// legend gives the latest values in the drive's units.
class Ds402MotionPlot : public QWidget {
    Q_OBJECT
public:
    explicit Ds402MotionPlot(QWidget* parent = nullptr);

    void addSample(double ms, double position, double velocity);
    void clear();
    int sampleCount() const { return static_cast<int>(t_.size()); }
    void setUnits(const od::Unit& position, const od::Unit& velocity);
    // What the empty plot says (the test move's motion by default).
    void setPlaceholder(const QString& text);
    // The legend as shown: "velocity 606Ch: 150 rpm" (the name alone before the first sample).
    QString positionText() const;
    QString velocityText() const;
    QSize sizeHint() const override { return {320, 120}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::vector<double> t_, pos_, vel_;
    od::Unit posUnit_, velUnit_;
    QString placeholder_;
};

}  // namespace coscope::gui
