// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

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

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    class ImageBuffer;
    void installImageBuffer();
    ImageBuffer* image_ = nullptr;  // mPaintBuffers' first entry, owned there
};

}  // namespace coscope::gui
