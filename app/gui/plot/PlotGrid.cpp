// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/PlotGrid.h"

#include "app/gui/plot/PlotPixels.h"

#include <cmath>

namespace coscope::gui {

PlotGrid::PlotGrid(QCustomPlot* plot) : QCPLayerable(plot) { setLayer(QStringLiteral("grid")); }

void PlotGrid::adopt(QCPAxis* axis) {
    if (!axis || !axis->grid()->visible()) return;
    axis->grid()->setVisible(false);
    axes_.emplace_back(axis);
}

void PlotGrid::applyDefaultAntialiasingHint(QCPPainter* painter) const {
    painter->setAntialiasing(false);
}  // QCPGrid's default

void PlotGrid::draw(QCPPainter* painter) {
    const PlotPixels pixels = PlotPixels::of(painter);
    for (const QPointer<QCPAxis>& axis : axes_)
        if (axis && axis->realVisibility()) drawAxis(painter, axis, pixels);
}

void PlotGrid::drawAxis(QCPPainter* painter, QCPAxis* axis, const PlotPixels& pixels) const {
    const QCPGrid* grid = axis->grid();
    const QCPAxisRect* rect = axis->axisRect();
    const QCPRange range = axis->range();
    const QVector<double> ticks = axis->tickVector();
    const bool horizontal = axis->orientation() == Qt::Horizontal;
    // A line at pixel t across the rect, as QCPGrid gives it to the painter (vertical lines
    // from the bottom up, horizontal ones from the left).
    auto line = [&](double t) {
        return horizontal ? QLineF(t, rect->bottom(), t, rect->top()) : QLineF(rect->left(), t, rect->right(), t);
    };
    auto draw = [&](const QLineF& l, const QPen& pen) {
        if (const int step = pixels.image ? PlotPixels::step(pen) : 0) {
            pixels.line(l.toLine(), qPremultiply(pen.color().rgba()),
                        step);  // as QCPPainter rounds it without antialiasing
            return;
        }
        painter->setPen(pen);
        painter->drawLine(l);
    };
    painter->save();
    painter->setAntialiasing(false);
    // QCPGrid::drawGridLines: the zero line (when 0 is inside the range and a tick) replaces that
    // tick's grid line.
    qsizetype zero = -1;
    if (grid->zeroLinePen().style() != Qt::NoPen && range.lower < 0 && range.upper > 0) {
        const double epsilon = range.size() * 1e-6;
        for (qsizetype i = 0; i < ticks.size() && zero < 0; ++i)
            if (std::abs(ticks[i]) < epsilon) zero = i;
        if (zero >= 0) draw(line(axis->coordToPixel(ticks[zero])), grid->zeroLinePen());
    }
    for (qsizetype i = 0; i < ticks.size(); ++i)
        if (i != zero) draw(line(axis->coordToPixel(ticks[i])), grid->pen());
    painter->restore();
}

}  // namespace coscope::gui
