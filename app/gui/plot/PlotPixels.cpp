// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/PlotPixels.h"

#include <qcustomplot.h>

#include <cmath>
#include <cstdlib>

namespace coscope::gui {

PlotPixels PlotPixels::of(QCPPainter* painter) {
    PlotPixels out;
    QPaintDevice* device = painter->device();
    if (!device || device->devType() != QInternal::Image || painter->modes().testFlag(QCPPainter::pmVectorized) ||
        painter->opacity() != 1.0 || painter->compositionMode() != QPainter::CompositionMode_SourceOver)
        return out;
    auto* img = static_cast<QImage*>(device);
    const QImage::Format f = img->format();
    if (f != QImage::Format_ARGB32_Premultiplied && f != QImage::Format_ARGB32 && f != QImage::Format_RGB32) return out;
    if (img->devicePixelRatio() != 1.0) return out;  // a high-DPI buffer: device pixels are not painter pixels
    painter->save();
    painter->setAntialiasing(false);  // QCPPainter drops its half-pixel shift
    const QTransform t = painter->combinedTransform();
    bool ok = t.type() <= QTransform::TxTranslate && t.dx() == std::round(t.dx()) && t.dy() == std::round(t.dy());
    out.shift = QPoint(int(t.dx()), int(t.dy()));
    out.clip = img->rect();
    if (ok && painter->hasClipping()) {
        const QRegion region = painter->clipRegion();
        ok = region.rectCount() <= 1;
        out.clip &= region.boundingRect().translated(out.shift);
    }
    painter->restore();
    if (ok) out.image = img;
    return out;
}

int PlotPixels::step(const QPen& pen) {
    if (pen.color().alpha() != 255 || pen.brush().style() != Qt::SolidPattern || pen.widthF() > 1.0) return 0;
    if (pen.style() == Qt::SolidLine) return 1;
    return pen.style() == Qt::DotLine ? 3 : 0;
}

void PlotPixels::line(const QLine& l, uint32_t px, int step) const {
    const QLine p = l.translated(shift);
    uchar* bits = image->bits();
    const qsizetype stride = image->bytesPerLine();
    if (p.x1() == p.x2()) {
        if (p.x1() < clip.left() || p.x1() > clip.right()) return;
        const int dir = p.y2() < p.y1() ? -1 : 1, n = std::abs(p.y2() - p.y1());
        for (int k = 0; k <= n; k += step) {
            const int y = p.y1() + dir * k;
            if (y >= clip.top() && y <= clip.bottom()) reinterpret_cast<uint32_t*>(bits + y * stride)[p.x1()] = px;
        }
    } else if (p.y1() == p.y2()) {
        if (p.y1() < clip.top() || p.y1() > clip.bottom()) return;
        const int dir = p.x2() < p.x1() ? -1 : 1, n = std::abs(p.x2() - p.x1());
        auto* row = reinterpret_cast<uint32_t*>(bits + p.y1() * stride);
        for (int k = 0; k <= n; k += step) {
            const int x = p.x1() + dir * k;
            if (x >= clip.left() && x <= clip.right()) row[x] = px;
        }
    }
}

}  // namespace coscope::gui
