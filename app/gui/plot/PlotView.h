// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/plot/PlotSignal.h"
#include "core/trace/TimeBase.h"

#include <QWidget>

#include <optional>
#include <vector>

class QCustomPlot;
class QCPAxis;
class QCPAxisRect;
class QCPGraph;
class QCPItemStraightLine;
class QCPRange;
class QLabel;

namespace coscope::gui {

class PlotGrid;
class PlotTicks;

// The plotting surface (QCustomPlot): the picked signals either stacked, one axis rect each,
// sharing the time axis, or overlaid in one rect with an own y-axis per signal. Time is in
// seconds from the trace's first frame. On refresh() it pulls min/max-decimated points for the
// visible time range from each signal's buffer (as many buckets as the plot is wide), so the
// cost of a redraw follows pixels, not samples. Two cursors (A: click, B: shift+click) read
// the values and differences; a click reports the frame of the nearest sample.
class PlotView : public QWidget {
    Q_OBJECT
public:
    enum class Layout { Stacked, Overlay };

    explicit PlotView(QWidget* parent = nullptr);

    void setSignals(std::vector<PlotSignal> plotted);
    const std::vector<PlotSignal>& plotted() const { return signals_; }
    void setLayoutMode(Layout layout);
    Layout layoutMode() const { return layout_; }
    void setOrigin(int64_t originNs);
    // The time axis in seconds from the origin, or labelled with the wall clock (one time base).
    void setTimeMode(TimeBase::Mode mode);
    QString timeAxisTitle() const;
    int64_t origin() const { return originNs_; }

    // The visible time range, seconds from the origin.
    void setTimeRange(double from, double to);
    std::pair<double, double> timeRange() const;
    int64_t toNs(double seconds) const { return originNs_ + static_cast<int64_t>(seconds * 1e9); }
    double toSeconds(int64_t ns) const { return double(ns - originNs_) / 1e9; }

    void setAutoScaleY(bool on);
    bool autoScaleY() const { return autoY_; }
    void rescaleY();  // fits every y-axis to the visible data once
    void setLegendVisible(bool on);
    bool legendVisible() const { return legendOn_; }

    // Re-decimates when data, range or size changed (or `force`) and replots. Returns whether
    // it redrew.
    bool refresh(bool force = false);

    // Cursors at times in seconds (nullopt = hidden).
    void setCursor(int which, std::optional<double> seconds);
    std::optional<double> cursor(int which) const { return cursors_[which & 1]; }
    // The value of signal i at time t (the last sample at or before it), scaled.
    std::optional<double> valueAt(size_t i, double seconds) const;

    // Points drawn for signal i (seconds, scaled value), for tests and export checks.
    std::vector<std::pair<double, double>> drawnPoints(size_t i) const;
    QString axisTitle(size_t i) const;
    bool graphVisible(size_t i) const;
    void setGraphVisible(size_t i, bool on);

    bool savePng(const QString& path, int width = 0, int height = 0);
    bool savePdf(const QString& path, int width = 0, int height = 0);
    QCustomPlot* customPlot() const { return plot_; }
    QString readoutHtml() const;

signals:
    void userNavigated();               // the user dragged or zoomed the time axis
    void frameClicked(uint32_t frame);  // a click near a sample
    void cursorsChanged();
    void legendToggled();

private:
    struct Track {
        QCPAxisRect* rect = nullptr;
        QCPAxis* yAxis = nullptr;
        QCPGraph* graph = nullptr;
        uint64_t drawnAppended = ~uint64_t(0);
        double visibleMin = 0, visibleMax = 0;  // extremes of the drawn points in the time range
        bool anyVisible = false;
    };
    void fitY();  // each y-axis to its tracks' visible extremes
    void rebuild();
    void applyXRange(const QCPRange& r);
    void onPress(QMouseEvent* e);
    void onRelease(QMouseEvent* e);
    void placeCursorItems();
    QCPAxis* timeAxis() const;
    void applyTimeAxis();  // its ticker and title for the time mode

    QCustomPlot* plot_;
    PlotGrid* grid_;  // layerables of plot_ (owned by it)
    PlotTicks* ticks_;
    std::vector<PlotSignal> signals_;
    std::vector<Track> tracks_;
    std::vector<SignalPoint> points_;  // one trace's columns, reused by every refresh
    std::vector<QCPAxisRect*> rects_;
    std::vector<QCPItemStraightLine*> cursorItems_;
    Layout layout_ = Layout::Stacked;
    int64_t originNs_ = 0;
    TimeBase::Mode timeMode_ = TimeBase::Mode::Relative;
    double from_ = 0, to_ = 10;
    bool autoY_ = true;
    bool legendOn_ = true;
    bool settingRange_ = false;
    std::optional<double> cursors_[2];
    double drawnFrom_ = -1, drawnTo_ = -1;
    int drawnWidth_ = -1;
    QPoint pressPos_;
    bool pressed_ = false;
};

}  // namespace coscope::gui
