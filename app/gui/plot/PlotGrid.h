// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <qcustomplot.h>

#include <QPointer>

#include <vector>

namespace coscope::gui {

struct PlotPixels;

// The grid lines of the plot's axes, drawn in their place (QCustomPlot's "grid" layer) instead of
// by each axis's QCPGrid: the same lines (QCPGrid::drawGridLines: a line a tick, the zero line
// instead of the tick line at 0, the grid's pens). On the plot's own image, a 1-pixel dotted or
// solid line is written pixel by pixel (Qt's dot pattern: a dot every third pixel from where the
// line starts, bottom for vertical lines, left for horizontal ones); the raster engine's
// cosmetic stroker costs ~10 % of a replot for the same dots. Anything else (PDF, scaled
// exports) draws the lines with QPainter as QCPGrid does.
class PlotGrid : public QCPLayerable {
public:
    explicit PlotGrid(QCustomPlot* plot);

    // Takes over the grid of `axis` (if visible): hides its QCPGrid and draws it here.
    void adopt(QCPAxis* axis);
    void clear() { axes_.clear(); }

protected:
    void applyDefaultAntialiasingHint(QCPPainter* painter) const override;
    void draw(QCPPainter* painter) override;

private:
    void drawAxis(QCPPainter* painter, QCPAxis* axis, const PlotPixels& pixels) const;
    std::vector<QPointer<QCPAxis>> axes_;
};

}  // namespace coscope::gui
