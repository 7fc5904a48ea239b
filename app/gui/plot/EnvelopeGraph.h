// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <qcustomplot.h>

#include <QRect>
#include <QVector>

namespace coscope::gui {

// A QCPGraph that paints a dense trace as one vertical span per pixel column instead of a
// polyline. The plot feeds it the buffer's min/max pyramid output (at most two points per pixel
// column, SignalBuffer::decimate), so it never holds more than ~2 points per pixel; when there
// are more points than columns the zig-zag polyline QCustomPlot would stroke (the dominant cost
// of a replot) is rasterised here into per-column spans: the column's extremes plus the join
// from the previous column, filled as 1-pixel-wide rectangles. Pixel for pixel this is what the
// non-antialiased polyline covers, within a pixel at the joins. Sparse traces (zoomed in) keep
// QCustomPlot's own line drawing. Legend, selection, fills and cursors are QCPGraph's.
class EnvelopeGraph : public QCPGraph {
    Q_OBJECT
public:
    EnvelopeGraph(QCPAxis* keyAxis, QCPAxis* valueAxis);

    // The rectangles of the last dense paint (pixel coordinates), for tests; empty when the
    // last paint drew a polyline.
    const QVector<QRect>& lastSpans() const { return spans_; }
    // Whether the last dense paint wrote its spans straight into the paint buffer's pixels.
    bool lastPaintDirect() const { return direct_; }

    // One vertical span per pixel column covering a polyline given in pixel coordinates
    // (x ascending). Segments longer than one column are returned in `longSegments` (drawn as
    // lines). Public so tests can check it against a plain scan.
    static void rasterise(const QVector<QPointF>& polyline, QVector<QRect>* spans, QVector<QLineF>* longSegments);

    // The same pixels as `spans` (one per column, x ascending) as few rectangles: runs of
    // columns sharing rows become one rectangle.
    static void mergeColumns(const QVector<QRect>& spans, QVector<QRect>* blocks);

protected:
    // The plain case (a linear line graph, nothing selected, no fill or scatters, on a raster
    // painter) converts the visible points to pixels in one loop instead of QCPGraph's copy of
    // them and two out-of-line coordToPixel calls a point; the same points as QCPGraph::getLines
    // gives, then drawLinePlot. Anything else is QCPGraph::draw.
    void draw(QCPPainter* painter) override;
    void drawLinePlot(QCPPainter* painter, const QVector<QPointF>& lines) const override;

private:
    // Writes the spans straight into the painter's QImage (the plot's own paint buffer) when
    // that is pixel for pixel what filling them would do; false: paint them instead.
    bool fillDirect(QCPPainter* painter, const QColor& color, int w) const;

    mutable QVector<QRect> spans_;
    QVector<QPointF> lines_;  // the plain case's pixel points, reused
    mutable bool direct_ = false;
    mutable QVector<QRect> blocks_;
    mutable QVector<QLineF> longSegments_;
};

}  // namespace coscope::gui
