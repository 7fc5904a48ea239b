// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QImage>
#include <QRect>
#include <QVector>

#include <cstdint>
#include <vector>

namespace coscope::gui {

// The dense traces of one replot, written into the plot's image in one pass. Each EnvelopeGraph
// hands over its per-column spans (add) instead of writing them; when the last graph is done
// (flush, from PlotSurface's marker placed after the graphs) the image is written in groups of
// 16 columns (one cache line of a row), row by row, every trace of the group in the order they
// were added. Pixel for pixel the same as writing the traces one after the other (a later trace
// covers an earlier one), but each cache line of the image is read and written once instead of
// once per trace: 8 overlaid traces of a long recording each cover most of the plot.
class SpanCanvas {
public:
    // A replot begins on `image` (nullptr: none to defer to); anything not flushed is dropped.
    void begin(QImage* image);
    // Spans (one a column, x ascending; painter coordinates, moved by dx, dy into the image),
    // clipped to `clip` (image coordinates), in premultiplied colour px. False: not deferred
    // (another image, or not one span a column): the caller writes them itself.
    bool add(const QImage* image, uint32_t px, const QVector<QRect>& spans, int dx, int dy, const QRect& clip);
    // Writes every trace added since begin() and forgets them.
    void flush();

    // AVX-512 masked stores write 16 pixels of a row at once where the CPU has them (the
    // default there); off, the portable loops write the same pixels (the tests compare both).
    static bool maskedStoresSupported();
    void setMaskedStores(bool on);

    struct Lanes;  // one trace's spans within a group of 16 columns (SpanCanvas.cpp)

private:
    struct Span {
        int x, top, bottom;  // image coordinates, clipped
    };
    struct Trace {
        uint32_t px = 0;
        std::vector<Span> spans;
    };
    void writeGroup(int x0, size_t first, size_t last, std::vector<size_t>& cursor);

    QImage* image_ = nullptr;
    bool masked_ = maskedStoresSupported();
    std::vector<Trace> traces_;  // [0, used_) pending; the rest kept for their memory
    size_t used_ = 0;
};

}  // namespace coscope::gui
