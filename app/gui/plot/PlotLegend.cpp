// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/PlotLegend.h"

#include <algorithm>
#include <cmath>

namespace coscope::gui {

void PlotLegend::addEntry(QCPAbstractPlottable* plottable) {
    if (!plottable || hasItemWithPlottable(plottable)) return;
    auto* entry = new PlotLegendEntry(this, plottable);
    // An entry is as high as its font and layers draw clipped one pixel up (QCPLayer::draw):
    // without room below, the font's lowest row goes, and "Pos_Cmd" reads "Pos Cmd".
    entry->setMargins(QMargins(0, 0, 0, 2));
    addItem(entry);
}

PlotLegend::Look PlotLegend::currentLook(qreal pixelRatio) const {
    Look look{mOuterRect, clipRect(), pixelRatio, getBrush(), getBorderPen(), {}, false};
    look.entries.reserve(size_t(itemCount()));
    for (int i = 0; i < itemCount(); ++i) {
        if (auto* entry = dynamic_cast<const PlotLegendEntry*>(item(i))) look.entries.push_back(entry->look());
        else look.foreign = true;
    }
    return look;
}

void PlotLegend::draw(QCPPainter* painter) {
    // The picture only where drawing it is what painting would give: a raster device, no
    // scaling or rotation, whole pixels (QCustomPlot's own exports ask for no caching).
    painter->save();
    painter->setAntialiasing(false);  // QCPPainter drops its half-pixel shift
    const QTransform t = painter->transform();
    const bool plain = !painter->modes().testFlag(QCPPainter::pmVectorized) &&
                       !painter->modes().testFlag(QCPPainter::pmNoCaching) && painter->device() &&
                       t.type() <= QTransform::TxTranslate && t.dx() == std::round(t.dx()) &&
                       t.dy() == std::round(t.dy());
    Look look;
    if (plain) look = currentLook(painter->device()->devicePixelRatioF());
    pictured_ = plain && !look.foreign;
    if (pictured_) {
        if (picture_.isNull() || !(look == look_)) render(look, *painter);
        painter->drawImage(pictureAt_, picture_);
    }
    painter->restore();
    if (!pictured_) QCPLegend::draw(painter);
}

void PlotLegend::render(const Look& look, const QCPPainter& like) {
    // A couple of pixels around the box: pens may reach past it.
    const QRect area = mOuterRect.adjusted(-2, -2, 2, 2);
    picture_ = QImage((QSizeF(area.size()) * look.pixelRatio).toSize(), QImage::Format_ARGB32_Premultiplied);
    picture_.setDevicePixelRatio(look.pixelRatio);
    picture_.fill(Qt::transparent);
    pictureAt_ = area.topLeft();
    {
        QCPPainter p(&picture_);
        p.setModes(like.modes());
        p.translate(-area.topLeft());
        // What QCPLayer::draw does for each layerable: its clip (one pixel up, as there), its
        // antialiasing, its drawing. Source-over is associative: the picture blended onto the
        // plot gives what the box and entries drawn onto it one by one give.
        auto drawLayerable = [&p](const QRect& clip, auto&& draw) {
            p.save();
            p.setClipRect(clip.translated(0, -1));
            draw();
            p.restore();
        };
        drawLayerable(clipRect(), [&] {
            applyDefaultAntialiasingHint(&p);
            QCPLegend::draw(&p);
        });
        for (int i = 0; i < itemCount(); ++i) {
            auto* entry = dynamic_cast<PlotLegendEntry*>(item(i));
            if (!entry || !entry->realVisibility()) continue;
            drawLayerable(entry->layerClip(), [&] { entry->drawEntry(&p); });
        }
    }
    look_ = look;
    ++renders_;
}

QSize PlotLegendEntry::minimumOuterSizeHint() const {
    if (!mPlottable) return QSize();
    const QString text = mPlottable->name();
    const QFont font = getFont();
    if (sizedPadding_ < 0 || text != sizedText_ || font != sizedFont_ || mParentLegend->iconSize() != sizedIcon_ ||
        mParentLegend->iconTextPadding() != sizedPadding_ || mMargins != sizedMargins_) {
        sizedText_ = text;
        sizedFont_ = font;
        sizedIcon_ = mParentLegend->iconSize();
        sizedPadding_ = mParentLegend->iconTextPadding();
        sizedMargins_ = mMargins;
        size_ = QCPPlottableLegendItem::minimumOuterSizeHint();
    }
    return size_;
}

PlotLegendEntryLook PlotLegendEntry::look() const {
    PlotLegendEntryLook l;
    l.visible = realVisibility();
    if (!l.visible) return l;
    l.rect = mRect;
    l.outer = mOuterRect;
    l.font = getFont();
    l.text = getTextColor();
    l.iconBorder = getIconBorderPen();
    l.icon = mParentLegend->iconSize();
    l.padding = mParentLegend->iconTextPadding();
    if (mPlottable) {
        l.name = mPlottable->name();
        l.pen = mPlottable->pen();
        l.brush = mPlottable->brush();
        if (auto* graph = qobject_cast<const QCPGraph*>(mPlottable)) {
            const QCPScatterStyle& s = graph->scatterStyle();
            l.lineStyle = int(graph->lineStyle());
            l.scatterShape = int(s.shape());
            l.scatterSize = s.size();
            l.scatterPen = s.pen();
            l.scatterBrush = s.brush();
        }
    }
    return l;
}

void PlotLegendEntry::draw(QCPPainter* painter) {
    auto* legend = dynamic_cast<PlotLegend*>(mParentLegend);
    if (legend && legend->drewPicture()) return;
    QCPPlottableLegendItem::draw(painter);
}

}  // namespace coscope::gui
