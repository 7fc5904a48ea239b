// SPDX-License-Identifier: GPL-3.0-or-later
// The plot of a long recording draws the true envelope: one hour at 1 kHz (3.6 M samples, one
// signal) with a single-sample spike and a single-sample dip, rendered as the user sees it.
// Every pixel column of the axis rect must show the extremes a plain scan of the samples in that
// column finds (and nothing beyond its neighbours' extremes), the whole hour in view, after the
// user zooms in with the mouse wheel, and after more samples (with a new spike) arrive. The dense
// trace is painted as per-column spans (EnvelopeGraph), not as QCustomPlot's polyline.
#include "app/gui/plot/EnvelopeGraph.h"
#include "app/gui/plot/PlotView.h"

#include <QtTest>

#include <qcustomplot.h>

#include <cmath>

using namespace coscope;
using namespace coscope::gui;

namespace {
constexpr int64_t kRate = 1000;             // samples per second
constexpr int64_t kSamples = 3600 * kRate;  // one hour
constexpr int64_t kSpike = 1'234'567, kDip = 2'900'001;
constexpr int64_t kLate = kSamples + 7 * kRate + 3;  // in the ten seconds that arrive later

double valueAt(int64_t i) {
    if (i == kSpike) return 1000;
    if (i == kDip) return -900;
    if (i == kLate) return -700;
    return std::round(100.0 * std::sin(double(i) / 200000.0) + double(i * 7919 % 41) - 20);
}

bool isTrace(QRgb p, const QColor& c) {
    return std::abs(qRed(p) - c.red()) + std::abs(qGreen(p) - c.green()) + std::abs(qBlue(p) - c.blue()) < 90;
}
}  // namespace

class TestPlotEnvelope : public QObject {
    Q_OBJECT
    std::vector<double> values_;  // the plain copy a scan reads
    std::shared_ptr<SignalBuffer> buffer_;

    void append(int64_t from, int64_t to) {
        std::vector<SignalSample> batch;
        for (int64_t i = from; i < to; ++i) {
            values_.push_back(valueAt(i));
            batch.push_back({i * 1'000'000, values_.back(), static_cast<FrameNo>(i)});
            if (batch.size() == 4096 || i + 1 == to) {
                buffer_->append(batch);
                batch.clear();
            }
        }
    }

    // Compares the rendered axis rect, column by column, with a plain scan of the samples.
    // Returns the number of columns compared.
    int compareWithPlainScan(PlotView& view) {
        QCustomPlot* cp = view.customPlot();
        const QImage img = cp->toPixmap(0, 0, 1.0).toImage();
        QCPAxisRect* rect = cp->axisRect(0);
        QCPAxis* x = rect->axis(QCPAxis::atBottom);
        QCPAxis* y = rect->axis(QCPAxis::atLeft);
        const QColor color = view.plotted()[0].color;
        const QRect r = rect->rect();
        struct Column {
            double top = 0, bottom = 0;  // plain scan's extremes as pixel rows
            bool any = false;
        };
        std::vector<Column> plain(static_cast<size_t>(r.right() + 2));
        for (int px = r.left(); px <= r.right(); ++px) {
            const auto lo = static_cast<int64_t>(std::ceil(x->pixelToCoord(px) * double(kRate)));
            const auto hi = static_cast<int64_t>(std::ceil(x->pixelToCoord(px + 1) * double(kRate)));  // exclusive
            Column& c = plain[static_cast<size_t>(px)];
            for (int64_t i = std::max<int64_t>(0, lo); i < std::min<int64_t>(hi, int64_t(values_.size())); ++i) {
                const double v = values_[static_cast<size_t>(i)];
                const double py = y->coordToPixel(v);
                c.top = c.any ? std::min(c.top, py) : py;
                c.bottom = c.any ? std::max(c.bottom, py) : py;
                c.any = true;
            }
        }
        int compared = 0;
        for (int px = r.left() + 2; px <= r.right() - 2; ++px) {
            const Column& c = plain[static_cast<size_t>(px)];
            if (!c.any) continue;
            int top = -1, bottom = -1;
            // The trace may be drawn a pixel to either side of its column (joins, rounding).
            double nTop = c.top, nBottom = c.bottom;
            for (int dx = -1; dx <= 1; ++dx) {
                const Column& n = plain[static_cast<size_t>(px + dx)];
                if (n.any) {
                    nTop = std::min(nTop, n.top);
                    nBottom = std::max(nBottom, n.bottom);
                }
                for (int py = r.top(); py <= r.bottom(); ++py) {
                    if (!isTrace(img.pixel(px + dx, py), color)) continue;
                    if (dx == 0) {
                        if (top < 0) top = py;
                        bottom = py;
                    }
                }
            }
            bool seenTop = false, seenBottom = false;
            for (int dx = -1; dx <= 1 && !(seenTop && seenBottom); ++dx)
                for (int py = r.top(); py <= r.bottom(); ++py) {
                    if (!isTrace(img.pixel(px + dx, py), color)) continue;
                    seenTop = seenTop || std::abs(py - c.top) <= 2;
                    seenBottom = seenBottom || std::abs(py - c.bottom) <= 2;
                }
            const QString where = QStringLiteral("column %1 (t = %2 s): plain %3..%4, drawn %5..%6")
                                      .arg(px)
                                      .arg(x->pixelToCoord(px))
                                      .arg(c.top)
                                      .arg(c.bottom)
                                      .arg(top)
                                      .arg(bottom);
            if (!seenTop || !seenBottom || top < 0 || top < nTop - 3 || bottom > nBottom + 3) {
                QTest::qFail(qPrintable(where), __FILE__, __LINE__);
                return -1;
            }
            ++compared;
        }
        return compared;
    }

    // The hour of position samples as the view's one signal, in plot colour `color`, no legend.
    void plotPosition(PlotView& view, int color) {
        PlotSignal s;
        s.key = {0, 2, 0x6064, 0, -1};
        s.label = QStringLiteral("n2 Position actual value");
        s.color = plotColor(color);
        s.buffer = buffer_;
        view.setLegendVisible(false);
        view.setSignals({s});
        view.setOrigin(0);
    }

    EnvelopeGraph* graph(PlotView& view) { return qobject_cast<EnvelopeGraph*>(view.customPlot()->graph(0)); }

private slots:
    void initTestCase() {
        // An hour at 1 kHz sample by sample (no decimated history: the drawing is compared exactly).
        buffer_ = std::make_shared<SignalBuffer>(size_t(64) * SignalBuffer::kChunkSize);
        values_.reserve(size_t(kSamples) + 20 * kRate);
        append(0, kSamples);
    }

    void drawsTheEnvelopeOfAnHour() {
        PlotView view;
        view.resize(1000, 500);
        plotPosition(view, 0);
        view.setTimeRange(0, 3600);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.refresh(true);
        view.refresh();  // as the dock's timer does: the axis rect's width after the first layout
        QCustomPlot* cp = view.customPlot();
        QVERIFY(graph(view));
        QVERIFY2(view.drawnPoints(0).size() <= size_t(2 * cp->axisRect(0)->width() + 2),
                 qPrintable(QString::number(view.drawnPoints(0).size())));  // the pyramid's columns, not 3.6 M points

        // The whole hour: the one-sample spike and dip are drawn in their columns.
        int n = compareWithPlainScan(view);
        QVERIFY(n > 800);
        QVERIFY(!graph(view)->lastSpans().isEmpty());  // painted as per-column spans
        auto drawnAt = [&](double seconds, double value) {
            const QImage img = cp->toPixmap(0, 0, 1.0).toImage();
            QCPAxisRect* rect = cp->axisRect(0);
            const int px = int(rect->axis(QCPAxis::atBottom)->coordToPixel(seconds)),
                      py = int(rect->axis(QCPAxis::atLeft)->coordToPixel(value));
            for (int dx = -1; dx <= 1; ++dx)
                for (int dy = -2; dy <= 2; ++dy)
                    if (isTrace(img.pixel(px + dx, py + dy), view.plotted()[0].color)) return true;
            return false;
        };
        QVERIFY(drawnAt(double(kSpike) / kRate, 1000));
        QVERIFY(drawnAt(double(kDip) / kRate, -900));

        // The user zooms in on the spike with the wheel (the dock then refreshes the view).
        QCPAxisRect* rect = cp->axisRect(0);
        const QPointF at(rect->axis(QCPAxis::atBottom)->coordToPixel(double(kSpike) / kRate),
                         rect->rect().center().y());
        for (int notch = 0; notch < 3; ++notch) {
            QWheelEvent wheel(at, cp->mapToGlobal(at), QPoint(), QPoint(0, 120 * 8), Qt::NoButton, Qt::NoModifier,
                              Qt::NoScrollPhase, false);
            QApplication::sendEvent(cp, &wheel);
            view.refresh();
            const auto [from, to] = view.timeRange();
            QVERIFY2(to - from < 3600.0 * std::pow(0.85, 8.0 * (notch + 1)) * 1.01,
                     qPrintable(QStringLiteral("%1..%2").arg(from).arg(to)));
            QVERIFY(from < double(kSpike) / kRate && to > double(kSpike) / kRate);
            n = compareWithPlainScan(view);
            QVERIFY(n > 800);
            QVERIFY(drawnAt(double(kSpike) / kRate, 1000));
        }

        // Live: ten more seconds arrive with a spike of their own; the whole history in view.
        append(kSamples, kSamples + 10 * kRate);
        view.setTimeRange(0, 3610);
        QVERIFY(view.refresh());
        n = compareWithPlainScan(view);
        QVERIFY(n > 800);
        QVERIFY(drawnAt(double(kLate) / kRate, -700));
    }

    // On screen the dense trace is written straight into the plot's paint buffer; the exported
    // picture (toPixmap) fills the same spans through QPainter. Both must show the same trace
    // pixels, the whole hour in view and zoomed in.
    void screenEqualsExport() {
        PlotView view;
        view.resize(1000, 500);
        plotPosition(view, 1);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QCustomPlot* cp = view.customPlot();
        for (const auto& [from, to] : {std::pair{0.0, 3610.0}, std::pair{1200.0, 1260.0}}) {
            view.setTimeRange(from, to);
            view.refresh(true);
            QVERIFY(graph(view)->lastPaintDirect());
            QVERIFY(!graph(view)->lastSpans().isEmpty());
            const QImage screen = cp->grab().toImage();
            const QImage exported = cp->toPixmap(0, 0, 1.0).toImage();
            QVERIFY(!graph(view)->lastPaintDirect());  // the export painted through QPainter
            const QRect r = cp->axisRect(0)->rect();
            int trace = 0, differ = 0;
            for (int y = r.top(); y <= r.bottom(); ++y)
                for (int x = r.left(); x <= r.right(); ++x) {
                    const bool a = isTrace(screen.pixel(x, y), plotColor(1)),
                               b = isTrace(exported.pixel(x, y), plotColor(1));
                    trace += a;
                    differ += a != b;
                }
            QVERIFY2(
                trace > 1000 && differ == 0,
                qPrintable(
                    QStringLiteral("%1..%2 s: %3 trace pixels, %4 differ").arg(from).arg(to).arg(trace).arg(differ)));
        }
    }
};

QTEST_MAIN(TestPlotEnvelope)
#include "test_plot_envelope.moc"
