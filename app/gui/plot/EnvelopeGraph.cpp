// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/EnvelopeGraph.h"

#include "app/gui/plot/PlotSurface.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace coscope::gui {

namespace {
// n pixels of one colour, four to a store (what the raster engine's own fill does).
void fillRow(uint32_t* p, int n, uint32_t v) {
    using V4 = uint32_t __attribute__((vector_size(16)));
    const V4 four = {v, v, v, v};
    int i = 0;
    for (; i + 4 <= n; i += 4) std::memcpy(p + i, &four, sizeof four);
    for (; i < n; ++i) p[i] = v;
}
}  // namespace

EnvelopeGraph::EnvelopeGraph(QCPAxis* keyAxis, QCPAxis* valueAxis) : QCPGraph(keyAxis, valueAxis) {}

void EnvelopeGraph::rasterise(const QVector<QPointF>& polyline, QVector<QRect>* spans, QVector<QLineF>* longSegments) {
    longSegments->clear();
    // At most a span a point: written through a pointer, the vector cut to size at the end
    // (an append a span costs more than the rest of the loop).
    spans->resize(polyline.size());
    QRect* out = spans->data();
    bool open = false;  // a column is being collected
    int column = 0;
    double lo = 0, hi = 0;
    QPointF prev;
    auto floorInt = [](double v) {  // std::floor for finite values in int range, without a libm call
        const int i = static_cast<int>(v);
        return v < i ? i - 1 : i;
    };
    auto flush = [&] {
        const int top = floorInt(lo), bottom = floorInt(hi);
        *out++ = QRect(column, top, 1, bottom - top + 1);
    };
    for (const QPointF& p : polyline) {
        if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || std::abs(p.x()) > 1e9 ||
            std::abs(p.y()) > 1e9) {  // a gap (NaN value): the line breaks
            if (open) flush();
            open = false;
            continue;
        }
        const int c = floorInt(p.x());
        if (!open) {
            open = true;
            column = c;
            lo = hi = p.y();
        } else if (c == column) {
            lo = std::min(lo, p.y());
            hi = std::max(hi, p.y());
        } else if (std::abs(c - column) == 1) {
            // The join to the previous column's last point is drawn in the new column.
            flush();
            column = c;
            lo = std::min(prev.y(), p.y());
            hi = std::max(prev.y(), p.y());
        } else {
            // A gap in the data wider than a column: a plain line segment bridges it.
            flush();
            longSegments->append(QLineF(prev, p));
            column = c;
            lo = hi = p.y();
        }
        prev = p;
    }
    if (open) flush();
    spans->resize(out - spans->data());
}

void EnvelopeGraph::mergeColumns(const QVector<QRect>& spans, QVector<QRect>* blocks) {
    // Sweep the columns left to right keeping open bands of rows (disjoint, together the
    // previous column's span) with the column each opened at. Rows a column no longer covers
    // close their band into a rectangle; rows it newly covers open a band (at most two: above
    // and below, as every column's span is one interval).
    blocks->clear();
    struct Band {
        int top, bottom, since;
    };
    std::vector<Band> open, next;
    int last = 0;
    auto close = [&](int top, int bottom, int since) {
        blocks->append(QRect(since, top, last - since + 1, bottom - top + 1));
    };
    auto closeAll = [&] {
        for (const Band& b : open) close(b.top, b.bottom, b.since);
        open.clear();
    };
    for (const QRect& s : spans) {
        const int c = s.x(), t = s.top(), b = s.bottom();
        if (!open.empty() && (c != last + 1 || open.size() > 32)) closeAll();  // a gap, or too fragmented
        next.clear();
        for (Band band : open) {
            if (band.bottom < t || band.top > b) {
                close(band.top, band.bottom, band.since);
                continue;
            }
            if (band.top < t) close(band.top, t - 1, band.since), band.top = t;
            if (band.bottom > b) close(b + 1, band.bottom, band.since), band.bottom = b;
            next.push_back(band);
        }
        if (next.empty()) {
            next.push_back({t, b, c});
        } else {
            if (next.front().top > t) next.insert(next.begin(), Band{t, next.front().top - 1, c});
            if (next.back().bottom < b) next.push_back({next.back().bottom + 1, b, c});
        }
        open.swap(next);
        last = c;
    }
    closeAll();
}

bool EnvelopeGraph::fillDirect(QCPPainter* painter, const QColor& color, int w) const {
    // Only where writing the pixels is exactly what the raster engine would do: a QImage in a
    // 32-bit format, opaque colour, plain source-over, whole-pixel translation, one clip rect.
    QPaintDevice* device = painter->device();
    if (!device || device->devType() != QInternal::Image) return false;
    auto* image = static_cast<QImage*>(device);
    const QImage::Format f = image->format();
    if (f != QImage::Format_ARGB32_Premultiplied && f != QImage::Format_ARGB32 && f != QImage::Format_RGB32)
        return false;
    if (color.alpha() != 255 || painter->opacity() != 1.0 ||
        painter->compositionMode() != QPainter::CompositionMode_SourceOver)
        return false;
    if (painter->pen().brush().style() != Qt::SolidPattern) return false;
    painter->save();
    painter->setAntialiasing(false);  // QCPPainter drops its half-pixel shift
    const QTransform t = painter->combinedTransform();
    const bool plain = painter->deviceTransform().isIdentity() && t.type() <= QTransform::TxTranslate &&
                       t.dx() == std::round(t.dx()) && t.dy() == std::round(t.dy());
    QRect clip = image->rect();
    bool ok = plain;
    if (ok && painter->hasClipping()) {
        const QRegion region = painter->clipRegion();
        ok = region.rectCount() <= 1;
        clip &= region.boundingRect().translated(static_cast<int>(t.dx()), static_cast<int>(t.dy()));
    }
    painter->restore();
    if (!ok) return false;
    const int dx = static_cast<int>(t.dx()), dy = static_cast<int>(t.dy());
    const uint32_t px = qPremultiply(color.rgba());
    uchar* bits = image->bits();
    const qsizetype stride = image->bytesPerLine();
    // On the plot's own surface the spans go to its canvas: all traces are written in one pass
    // once the last graph is drawn.
    if (auto* surface = qobject_cast<PlotSurface*>(parentPlot());
        surface && w == 1 && surface->canvas().add(image, px, spans_, dx, dy, clip))
        return true;
    // Row by row over the merged rectangles: consecutive pixels of a row share cache lines,
    // a column's would each touch its own.
    mergeColumns(spans_, &blocks_);
    for (const QRect& b : blocks_) {
        QRect r = b.translated(dx, dy);
        if (w > 1) r.adjust(-(w - 1) / 2, -(w - 1) / 2, w / 2, w / 2);
        r &= clip;
        if (r.isEmpty()) continue;
        for (int y = r.top(); y <= r.bottom(); ++y)
            fillRow(reinterpret_cast<uint32_t*>(bits + y * stride) + r.left(), r.width(), px);
    }
    return true;
}

void EnvelopeGraph::draw(QCPPainter* painter) {
    QCPAxis* key = keyAxis();
    QCPAxis* value = valueAxis();
    const bool plain = key && value && mLineStyle == lsLine && mScatterStyle.isNone() &&
                       mBrush.style() == Qt::NoBrush && selection().isEmpty() &&
                       !painter->modes().testFlag(QCPPainter::pmVectorized) && key->orientation() == Qt::Horizontal &&
                       key->scaleType() == QCPAxis::stLinear && value->scaleType() == QCPAxis::stLinear &&
                       !key->rangeReversed() && !value->rangeReversed();
    if (!plain) {
        QCPGraph::draw(painter);
        return;
    }
    const QCPRange kr = key->range(), vr = value->range();
    if (kr.size() <= 0 || mDataContainer->isEmpty()) return;
    // QCPGraph::getVisibleDataBounds: one point either side of the visible range.
    const auto begin = mDataContainer->findBegin(kr.lower), end = mDataContainer->findEnd(kr.upper);
    lines_.resize(end - begin);
    // QCPAxis::coordToPixel's linear, unreversed arithmetic, term for term (same pixels).
    const double kSize = kr.size(), kWidth = key->axisRect()->width(), kLeft = key->axisRect()->left();
    const double vSize = vr.size(), vHeight = value->axisRect()->height(), vBottom = value->axisRect()->bottom();
    QPointF* out = lines_.data();
    for (auto it = begin; it != end; ++it, ++out)
        *out =
            QPointF((it->key - kr.lower) / kSize * kWidth + kLeft, vBottom - (it->value - vr.lower) / vSize * vHeight);
    painter->setPen(mPen);
    painter->setBrush(Qt::NoBrush);
    drawLinePlot(painter, lines_);
}

void EnvelopeGraph::drawLinePlot(QCPPainter* painter, const QVector<QPointF>& lines) const {
    spans_.clear();
    direct_ = false;
    // Dense: more points than the pixel columns they cover. Vector output (PDF) and a vertical
    // key axis keep the polyline.
    const bool dense = lines.size() > 2 && std::abs(lines.back().x() - lines.front().x()) + 1 < lines.size();
    if (!dense || painter->modes().testFlag(QCPPainter::pmVectorized) || keyAxis()->orientation() != Qt::Horizontal) {
        QCPGraph::drawLinePlot(painter, lines);
        return;
    }
    rasterise(lines, &spans_, &longSegments_);
    const QPen pen = painter->pen();
    const int w = std::max(1, static_cast<int>(std::lround(pen.widthF())));
    if (!longSegments_.isEmpty()) painter->drawLines(longSegments_);
    if ((direct_ = fillDirect(painter, pen.color(), w))) return;
    // Filled as few wide rectangles (row fills) rather than a 1-pixel column per column: the
    // raster engine fills rows, so this is what keeps dense bands cheap.
    mergeColumns(spans_, &blocks_);
    if (w > 1)
        for (QRect& r : blocks_) r.adjust(-(w - 1) / 2, -(w - 1) / 2, w / 2, w / 2);
    painter->save();
    painter->setPen(Qt::NoPen);
    painter->setBrush(pen.color());
    painter->setAntialiasing(false);
    painter->drawRects(blocks_);
    painter->restore();
}

}  // namespace coscope::gui
