// SPDX-License-Identifier: GPL-3.0-or-later
// SpanCanvas writes the dense traces of a replot in one pass, choosing per group of 16 columns
// between writing each trace's spans column by column (thin spans) and a row sweep (tall,
// overlaid spans). Either way the image must be pixel for pixel what painting the traces one
// after the other gives (a later trace covers an earlier one), including groups cut by the
// image's edge and by the clip rect, and traces with gaps. Where the CPU has AVX-512 the canvas
// writes with masked stores; each case runs both ways there.
#include "app/gui/plot/SpanCanvas.h"

#include <QtTest>

#include <cstdint>
#include <random>

using namespace coscope::gui;

namespace {
struct TraceSpec {
    uint32_t px;
    QVector<QRect> spans;
};

// Spans one a column (x ascending) around a wandering centre; `height` their typical size.
QVector<QRect> makeSpans(std::mt19937& rng, int from, int to, int rows, int height, bool gaps) {
    QVector<QRect> spans;
    std::uniform_int_distribution<int> step(-3, 3), size(0, height), gap(0, 9);
    int centre = rows / 2;
    for (int x = from; x < to; ++x) {
        centre = std::clamp(centre + step(rng), 0, rows - 1);
        if (gaps && gap(rng) == 0) continue;
        const int h = size(rng), top = centre - h / 2;
        spans.append(QRect(x, top, 1, h + 1));
    }
    return spans;
}

// What painting the traces one after the other writes.
void reference(QImage& image, const std::vector<TraceSpec>& traces, int dx, int dy, const QRect& clip) {
    const QRect c = clip & image.rect();
    for (const TraceSpec& t : traces)
        for (const QRect& s : t.spans)
            for (int y = s.top() + dy; y <= s.bottom() + dy; ++y) {
                const int x = s.x() + dx;
                if (c.contains(x, y)) reinterpret_cast<uint32_t*>(image.scanLine(y))[x] = t.px;
            }
}
}  // namespace

class TestPlotSpanCanvas : public QObject {
    Q_OBJECT
private slots:
    void equalsTracesPaintedInTurn_data() {
        QTest::addColumn<int>("height");
        QTest::addColumn<bool>("gaps");
        QTest::addColumn<bool>("masked");
        for (const bool masked : {false, true}) {
            if (masked && !SpanCanvas::maskedStoresSupported()) {
                qInfo("this CPU has no AVX-512: the masked-store cases are not run");
                break;
            }
            const char* how = masked ? ", AVX-512 masked stores" : ", portable loops";
            QTest::newRow(qPrintable(QStringLiteral("one-pixel spans (a steep thin line)") + how))
                << 0 << false << masked;
            QTest::newRow(qPrintable(QStringLiteral("thin spans (column by column)") + how)) << 6 << false << masked;
            QTest::newRow(qPrintable(QStringLiteral("tall overlaid spans (row sweep)") + how))
                << 400 << false << masked;
            QTest::newRow(qPrintable(QStringLiteral("mixed, with gaps") + how)) << 60 << true << masked;
        }
    }

    void equalsTracesPaintedInTurn() {
        QFETCH(int, height);
        QFETCH(bool, gaps);
        QFETCH(bool, masked);
        std::mt19937 rng(uint32_t(height) * 7919u + (gaps ? 1u : 0u));
        const int width = 403, rows = 300;  // not a whole number of 16-column groups
        QImage expected(width, rows, QImage::Format_ARGB32_Premultiplied);
        expected.fill(QColor(0xfa, 0xfa, 0xfa));
        QImage actual = expected.copy();
        // Spans in painter coordinates, moved by (dx, dy), some beyond the image on either side,
        // clipped to an axis rect.
        const int dx = -5, dy = 3;
        const QRect clip(0, 10, width - 7, rows - 30);
        std::vector<TraceSpec> traces;
        for (int k = 0; k < 9; ++k) {  // more than 8: past the canvas's 16 inline lanes too
            const int from = k == 3 ? 300 : 0, to = k == 5 ? 100 : width + 20;
            traces.push_back({qPremultiply(QColor::fromHsv(k * 40, 200, 200).rgba()),
                              makeSpans(rng, from, to, rows, k % 2 ? height : height / 3 + 1, gaps)});
        }
        traces.push_back({qPremultiply(QColor(0x10, 0x20, 0x30).rgba()), {}});  // an empty trace
        reference(expected, traces, dx, dy, clip);

        SpanCanvas canvas;
        canvas.setMaskedStores(masked);
        canvas.begin(&actual);
        for (const TraceSpec& t : traces) QVERIFY(canvas.add(&actual, t.px, t.spans, dx, dy, clip));
        canvas.flush();
        for (int y = 0; y < rows; ++y)
            for (int x = 0; x < width; ++x)
                if (actual.pixel(x, y) != expected.pixel(x, y))
                    QFAIL(qPrintable(QStringLiteral("pixel (%1, %2): %3, painted in turn %4")
                                         .arg(x)
                                         .arg(y)
                                         .arg(actual.pixel(x, y), 8, 16)
                                         .arg(expected.pixel(x, y), 8, 16)));
    }
};

QTEST_MAIN(TestPlotSpanCanvas)
#include "test_plot_span_canvas.moc"
