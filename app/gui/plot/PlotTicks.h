// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <qcustomplot.h>

#include <QPointer>

#include <vector>

namespace coscope::gui {

struct PlotPixels;

// The tick marks of the plot's axes, drawn first on the axes' layer instead of by each axis: the same marks (QCPAxisPainterPrivate::draw: a line a tick and a sub tick, inward by
// the tick lengths, from the axis's offset; the axis keeps its base line and labels and draws
// its ticks with no pen). On the plot's own image the marks are written pixel by pixel; the
// raster engine spends ~2000 instructions on each of the ~500 tiny lines of a stacked replot.
// Anything else (PDF, scaled exports) draws them with QPainter as the axis would.
class PlotTicks : public QCPLayerable {
public:
    explicit PlotTicks(QCustomPlot* plot);

    // Takes over the ticks of `axis` (visible, with ticks, on the left, right or bottom).
    void adopt(QCPAxis* axis);
    void clear() { axes_.clear(); }
    // Puts the marks first on the adopted axes' layer (call once they are adopted).
    void placeFirst();

protected:
    void applyDefaultAntialiasingHint(QCPPainter* painter) const override;
    void draw(QCPPainter* painter) override;

private:
    struct Adopted {
        QPointer<QCPAxis> axis;
        QPen tick, subTick;  // the axis's pens (it keeps Qt::NoPen)
    };
    void drawAxis(QCPPainter* painter, const Adopted& a, const PlotPixels& pixels) const;
    std::vector<Adopted> axes_;
};

}  // namespace coscope::gui
