// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/PlotSurface.h"

#include <QPaintEvent>

#include <algorithm>
#include <cstdlib>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace coscope::gui {

namespace {
// Pixel memory for the plot's image, asked for in 2 MiB pages where the kernel offers them on
// request (transparent huge pages in "madvise" mode): a trace's column spans, the grid and the
// tick labels write rows ~5 KiB apart, each its own 4 KiB page otherwise (a TLB miss a row).
uchar* allocatePixels(size_t bytes) {
#ifdef __linux__
    constexpr size_t kHuge = size_t(2) << 20;
    const size_t rounded = (bytes + kHuge - 1) / kHuge * kHuge;
    void* p = nullptr;
    if (posix_memalign(&p, kHuge, rounded) != 0) return nullptr;
    madvise(p, rounded, MADV_HUGEPAGE);  // a hint: without it the memory is plain pages
    return static_cast<uchar*>(p);
#else
    return static_cast<uchar*>(std::malloc(bytes));
#endif
}
}  // namespace

// The bottom paint buffer as a QImage (ARGB32 premultiplied: other buffers and exports blend
// the same way). `base` is the opaque colour it starts from instead of transparent, when the
// plot's background is one opaque colour; then it is drawn as a copy.
class PlotSurface::ImageBuffer : public QCPAbstractPaintBuffer {
public:
    ImageBuffer(const QSize& size, double devicePixelRatio) : QCPAbstractPaintBuffer(size, devicePixelRatio) {
        ImageBuffer::reallocateBuffer();
    }

    QColor base;  // invalid: transparent like QCustomPlot's own buffers
    QImage* image() { return &image_; }

    QCPPainter* startPainting() override { return new QCPPainter(&image_); }
    void draw(QCPPainter* painter) const override {
        if (!painter || !painter->isActive()) return;
        if (base.isValid()) {
            const QPainter::CompositionMode mode = painter->compositionMode();
            painter->setCompositionMode(QPainter::CompositionMode_Source);
            painter->drawImage(0, 0, image_);
            painter->setCompositionMode(mode);
        } else {
            painter->drawImage(0, 0, image_);
        }
    }
    void clear(const QColor& color) override { image_.fill(color.alpha() == 0 && base.isValid() ? base : color); }

protected:
    void reallocateBuffer() override {
        setInvalidated();
        const QSize size = mSize * mDevicePixelRatio;
        const qsizetype stride = qsizetype(std::max(1, size.width())) * 4;
        uchar* pixels = allocatePixels(size_t(stride) * size_t(std::max(1, size.height())));
        if (pixels)
            image_ = QImage(
                pixels, size.width(), size.height(), stride, QImage::Format_ARGB32_Premultiplied,
                [](void* p) { std::free(p); }, pixels);
        else image_ = QImage(size, QImage::Format_ARGB32_Premultiplied);
        image_.setDevicePixelRatio(mDevicePixelRatio);
        image_.fill(base.isValid() ? base : QColor(Qt::transparent));
    }

private:
    QImage image_;
};

// Draws nothing itself: where it sits among its layer's layerables, the canvas is written.
class PlotSurface::TraceFlush : public QCPLayerable {
public:
    TraceFlush(QCustomPlot* plot, SpanCanvas* canvas) : QCPLayerable(plot), canvas_(canvas) {}

protected:
    void applyDefaultAntialiasingHint(QCPPainter*) const override {}
    void draw(QCPPainter*) override { canvas_->flush(); }

private:
    SpanCanvas* canvas_;
};

PlotSurface::PlotSurface(QWidget* parent) : QCustomPlot(parent), flush_(new TraceFlush(this, &canvas_)) {
    // Before every replot (QCustomPlot's setupPaintBuffers keeps the buffers it finds).
    connect(this, &QCustomPlot::beforeReplot, this, &PlotSurface::installImageBuffer);
    installImageBuffer();
}

void PlotSurface::installImageBuffer() {
    const bool opaque = mBackgroundPixmap.isNull() && mBackgroundBrush.style() == Qt::SolidPattern &&
                        mBackgroundBrush.color().alpha() == 255;
    if (mPaintBuffers.isEmpty() || mPaintBuffers.first().data() != image_) {
        image_ = new ImageBuffer(viewport().size(), bufferDevicePixelRatio());
        if (mPaintBuffers.isEmpty()) mPaintBuffers.append(QSharedPointer<QCPAbstractPaintBuffer>(image_));
        else mPaintBuffers.first() = QSharedPointer<QCPAbstractPaintBuffer>(image_);
    }
    image_->base = opaque ? mBackgroundBrush.color() : QColor();
    canvas_.begin(image_->image());
}

void PlotSurface::placeTraceFlush() {
    QCPLayer* layer = flush_->layer() ? flush_->layer() : currentLayer();
    flush_->setLayer(layer);  // moves it behind the layer's last layerable
}

void PlotSurface::paintEvent(QPaintEvent* event) {
    // Ours still (checked before image_ is read), and on an opaque background.
    if (!image_ || mPaintBuffers.isEmpty() || mPaintBuffers.first().data() != image_ || !image_->base.isValid()) {
        QCustomPlot::paintEvent(event);
        return;
    }
    // The bottom buffer already holds the background: copy it, then blend any buffered layers.
    QCPPainter painter(this);
    if (!painter.isActive()) return;
    for (const QSharedPointer<QCPAbstractPaintBuffer>& buffer : mPaintBuffers) buffer->draw(&painter);
}

}  // namespace coscope::gui
