// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/PlotGrid.h"

#include <cmath>

namespace coscope::gui {

namespace {
// A pen written pixel by pixel: opaque, 1 pixel, solid or Qt's dots; 0 when it is not one.
int plotGridStep(const QPen& pen) {
    if (pen.color().alpha() != 255 || pen.brush().style() != Qt::SolidPattern || pen.widthF() > 1.0) return 0;
    if (pen.style() == Qt::SolidLine) return 1;
    return pen.style() == Qt::DotLine ? 3 : 0;
}
}  // namespace

PlotGrid::PlotGrid(QCustomPlot* plot) : QCPLayerable(plot) { setLayer(QStringLiteral("grid")); }

void PlotGrid::adopt(QCPAxis* axis) {
    if (!axis || !axis->grid()->visible()) return;
    axis->grid()->setVisible(false);
    axes_.emplace_back(axis);
}

void PlotGrid::applyDefaultAntialiasingHint(QCPPainter* painter) const { painter->setAntialiasing(false); }  // QCPGrid's default

void PlotGrid::draw(QCPPainter* painter) {
    // Writing pixels is what the raster engine would do only on a 32-bit image, plain
    // source-over, unscaled, whole-pixel translation, one clip rectangle.
    QImage* image = nullptr;
    QPoint shift;
    QRect clip;
    QPaintDevice* device = painter->device();
    if (device && device->devType() == QInternal::Image && !painter->modes().testFlag(QCPPainter::pmVectorized) && painter->opacity() == 1.0 &&
        painter->compositionMode() == QPainter::CompositionMode_SourceOver) {
        auto* img = static_cast<QImage*>(device);
        const QImage::Format f = img->format();
        const QTransform t = painter->combinedTransform();
        bool ok = (f == QImage::Format_ARGB32_Premultiplied || f == QImage::Format_ARGB32 || f == QImage::Format_RGB32) && t.type() <= QTransform::TxTranslate &&
                  t.dx() == std::round(t.dx()) && t.dy() == std::round(t.dy());
        shift = QPoint(int(t.dx()), int(t.dy()));
        clip = img->rect();
        if (ok && painter->hasClipping()) {
            const QRegion region = painter->clipRegion();
            ok = region.rectCount() <= 1;
            clip &= region.boundingRect().translated(shift);
        }
        if (ok) image = img;
    }
    for (const QPointer<QCPAxis>& axis : axes_)
        if (axis && axis->realVisibility()) drawAxis(painter, axis, image, shift, clip);
}

void PlotGrid::drawAxis(QCPPainter* painter, QCPAxis* axis, QImage* image, QPoint shift, const QRect& clip) const {
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
        const int step = image ? plotGridStep(pen) : 0;
        if (!step) {
            painter->setPen(pen);
            painter->drawLine(l);  // QCPPainter rounds the line to whole pixels without antialiasing
            return;
        }
        const QLine p = l.toLine().translated(shift);
        const uint32_t px = qPremultiply(pen.color().rgba());
        uchar* bits = image->bits();
        const qsizetype stride = image->bytesPerLine();
        if (p.x1() == p.x2()) {
            if (p.x1() < clip.left() || p.x1() > clip.right()) return;
            const int dir = p.y2() < p.y1() ? -1 : 1, n = std::abs(p.y2() - p.y1());
            for (int k = 0; k <= n; k += step) {
                const int y = p.y1() + dir * k;
                if (y >= clip.top() && y <= clip.bottom()) reinterpret_cast<uint32_t*>(bits + y * stride)[p.x1()] = px;
            }
        } else {
            if (p.y1() < clip.top() || p.y1() > clip.bottom()) return;
            const int dir = p.x2() < p.x1() ? -1 : 1, n = std::abs(p.x2() - p.x1());
            auto* row = reinterpret_cast<uint32_t*>(bits + p.y1() * stride);
            for (int k = 0; k <= n; k += step) {
                const int x = p.x1() + dir * k;
                if (x >= clip.left() && x <= clip.right()) row[x] = px;
            }
        }
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
