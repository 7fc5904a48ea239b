// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/ds402/Ds402MotionPlot.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>

namespace coscope::gui {

namespace {
constexpr size_t kMaxSamples = 2000;
}

Ds402MotionPlot::Ds402MotionPlot(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("ds402MotionPlot"));
    setMinimumHeight(90);
}

void Ds402MotionPlot::addSample(double ms, double position, double velocity) {
    if (t_.size() >= kMaxSamples) {
        t_.erase(t_.begin());
        pos_.erase(pos_.begin());
        vel_.erase(vel_.begin());
    }
    t_.push_back(ms);
    pos_.push_back(position);
    vel_.push_back(velocity);
    update();
}

void Ds402MotionPlot::setUnits(const od::Unit& position, const od::Unit& velocity) {
    posUnit_ = position;
    velUnit_ = velocity;
    update();
}

QString Ds402MotionPlot::positionText() const {
    return pos_.empty() ? tr("position 6064h") : tr("position 6064h: %1").arg(inUnit(pos_.back(), posUnit_));
}

QString Ds402MotionPlot::velocityText() const {
    return vel_.empty() ? tr("velocity 606Ch") : tr("velocity 606Ch: %1").arg(inUnit(vel_.back(), velUnit_));
}

void Ds402MotionPlot::clear() {
    t_.clear();
    pos_.clear();
    vel_.clear();
    update();
}

void Ds402MotionPlot::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const double line = fontMetrics().lineSpacing();
    const QRectF area = QRectF(rect()).adjusted(4, 2 * line + 6, -4, -4);  // the legend above, one line each
    p.fillRect(rect(), palette().base());
    p.setPen(QColor(200, 200, 200));
    p.drawRect(area);
    p.setPen(QColor(30, 90, 200));
    p.drawText(QPointF(6, line), positionText());
    p.setPen(QColor(220, 110, 20));
    p.drawText(QPointF(6, 2 * line + 2), velocityText());
    if (t_.size() < 2) {
        p.setPen(palette().placeholderText().color());
        p.drawText(area, Qt::AlignCenter,
                   placeholder_.isEmpty() ? tr("The test move's motion shows here") : placeholder_);
        return;
    }
    const double t0 = t_.front(), t1 = std::max(t_.back(), t0 + 1);
    auto draw = [&](const std::vector<double>& y, QColor c) {
        auto [lo, hi] = std::minmax_element(y.begin(), y.end());
        const double a = *lo, b = std::max(*hi, *lo + 1);
        QPainterPath path;
        for (size_t i = 0; i < y.size(); ++i) {
            const QPointF pt(area.left() + (t_[i] - t0) / (t1 - t0) * area.width(),
                             area.bottom() - (y[i] - a) / (b - a) * area.height());
            if (i == 0) path.moveTo(pt);
            else path.lineTo(pt);
        }
        p.setPen(QPen(c, 1.8));
        p.drawPath(path);
    };
    draw(pos_, QColor(30, 90, 200));
    draw(vel_, QColor(220, 110, 20));
}

void Ds402MotionPlot::setPlaceholder(const QString& text) {
    placeholder_ = text;
    update();
}

}  // namespace coscope::gui
