// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <qcustomplot.h>

#include <QImage>
#include <QString>

#include <vector>

namespace coscope::gui {

class PlotLegendEntry;

// What one legend entry shows (PlotLegendEntry::look); compared, not hashed, on every draw.
struct PlotLegendEntryLook {
    QRect rect, outer;
    QFont font;
    QColor text;
    QPen iconBorder;
    QSize icon;
    int padding = 0;
    QString name;
    QPen pen;
    QBrush brush;
    int lineStyle = -1, scatterShape = -1;
    double scatterSize = 0;
    QPen scatterPen;
    QBrush scatterBrush;
    bool visible = false;
    bool operator==(const PlotLegendEntryLook& o) const = default;
};

// The plot's legend (a QCPLegend): on screen it is drawn from a picture of the box and its
// entries, rendered by QCPLegend and QCPPlottableLegendItem themselves and drawn anew only when
// what it shows changes (entry texts, fonts, text colours, trace pens, icon size, the box's brush
// and pen, its place and size, the viewport). QCustomPlot would lay out and shape every entry's text on every
// replot. Exports (PDF, scaled pictures) draw the legend directly, as QCustomPlot does.
class PlotLegend : public QCPLegend {
public:
    // A legend entry for `plottable` (instead of plottable->addToLegend(this)).
    void addEntry(QCPAbstractPlottable* plottable);
    // How often the picture was rendered (for tests).
    int pictureRenders() const { return renders_; }
    // Whether the last draw used the picture (then the entries draw nothing themselves).
    bool drewPicture() const { return pictured_; }

protected:
    void draw(QCPPainter* painter) override;

private:
    // Everything the picture depends on; compared on every draw.
    struct Look {
        QRect outer, clip;  // the box, and the plot's viewport it is clipped to
        qreal pixelRatio = 1;
        QBrush brush;
        QPen border;
        std::vector<PlotLegendEntryLook> entries;
        bool foreign = false;  // an item that is not a PlotLegendEntry: never pictured
        bool operator==(const Look& o) const = default;
    };
    Look currentLook(qreal pixelRatio) const;
    void render(const Look& look, const QCPPainter& like);

    QImage picture_;
    QPoint pictureAt_;
    Look look_;
    int renders_ = 0;
    bool pictured_ = false;
};

// One entry: its size is measured once per text, font and icon size (QCPPlottableLegendItem
// measures its text on every layout pass), and it draws nothing when the legend drew its picture.
class PlotLegendEntry : public QCPPlottableLegendItem {
public:
    PlotLegendEntry(QCPLegend* legend, QCPAbstractPlottable* plottable) : QCPPlottableLegendItem(legend, plottable) {}

    QSize minimumOuterSizeHint() const override;
    // What the entry shows (text, font, colours, pens, rects).
    PlotLegendEntryLook look() const;
    QRect layerClip() const { return clipRect(); }
    // QCPPlottableLegendItem's own drawing (with its antialiasing), for the legend's picture.
    void drawEntry(QCPPainter* painter) {
        applyDefaultAntialiasingHint(painter);
        QCPPlottableLegendItem::draw(painter);
    }

protected:
    void draw(QCPPainter* painter) override;

private:
    mutable QString sizedText_;
    mutable QFont sizedFont_;
    mutable QSize sizedIcon_;
    mutable int sizedPadding_ = -1;
    mutable QMargins sizedMargins_;
    mutable QSize size_;
};

}  // namespace coscope::gui
