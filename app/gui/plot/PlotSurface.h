// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/plot/SpanCanvas.h"

#include <qcustomplot.h>

#include <QImage>

namespace coscope::gui {

// The plot's QCustomPlot, painting into a QImage it owns rather than QCustomPlot's QPixmap:
//  - dense traces (EnvelopeGraph) write their per-column spans straight into the image's
//    pixels instead of asking the raster engine for thousands of small rectangles;
//  - with an opaque background the image starts each replot filled with it, so showing it is
//    one plain copy, not a fill of the widget followed by a blend of a transparent buffer.
// Everything else (layers, layout, exports through toPixmap/savePdf) is QCustomPlot's.
class PlotSurface : public QCustomPlot {
    Q_OBJECT
public:
    explicit PlotSurface(QWidget* parent = nullptr);

    // Where the dense traces of a replot wait to be written in one pass (EnvelopeGraph).
    SpanCanvas& canvas() { return canvas_; }
    // Call once the graphs exist: the canvas is written right after the last of them (before
    // anything drawn later on their layer: cursors, items).
    void placeTraceFlush();

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    class ImageBuffer;
    class TraceFlush;
    void installImageBuffer();
    ImageBuffer* image_ = nullptr;  // mPaintBuffers' first entry, owned there
    SpanCanvas canvas_;
    TraceFlush* flush_ = nullptr;  // a layerable of the plot (owned by it)
};

}  // namespace coscope::gui
