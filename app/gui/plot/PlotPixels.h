// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QImage>
#include <QLine>
#include <QPen>
#include <QPoint>
#include <QRect>

class QCPPainter;

namespace coscope::gui {

// The plot's image behind a painter, when writing a 1-pixel line's pixels straight into it is
// what the raster engine would do: a 32-bit image at device pixel ratio 1, plain source-over,
// full opacity, unscaled, whole-pixel translation, one clip rectangle (PlotGrid, PlotTicks).
struct PlotPixels {
    QImage* image = nullptr;  // nullptr: draw with the painter
    QPoint shift;             // painter to image coordinates
    QRect clip;               // image coordinates

    static PlotPixels of(QCPPainter* painter);
    // A pen written pixel by pixel: opaque, at most 1 pixel wide, solid (1) or Qt's dots (a dot
    // every third pixel from where the line starts); 0 when it is not one.
    static int step(const QPen& pen);
    // The pixels of `line` (painter coordinates, horizontal or vertical, both ends included) from
    // its first point on, every `step`th one.
    void line(const QLine& line, uint32_t px, int step) const;
};

}  // namespace coscope::gui
