// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/PlotSurface.h"

#include <QPaintEvent>

namespace coscope::gui {

// The bottom paint buffer as a QImage (ARGB32 premultiplied: other buffers and exports blend
// the same way). `base` is the opaque colour it starts from instead of transparent, when the
// plot's background is one opaque colour; then it is drawn as a copy.
class PlotSurface::ImageBuffer : public QCPAbstractPaintBuffer {
public:
    ImageBuffer(const QSize& size, double devicePixelRatio) : QCPAbstractPaintBuffer(size, devicePixelRatio) { ImageBuffer::reallocateBuffer(); }

    QColor base;  // invalid: transparent like QCustomPlot's own buffers

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
        image_ = QImage(mSize * mDevicePixelRatio, QImage::Format_ARGB32_Premultiplied);
        image_.setDevicePixelRatio(mDevicePixelRatio);
        image_.fill(base.isValid() ? base : QColor(Qt::transparent));
    }

private:
    QImage image_;
};

PlotSurface::PlotSurface(QWidget* parent) : QCustomPlot(parent) {
    // Before every replot (QCustomPlot's setupPaintBuffers keeps the buffers it finds).
    connect(this, &QCustomPlot::beforeReplot, this, &PlotSurface::installImageBuffer);
    installImageBuffer();
}

void PlotSurface::installImageBuffer() {
    const bool opaque = mBackgroundPixmap.isNull() && mBackgroundBrush.style() == Qt::SolidPattern && mBackgroundBrush.color().alpha() == 255;
    if (mPaintBuffers.isEmpty() || mPaintBuffers.first().data() != image_) {
        image_ = new ImageBuffer(viewport().size(), bufferDevicePixelRatio());
        if (mPaintBuffers.isEmpty()) mPaintBuffers.append(QSharedPointer<QCPAbstractPaintBuffer>(image_));
        else mPaintBuffers.first() = QSharedPointer<QCPAbstractPaintBuffer>(image_);
    }
    image_->base = opaque ? mBackgroundBrush.color() : QColor();
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
