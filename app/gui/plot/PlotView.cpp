// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/PlotView.h"

#include "app/gui/plot/EnvelopeGraph.h"
#include "app/gui/plot/PlotGaps.h"
#include "app/gui/plot/PlotGrid.h"
#include "app/gui/plot/PlotLegend.h"
#include "app/gui/plot/PlotSurface.h"
#include "app/gui/plot/PlotTicks.h"
#include "app/gui/plot/WallClockTicker.h"
#include "core/od/NumberNotation.h"

#include <QVBoxLayout>

#include <qcustomplot.h>

#include <algorithm>
#include <cmath>

namespace coscope::gui {

QColor plotColor(int i) {
    static const QColor colors[] = {QColor(0x1f, 0x77, 0xb4), QColor(0xd6, 0x27, 0x28), QColor(0x2c, 0xa0, 0x2c),
                                    QColor(0xff, 0x7f, 0x0e), QColor(0x94, 0x67, 0xbd), QColor(0x8c, 0x56, 0x4b),
                                    QColor(0x17, 0xbe, 0xcf), QColor(0xe3, 0x77, 0xc2), QColor(0x7f, 0x7f, 0x7f),
                                    QColor(0xbc, 0xbd, 0x22)};
    return colors[static_cast<size_t>(std::abs(i)) % std::size(colors)];
}

namespace {
const QColor kCursorColor[2] = {QColor(0x30, 0x30, 0x30), QColor(0x94, 0x67, 0xbd)};

QString number(double v) {
    if (std::abs(v) >= 1e7 || (v != 0 && std::abs(v) < 1e-3)) return QString::number(v, 'g', 6);
    return QString::number(v, 'f', std::abs(v) >= 1000 ? 1 : 3);
}

// Value axis of a bit pattern: ticks on whole powers of two, labelled in hex ("0400h").
class HexTicker : public QCPAxisTicker {
protected:
    double getTickStep(const QCPRange& range) override {
        const double step = QCPAxisTicker::getTickStep(range);
        double p = 1;
        while (p < step && p < 0x1p62) p *= 2;
        return p;
    }
    QString getTickLabel(double tick, const QLocale&, QChar, int) override {
        return tick < 0 ? QString() : od::hexText(static_cast<uint64_t>(std::llround(tick)), 4);
    }
};
}  // namespace

QString PlotSignal::valueText(double v) const {
    if (hex && v >= 0) return od::hexText(static_cast<uint64_t>(std::llround(v)), 4);
    return number(v);
}

PlotView::PlotView(QWidget* parent)
    : QWidget(parent), plot_(new PlotSurface(this)), grid_(new PlotGrid(plot_)), ticks_(new PlotTicks(plot_)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(plot_);
    plot_->setInteractions(QCP::iRangeDrag | QCP::iRangeZoom);
    plot_->setNoAntialiasingOnDrag(true);
    plot_->setPlottingHint(QCP::phFastPolylines, true);
    // One paint buffer instead of two: the overlay layer (QCustomPlot's selection rectangle,
    // unused here) needs no own buffer to clear and blend on every replot.
    if (QCPLayer* overlay = plot_->layer(QStringLiteral("overlay"))) overlay->setMode(QCPLayer::lmLogical);
    connect(plot_, &QCustomPlot::mousePress, this, &PlotView::onPress);
    connect(plot_, &QCustomPlot::mouseRelease, this, &PlotView::onRelease);
    rebuild();
}

QCPAxis* PlotView::timeAxis() const { return rects_.empty() ? nullptr : rects_.back()->axis(QCPAxis::atBottom); }

void PlotView::setSignals(std::vector<PlotSignal> plotted) {
    signals_ = std::move(plotted);
    rebuild();
    refresh(true);
}

void PlotView::setLayoutMode(Layout layout) {
    if (layout == layout_) return;
    layout_ = layout;
    rebuild();
    refresh(true);
}

void PlotView::rebuild() {
    plot_->clearItems();
    cursorItems_.clear();
    plot_->clearGraphs();
    plot_->plotLayout()->clear();  // deletes the axis rects, their extra axes and the legend
    tracks_.assign(signals_.size(), Track{});
    rects_.clear();
    grid_->clear();
    ticks_->clear();
    auto* group = new QCPMarginGroup(plot_);
    QFont small = font();
    small.setPointSizeF(font().pointSizeF() * 0.9);

    auto newRect = [&](int row) {
        auto* rect = new QCPAxisRect(plot_);
        plot_->plotLayout()->addElement(row, 0, rect);
        rect->setMarginGroup(QCP::msLeft | QCP::msRight, group);
        rect->setRangeDrag(autoY_ ? Qt::Horizontal : Qt::Horizontal | Qt::Vertical);
        rect->setRangeZoom(autoY_ ? Qt::Horizontal : Qt::Horizontal | Qt::Vertical);
        QCPAxis* x = rect->axis(QCPAxis::atBottom);
        x->grid()->setPen(QPen(QColor(0xdd, 0xdd, 0xdd), 0, Qt::DotLine));
        rect->axis(QCPAxis::atLeft)->grid()->setPen(QPen(QColor(0xdd, 0xdd, 0xdd), 0, Qt::DotLine));
        grid_->adopt(x);  // the dotted lines written straight into the plot's image
        grid_->adopt(rect->axis(QCPAxis::atLeft));
        for (QCPAxis* a : rect->axes()) {
            a->setLabelFont(small);
            a->setTickLabelFont(small);
        }
        connect(x, qOverload<const QCPRange&>(&QCPAxis::rangeChanged), this, &PlotView::applyXRange);
        rects_.push_back(rect);
        return rect;
    };

    auto styleGraph = [&](size_t i, QCPAxisRect* rect, QCPAxis* y) {
        const PlotSignal& s = signals_[i];
        QCPGraph* g = new EnvelopeGraph(rect->axis(QCPAxis::atBottom), y);  // registers with plot_
        g->setPen(QPen(s.color, 1.0));  // wider pens go through the stroker: several times slower
        g->setName(s.scale.unit.isEmpty() || s.digital ? s.label
                                                       : QStringLiteral("%1 [%2]").arg(s.label, s.scale.unit));
        g->setLineStyle(s.digital ? QCPGraph::lsStepLeft : QCPGraph::lsLine);
        g->setAdaptiveSampling(false);  // the buffer decimates already
        tracks_[i] = Track{rect, y, g};
        if (s.hex) y->setTicker(QSharedPointer<HexTicker>::create());
        if (s.digital) {
            y->setRange(-0.2, 1.2);
            y->setTicker(QSharedPointer<QCPAxisTickerFixed>::create());
            qSharedPointerCast<QCPAxisTickerFixed>(y->ticker())->setTickStep(1.0);
        }
    };

    if (signals_.empty() || layout_ == Layout::Overlay) {
        QCPAxisRect* rect = newRect(0);
        for (size_t i = 0; i < signals_.size(); ++i) {
            QCPAxis* y = nullptr;
            if (i == 0) {
                y = rect->axis(QCPAxis::atLeft);
            } else if (i == 1) {
                y = rect->axis(QCPAxis::atRight);
                y->setVisible(true);
            } else {
                y = rect->addAxis(i % 2 ? QCPAxis::atRight : QCPAxis::atLeft);
                y->setLabelFont(small);
                y->setTickLabelFont(small);
            }
            const QColor c = signals_[i].color;
            y->setBasePen(QPen(c));
            y->setTickPen(QPen(c));
            y->setSubTickPen(QPen(c));
            y->setLabelColor(c);
            y->setTickLabelColor(c);
            y->setLabel(signals_[i].digital
                            ? signals_[i].name
                            : (signals_[i].scale.unit.isEmpty() ? signals_[i].name : signals_[i].scale.unit));
            styleGraph(i, rect, y);
        }
        if (signals_.empty()) rect->axis(QCPAxis::atLeft)->setLabel(tr("Pick signals on the left"));
    } else {
        for (size_t i = 0; i < signals_.size(); ++i) {
            QCPAxisRect* rect = newRect(static_cast<int>(i));
            QCPAxis* y = rect->axis(QCPAxis::atLeft);
            const PlotSignal& s = signals_[i];
            y->setLabel(s.digital ? QStringLiteral("bit %1").arg(s.key.bit)
                                  : (s.scale.unit.isEmpty() ? QStringLiteral("raw") : s.scale.unit));
            y->setLabelColor(s.color);
            plot_->plotLayout()->setRowStretchFactor(static_cast<int>(i), s.digital ? 0.3 : 1.0);
            styleGraph(i, rect, y);
            if (i + 1 < signals_.size()) {
                rect->axis(QCPAxis::atBottom)->setTickLabels(false);
                rect->setAutoMargins(QCP::msLeft | QCP::msRight | QCP::msTop);
                rect->setMargins(QMargins(0, 0, 0, 4));
            }
        }
    }
    applyTimeAxis();
    // Hidden axes (the top ones, an unused right one) need no ticks: QCustomPlot would still make
    // their ticks and labels on every replot.
    // The visible ones' tick marks are written into the plot's image (PlotTicks).
    for (QCPAxisRect* rect : rects_)
        for (QCPAxis* a : rect->axes())
            if (!a->visible()) {
                a->setTicks(false);
                a->setTickLabels(false);
            } else {
                ticks_->adopt(a);
            }
    ticks_->placeFirst();
    static_cast<PlotSurface*>(plot_)->placeTraceFlush();  // after the graphs, before the cursors

    // One legend in the top rect; a click on an entry hides or shows its trace.
    auto* legend = new PlotLegend;
    rects_.front()->insetLayout()->addElement(legend, Qt::AlignTop | Qt::AlignLeft);
    // Clear of the value axes: past their inward tick marks, off the top edge.
    rects_.front()->insetLayout()->setMargins(QMargins(10, 6, 10, 6));
    legend->setLayer(QStringLiteral("legend"));
    legend->setFont(small);
    legend->setBrush(QBrush(QColor(255, 255, 255, 215)));
    legend->setBorderPen(QPen(QColor(0xbb, 0xbb, 0xbb)));
    legend->setIconSize(18, 10);
    plot_->legend = legend;
    for (Track& t : tracks_) legend->addEntry(t.graph);
    legend->setVisible(legendOn_ && !signals_.empty());

    // Cursor lines, one pair per rect.
    for (QCPAxisRect* rect : rects_) {
        for (int c = 0; c < 2; ++c) {
            auto* line = new QCPItemStraightLine(plot_);
            line->setClipAxisRect(rect);
            line->point1->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
            line->point2->setAxes(rect->axis(QCPAxis::atBottom), rect->axis(QCPAxis::atLeft));
            line->setPen(QPen(kCursorColor[c], 1, c ? Qt::DashDotLine : Qt::DashLine));
            line->setVisible(false);
            cursorItems_.push_back(line);
        }
    }
    settingRange_ = true;
    for (QCPAxisRect* rect : rects_) rect->axis(QCPAxis::atBottom)->setRange(from_, to_);
    settingRange_ = false;
    drawnWidth_ = -1;
}

void PlotView::setOrigin(int64_t originNs) {
    if (originNs == originNs_) return;
    originNs_ = originNs;
    applyTimeAxis();
}

void PlotView::setTimeMode(TimeBase::Mode mode) {
    if (mode == timeMode_) return;
    timeMode_ = mode;
    applyTimeAxis();
    plot_->replot(QCustomPlot::rpQueuedReplot);
}

QString PlotView::timeAxisTitle() const {
    QCPAxis* t = timeAxis();
    return t ? t->label() : QString();
}

void PlotView::applyTimeAxis() {
    QCPAxis* t = timeAxis();
    if (!t) return;
    const bool clock = TimeBase{originNs_, timeMode_}.shown() == TimeBase::Mode::WallClock;
    if (clock) t->setTicker(QSharedPointer<WallClockTicker>::create(originNs_));
    else if (t->ticker().dynamicCast<WallClockTicker>()) t->setTicker(QSharedPointer<QCPAxisTicker>::create());
    t->setLabel(clock ? tr("Time") : tr("Time [s]"));
}

void PlotView::applyXRange(const QCPRange& r) {
    if (settingRange_) return;
    from_ = r.lower;
    to_ = r.upper;
    settingRange_ = true;
    for (QCPAxisRect* rect : rects_) rect->axis(QCPAxis::atBottom)->setRange(r);
    settingRange_ = false;
    emit userNavigated();
}

void PlotView::setTimeRange(double from, double to) {
    if (!(to > from)) to = from + 1e-3;
    from_ = from;
    to_ = to;
}

std::pair<double, double> PlotView::timeRange() const { return {from_, to_}; }

void PlotView::setAutoScaleY(bool on) {
    autoY_ = on;
    for (QCPAxisRect* rect : rects_) {
        rect->setRangeDrag(on ? Qt::Horizontal : Qt::Horizontal | Qt::Vertical);
        rect->setRangeZoom(on ? Qt::Horizontal : Qt::Horizontal | Qt::Vertical);
    }
    if (on) {
        rescaleY();
        plot_->replot();
    }
}

void PlotView::setLegendVisible(bool on) {
    legendOn_ = on;
    if (plot_->legend) plot_->legend->setVisible(on && !signals_.empty());
    plot_->replot();
}

void PlotView::rescaleY() {
    for (Track& t : tracks_) {
        t.anyVisible = false;
        for (auto it = t.graph->data()->constBegin(); it != t.graph->data()->constEnd(); ++it) {
            if (it->key < from_ || it->key > to_ || !std::isfinite(it->value)) continue;
            t.visibleMin = t.anyVisible ? std::min(t.visibleMin, it->value) : it->value;
            t.visibleMax = t.anyVisible ? std::max(t.visibleMax, it->value) : it->value;
            t.anyVisible = true;
        }
    }
    fitY();
}

void PlotView::fitY() {
    // Per y-axis: the extremes of the visible points of every graph on it.
    std::vector<std::pair<QCPAxis*, QCPRange>> ranges;
    for (size_t i = 0; i < tracks_.size(); ++i) {
        const Track& t = tracks_[i];
        if (signals_[i].digital || !t.anyVisible) continue;
        const QCPRange r(t.visibleMin, t.visibleMax);
        auto slot = std::find_if(ranges.begin(), ranges.end(), [&](const auto& p) { return p.first == t.yAxis; });
        if (slot == ranges.end()) ranges.emplace_back(t.yAxis, r);
        else slot->second.expand(r);
    }
    for (auto& [axis, r] : ranges) {
        double span = r.size();
        if (span <= 0) span = std::max(1.0, std::abs(r.center()) * 0.1);
        axis->setRange(r.lower - span * 0.08, r.upper + span * 0.08);
    }
}

bool PlotView::refresh(bool force) {
    const int width = rects_.empty() ? 800 : std::max(16, rects_.front()->width());
    bool changed = force || from_ != drawnFrom_ || to_ != drawnTo_ || width != drawnWidth_;
    for (size_t i = 0; i < tracks_.size() && !changed; ++i)
        if ((signals_[i].buffer ? signals_[i].buffer->appended() : 0) != tracks_[i].drawnAppended) changed = true;
    if (!changed) return false;
    settingRange_ = true;
    for (QCPAxisRect* rect : rects_) rect->axis(QCPAxis::atBottom)->setRange(from_, to_);
    settingRange_ = false;
    const int64_t t0 = toNs(from_), t1 = toNs(to_);
    for (size_t i = 0; i < tracks_.size(); ++i) {
        const PlotSignal& s = signals_[i];
        QVector<QCPGraphData> data;
        tracks_[i].anyVisible = false;
        if (s.buffer) {
            tracks_[i].drawnAppended = s.buffer->appended();
            // Analog traces from the buffer's edge index (cost follows the columns shown);
            // a bit's trace from the pyramid's AND/OR masks.
            if (s.digital) points_ = s.buffer->decimate(t0, t1, width, s.key.bit);
            else s.buffer->envelope(t0, t1, width, points_);
            // No line across a gap of the samples (PlotGaps.h): a NaN point between them breaks it.
            const std::vector<size_t> gaps = plotGaps(points_, (t1 - t0) / width);
            data.resize(static_cast<qsizetype>(points_.size()) + static_cast<qsizetype>(gaps.size()));
            QCPGraphData* d = data.data();
            Track& t = tracks_[i];
            auto gap = gaps.begin();
            for (size_t k = 0; k < points_.size(); ++k) {
                const SignalPoint& p = points_[k];
                *d = QCPGraphData(toSeconds(p.timeNs), s.valueOf(p.value));
                if (d->key >= from_ && d->key <= to_ && std::isfinite(d->value)) {  // what rescaleY() would find
                    t.visibleMin = t.anyVisible ? std::min(t.visibleMin, d->value) : d->value;
                    t.visibleMax = t.anyVisible ? std::max(t.visibleMax, d->value) : d->value;
                    t.anyVisible = true;
                }
                ++d;
                if (gap != gaps.end() && *gap == k) {
                    *d++ = QCPGraphData(toSeconds((p.timeNs + points_[k + 1].timeNs) / 2), qQNaN());
                    ++gap;
                }
            }
        }
        // Dense min/max columns gain nothing from antialiasing and cost most of the paint time.
        tracks_[i].graph->setAntialiased(data.size() <= width);
        tracks_[i].graph->data()->set(data, true);
    }
    if (autoY_) fitY();
    placeCursorItems();
    drawnFrom_ = from_;
    drawnTo_ = to_;
    drawnWidth_ = width;
    plot_->replot();
    return true;
}

void PlotView::placeCursorItems() {
    for (size_t k = 0; k < cursorItems_.size(); ++k) {
        QCPItemStraightLine* line = cursorItems_[k];
        const std::optional<double> t = cursors_[k % 2];
        line->setVisible(t.has_value());
        if (!t) continue;
        line->point1->setCoords(*t, 0);
        line->point2->setCoords(*t, 1);
    }
}

void PlotView::setCursor(int which, std::optional<double> seconds) {
    cursors_[which & 1] = seconds;
    placeCursorItems();
    plot_->replot();
    emit cursorsChanged();
}

std::optional<double> PlotView::valueAt(size_t i, double seconds) const {
    if (i >= signals_.size() || !signals_[i].buffer) return std::nullopt;
    const auto s = signals_[i].buffer->at(toNs(seconds));
    if (!s) return std::nullopt;
    const PlotSignal& p = signals_[i];
    if (p.digital) return double((static_cast<int64_t>(s->value) >> p.key.bit) & 1);
    return p.scale.apply(s->value);
}

std::vector<std::pair<double, double>> PlotView::drawnPoints(size_t i) const {
    std::vector<std::pair<double, double>> out;
    if (i >= tracks_.size()) return out;
    for (auto it = tracks_[i].graph->data()->constBegin(); it != tracks_[i].graph->data()->constEnd(); ++it)
        out.emplace_back(it->key, it->value);
    return out;
}

QString PlotView::axisTitle(size_t i) const {
    if (i >= tracks_.size()) return {};
    return tracks_[i].yAxis->label();
}

bool PlotView::graphVisible(size_t i) const { return i < tracks_.size() && tracks_[i].graph->visible(); }

void PlotView::setGraphVisible(size_t i, bool on) {
    if (i >= tracks_.size()) return;
    tracks_[i].graph->setVisible(on);
    if (QCPPlottableLegendItem* item = plot_->legend ? plot_->legend->itemWithPlottable(tracks_[i].graph) : nullptr)
        item->setTextColor(on ? Qt::black : QColor(0xaa, 0xaa, 0xaa));
    plot_->replot();
    emit legendToggled();
}

bool PlotView::savePng(const QString& path, int width, int height) { return plot_->savePng(path, width, height); }
bool PlotView::savePdf(const QString& path, int width, int height) { return plot_->savePdf(path, width, height); }

void PlotView::onPress(QMouseEvent* e) {
    pressPos_ = e->pos();
    pressed_ = e->button() == Qt::LeftButton;
}

void PlotView::onRelease(QMouseEvent* e) {
    if (!pressed_ || e->button() != Qt::LeftButton) return;
    pressed_ = false;
    if ((e->pos() - pressPos_).manhattanLength() > 3) return;  // a drag, not a click
    const QPointF pos = e->pos();
    if (plot_->legend && plot_->legend->visible()) {
        for (int k = 0; k < plot_->legend->itemCount(); ++k) {
            auto* item = qobject_cast<QCPPlottableLegendItem*>(plot_->legend->item(k));
            if (!item || item->selectTest(pos, false) < 0) continue;
            for (size_t i = 0; i < tracks_.size(); ++i)
                if (tracks_[i].graph == item->plottable()) setGraphVisible(i, !tracks_[i].graph->visible());
            return;
        }
    }
    QCPAxisRect* rect = plot_->axisRectAt(pos);
    if (!rect) return;
    const double t = rect->axis(QCPAxis::atBottom)->pixelToCoord(pos.x());
    setCursor((e->modifiers() & Qt::ShiftModifier) ? 1 : 0, t);
    // The frame of the nearest sample of the traces in this rect.
    std::optional<SignalSample> best;
    for (size_t i = 0; i < tracks_.size(); ++i) {
        if (tracks_[i].rect != rect || !signals_[i].buffer || !tracks_[i].graph->visible()) continue;
        const auto s = signals_[i].buffer->nearest(toNs(t));
        if (s && (!best || std::llabs(s->timeNs - toNs(t)) < std::llabs(best->timeNs - toNs(t)))) best = s;
    }
    if (best) emit frameClicked(best->frame);
}

QString PlotView::readoutHtml() const {
    if (!cursors_[0] && !cursors_[1])
        return tr("Click the plot to place cursor A (jumps to the frame), Shift+click for cursor B.");
    QString html = QStringLiteral("<table cellspacing=0 cellpadding=2><tr><th align=left></th>");
    for (int c = 0; c < 2; ++c)
        html += cursors_[c]
                    ? QStringLiteral("<th align=right>%1 = %2 s</th>").arg(c ? u'B' : u'A').arg(number(*cursors_[c]))
                    : QStringLiteral("<th></th>");
    html += cursors_[0] && cursors_[1]
                ? QStringLiteral("<th align=right>&Delta;t = %1 s</th></tr>").arg(number(*cursors_[1] - *cursors_[0]))
                : QStringLiteral("<th></th></tr>");
    for (size_t i = 0; i < signals_.size(); ++i) {
        const PlotSignal& s = signals_[i];
        html += QStringLiteral("<tr><td><font color=%1>&#9632;</font> %2</td>")
                    .arg(s.color.name(), s.titleWithUnit().toHtmlEscaped());
        std::optional<double> v[2];
        for (int c = 0; c < 2; ++c) {
            if (cursors_[c]) v[c] = valueAt(i, *cursors_[c]);
            html += QStringLiteral("<td align=right>%1</td>").arg(v[c] ? s.valueText(*v[c]) : QString());
        }
        // A difference of two bit patterns means nothing: none for hex.
        html += QStringLiteral("<td align=right>%1</td></tr>")
                    .arg(v[0] && v[1] && !s.hex ? QStringLiteral("&Delta; %1").arg(number(*v[1] - *v[0])) : QString());
    }
    return html + QStringLiteral("</table>");
}

}  // namespace coscope::gui
