// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/PlotTicks.h"

#include "app/gui/plot/PlotPixels.h"

namespace coscope::gui {

namespace {
// The axis's sub tick positions: QCPAxis keeps them protected (no getter); a pointer to the
// member, named through a derived class, reads them.
struct PlotTicksAxisAccess : QCPAxis {
    static const QVector<double>& subTicks(const QCPAxis* axis) {
        return axis->*(&PlotTicksAxisAccess::mSubTickVector);
    }
};
}  // namespace

PlotTicks::PlotTicks(QCustomPlot* plot) : QCPLayerable(plot) {}

void PlotTicks::placeFirst() {
    // Ahead of everything on the axes' layer (QCustomPlot puts the axes of new rects on the
    // current layer, "main", with the traces): each rect's traces covered its marks, as they do
    // here, on screen (traces written last) and in exports alike. The axes' base lines, drawn
    // after, share the marks' colour where they meet.
    if (!axes_.empty() && axes_.front().axis) moveToLayer(axes_.front().axis->layer(), true);
}

void PlotTicks::adopt(QCPAxis* axis) {
    if (!axis || !axis->visible() || !axis->ticks() || axis->axisType() == QCPAxis::atTop) return;
    axes_.push_back({axis, axis->tickPen(), axis->subTickPen()});
    axis->setTickPen(Qt::NoPen);
    axis->setSubTickPen(Qt::NoPen);
}

void PlotTicks::applyDefaultAntialiasingHint(QCPPainter* painter) const {
    painter->setAntialiasing(false);
}  // QCPAxis's default

void PlotTicks::draw(QCPPainter* painter) {
    const PlotPixels pixels = PlotPixels::of(painter);
    for (const Adopted& a : axes_)
        if (a.axis && a.axis->realVisibility() && a.axis->ticks()) drawAxis(painter, a, pixels);
}

void PlotTicks::drawAxis(QCPPainter* painter, const Adopted& a, const PlotPixels& pixels) const {
    QCPAxis* axis = a.axis;
    const QRect rect = axis->axisRect()->rect();
    const int offset = axis->offset();
    const QCPAxis::AxisType type = axis->axisType();
    // QCPAxisPainterPrivate::draw: the origin, the right axis's one-pixel correction, inward.
    const QPoint origin = type == QCPAxis::atLeft    ? rect.bottomLeft() + QPoint(-offset, 0)
                          : type == QCPAxis::atRight ? rect.bottomRight() + QPoint(offset, 0)
                                                     : rect.bottomLeft() + QPoint(0, offset);
    const double xCor = type == QCPAxis::atRight ? 1 : 0;
    const int dir = type == QCPAxis::atBottom || type == QCPAxis::atRight ? -1 : 1;
    const bool horizontal = type == QCPAxis::atBottom;
    auto mark = [&](double at, int out, int in) {
        return horizontal ? QLineF(at + xCor, origin.y() - out * dir, at + xCor, origin.y() + in * dir)
                          : QLineF(origin.x() - out * dir + xCor, at, origin.x() + in * dir + xCor, at);
    };
    auto marks = [&](const QVector<double>& at, const QPen& pen, int out, int in) {
        if (pen.style() == Qt::NoPen || at.isEmpty()) return;
        const int step = pixels.image ? PlotPixels::step(pen) : 0;
        const uint32_t px = qPremultiply(pen.color().rgba());
        if (!step) painter->setPen(pen);
        for (double v : at) {
            const QLineF l = mark(axis->coordToPixel(v), out, in);
            if (step) pixels.line(l.toLine(), px, step);  // as QCPPainter rounds it without antialiasing
            else painter->drawLine(l);
        }
    };
    painter->save();
    painter->setAntialiasing(false);
    const QVector<double> ticks = axis->tickVector();
    const QVector<double>& subTicks = PlotTicksAxisAccess::subTicks(axis);
    marks(ticks, a.tick, axis->tickLengthOut(), axis->tickLengthIn());
    if (axis->subTicks()) marks(subTicks, a.subTick, axis->subTickLengthOut(), axis->subTickLengthIn());
    // The base line's endings (QCPAxisRect::addAxis gives a second axis on a side half bars):
    // QCPAxisPainterPrivate draws them antialiased with the pen it last set, the sub ticks' (or
    // the ticks', the base line's), which the axis now has as no pen.
    const QCPLineEnding lower = axis->lowerEnding(), upper = axis->upperEnding();
    if (lower.style() != QCPLineEnding::esNone || upper.style() != QCPLineEnding::esNone) {
        const QPointF o = QPointF(origin) + QPointF(xCor, 0);
        QLineF base = horizontal ? QLineF(o, o + QPointF(rect.width(), 0)) : QLineF(o, o + QPointF(0, -rect.height()));
        if (axis->rangeReversed()) base = QLineF(base.p2(), base.p1());
        const QPen pen = axis->subTicks() && !subTicks.isEmpty() ? a.subTick
                         : !ticks.isEmpty()                      ? a.tick
                                                                 : axis->basePen();
        painter->setPen(pen);
        painter->setAntialiasing(true);
        painter->setBrush(QBrush(axis->basePen().color()));
        const QCPVector2D v(base.dx(), base.dy());
        if (lower.style() != QCPLineEnding::esNone)
            lower.draw(painter,
                       QCPVector2D(base.p1()) - v.normalized() * lower.realLength() * (lower.inverted() ? -1 : 1), -v);
        if (upper.style() != QCPLineEnding::esNone)
            upper.draw(painter,
                       QCPVector2D(base.p2()) + v.normalized() * upper.realLength() * (upper.inverted() ? -1 : 1), v);
    }
    painter->restore();
}

}  // namespace coscope::gui
