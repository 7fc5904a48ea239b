// SPDX-License-Identifier: GPL-3.0-or-later
// The plot's frame drawn its own way on screen: the legend from a picture rendered anew only
// when what it shows changes (PlotLegend), the dotted grid written into the image (PlotGrid).
// The exported picture (toPixmap: QCustomPlot asks for no caching) draws both with QPainter as
// QCustomPlot would; the screen must show the same pixels, before and after a click on a legend
// entry greys it out and hides its trace.
#include "app/gui/plot/PlotLegend.h"
#include "app/gui/plot/PlotView.h"
#include "core/trace/SignalBuffer.h"

#include <QtTest>

#include <qcustomplot.h>

#include <cmath>
#include <cstdlib>
#include <memory>

using namespace coscope;
using namespace coscope::gui;

namespace {
// Pixels of `r` in which a and b differ by more than a little (text edges may round apart).
int differing(const QImage& a, const QImage& b, const QRect& r, const QRect& skip = {}) {
    int n = 0;
    for (int y = r.top(); y <= r.bottom(); ++y)
        for (int x = r.left(); x <= r.right(); ++x) {
            if (skip.contains(x, y)) continue;
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            if (std::abs(qRed(p) - qRed(q)) > 24 || std::abs(qGreen(p) - qGreen(q)) > 24 ||
                std::abs(qBlue(p) - qBlue(q)) > 24)
                ++n;
        }
    return n;
}
}  // namespace

class TestPlotFrame : public QObject {
    Q_OBJECT

    std::vector<PlotSignal> signals_() {
        std::vector<PlotSignal> out;
        for (int s = 0; s < 3; ++s) {
            auto b = std::make_shared<SignalBuffer>();
            std::vector<SignalSample> batch;
            for (int64_t i = 0; i < 2000; ++i)
                batch.push_back({i * 5'000'000, 100.0 * std::sin(double(i) / (40.0 + 30 * s)) + 20 * s, FrameNo(i)});
            b->append(batch);
            PlotSignal p;
            p.key = {0, uint8_t(s + 1), 0x6064, 0, -1};
            p.label = QStringLiteral("n%1 Position actual value").arg(s + 1);
            p.color = plotColor(s);
            p.buffer = b;
            out.push_back(p);
        }
        return out;
    }

    // The screen (the plot's own image) against the export, in the legend and in every axis rect.
    void compareWithExport(PlotView& view, const char* when) {
        QCustomPlot* cp = view.customPlot();
        auto* legend = dynamic_cast<PlotLegend*>(cp->legend);
        QVERIFY(legend);
        QVERIFY2(legend->drewPicture(), when);  // the replot drew the picture, not the entries
        const QImage screen = cp->grab().toImage();
        const QImage exported = cp->toPixmap(0, 0, 1.0).toImage();
        QVERIFY(!legend->drewPicture());  // the export drew the legend itself
        const QRect box = legend->outerRect();
        QVERIFY(box.width() > 50 && box.height() > 30);
        const int inLegend = differing(screen, exported, box.adjusted(-1, -1, 1, 1));
        QVERIFY2(inLegend == 0,
                 qPrintable(QStringLiteral("%1: %2 legend pixels differ").arg(QLatin1String(when)).arg(inLegend)));
        for (int r = 0; r < cp->axisRectCount(); ++r) {
            const int inRect = differing(screen, exported, cp->axisRect(r)->rect(), box.adjusted(-1, -1, 1, 1));
            QVERIFY2(
                inRect == 0,
                qPrintable(
                    QStringLiteral("%1: %2 pixels of rect %3 differ").arg(QLatin1String(when)).arg(inRect).arg(r)));
        }
        // The dotted grid is there: pixels of the grid's colour in the first rect.
        int dots = 0;
        const QRect area = cp->axisRect(0)->rect();
        for (int y = area.top(); y <= area.bottom(); ++y)
            for (int x = area.left(); x <= area.right(); ++x) dots += screen.pixel(x, y) == qRgb(0xdd, 0xdd, 0xdd);
        QVERIFY2(dots > 100, qPrintable(QString::number(dots)));
    }

private slots:
    void legendPictureFollowsTheLegend() {
        for (PlotView::Layout layout : {PlotView::Layout::Stacked, PlotView::Layout::Overlay}) {
            PlotView view;
            view.resize(900, 600);
            view.setLayoutMode(layout);
            view.setSignals(signals_());
            view.setOrigin(0);
            view.setTimeRange(0, 10);
            view.show();
            QVERIFY(QTest::qWaitForWindowExposed(&view));
            view.refresh(true);
            QCustomPlot* cp = view.customPlot();
            auto* legend = dynamic_cast<PlotLegend*>(cp->legend);
            QVERIFY(legend && legend->itemCount() == 3);
            compareWithExport(view, "shown");

            // Scrolling replots the plot, not the legend's picture.
            const int renders = legend->pictureRenders();
            for (int k = 1; k <= 5; ++k) {
                view.setTimeRange(0.1 * k, 9 + 0.1 * k);
                QVERIFY(view.refresh());
            }
            QCOMPARE(legend->pictureRenders(), renders);
            compareWithExport(view, "scrolled");

            // A click on the first entry hides its trace and greys the entry: the picture changes.
            const QImage before = cp->grab().toImage();
            QTest::mouseClick(cp, Qt::LeftButton, Qt::NoModifier, legend->item(0)->rect().center());
            QVERIFY(!view.graphVisible(0));
            QVERIFY(legend->pictureRenders() > renders);
            QVERIFY(differing(before, cp->grab().toImage(), legend->item(0)->rect()) > 10);
            compareWithExport(view, "entry hidden");
            QTest::mouseClick(cp, Qt::LeftButton, Qt::NoModifier, legend->item(0)->rect().center());
            QVERIFY(view.graphVisible(0));
            compareWithExport(view, "entry shown again");
            QCOMPARE(differing(before, cp->grab().toImage(), legend->outerRect()), 0);
        }
    }
};

QTEST_MAIN(TestPlotFrame)
#include "test_plot_frame.moc"
