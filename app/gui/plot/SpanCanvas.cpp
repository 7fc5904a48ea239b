// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/SpanCanvas.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <utility>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#endif

namespace coscope::gui {

namespace {
constexpr int kGroup = 16;  // columns of a group: 64 bytes of a row
using V4 = int32_t __attribute__((vector_size(16)));
}  // namespace

// Per trace of a group: its lanes' rows (none: top > bottom), the rows it covers, its colour.
struct SpanCanvas::Lanes {
    V4 top[4], bottom[4];
    int from, to;
    int pixels;  // what its spans cover
    V4 color;
};

namespace {
// One trace's spans of a group written column by column, one store a pixel, down each column
// four rows a turn (the loop's own instructions were most of the cost).
void writeColumns(uchar* bits, qsizetype stride, int x0, const SpanCanvas::Lanes& a) {
    alignas(16) int32_t top[kGroup], bottom[kGroup];
    std::memcpy(top, a.top, sizeof top);
    std::memcpy(bottom, a.bottom, sizeof bottom);
    const uint32_t color = uint32_t(a.color[0]);
    for (int q = 0; q < kGroup; ++q) {
        if (top[q] > bottom[q]) continue;
        uchar* p = bits + qsizetype(top[q]) * stride + qsizetype(x0 + q) * 4;
        int rows = bottom[q] - top[q] + 1;
        for (; rows >= 4; rows -= 4, p += 4 * stride) {
            *reinterpret_cast<uint32_t*>(p) = color;
            *reinterpret_cast<uint32_t*>(p + stride) = color;
            *reinterpret_cast<uint32_t*>(p + 2 * stride) = color;
            *reinterpret_cast<uint32_t*>(p + 3 * stride) = color;
        }
        for (; rows > 0; --rows, p += stride) *reinterpret_cast<uint32_t*>(p) = color;
    }
}
}  // namespace

#if defined(__x86_64__) && defined(__GNUC__)
#define COSCOPE_SPAN_MASKED 1
namespace {
// AVX-512, where the CPU has it (checked at run time; the build targets plain x86-64): a lane
// mask from two compares and one masked store write a trace's 16 pixels of a row at once.
// Measured on the 8 x 1 kHz replots (bench_plot_replot, CPU ms, medians of 6 alternated runs):
// 10 min shared axes (thin spans) 3.23 -> 2.53, 1 h shared axes (row sweep) 2.84 -> 2.38.

// Each trace in turn, a masked store per row of its band: a later trace covers an earlier one.
// A trace covering less than a pixel in four rows of its band (a steep, thin line) is written
// by column: a masked store of a row costs less than a column's store of a pixel (measured: a
// band of 700 rows with 35-pixel spans, 10 min shared axes, is 20 % faster masked), but not 4x less.
__attribute__((target("avx512f"))) void writeLanesMasked(uchar* bits, qsizetype stride, int x0,
                                                         const SpanCanvas::Lanes* l, size_t n) {
    for (size_t k = 0; k < n; ++k) {
        if (4 * l[k].pixels < l[k].to - l[k].from + 1) {
            writeColumns(bits, stride, x0, l[k]);
            continue;
        }
        const __m512i top = _mm512_loadu_si512(l[k].top), bottom = _mm512_loadu_si512(l[k].bottom);
        const __m512i color = _mm512_set1_epi32(l[k].color[0]);
        uchar* row = bits + qsizetype(l[k].from) * stride + qsizetype(x0) * 4;
        for (int y = l[k].from; y <= l[k].to; ++y, row += stride) {
            const __m512i vy = _mm512_set1_epi32(y);
            const __mmask16 m = _mm512_mask_cmple_epi32_mask(_mm512_cmple_epi32_mask(top, vy), vy, bottom);
            _mm512_mask_storeu_epi32(row, m, color);
        }
    }
}

// The row sweep below, 16 lanes a step: the last trace first, each lane taken by the first
// trace covering it, one masked store of the taken lanes a row.
__attribute__((target("avx512f"))) void sweepRowsMasked(uchar* bits, qsizetype stride, int x0,
                                                        const SpanCanvas::Lanes* l, size_t n,
                                                        const std::pair<int, int>* band, size_t bands) {
    for (size_t b = 0; b < bands; ++b) {
        for (int y = band[b].first; y <= band[b].second; ++y) {
            const __m512i vy = _mm512_set1_epi32(y);
            __m512i p = _mm512_setzero_si512();
            __mmask16 taken = 0;
            for (size_t k = n; k-- > 0;) {
                if (y < l[k].from || y > l[k].to) continue;
                const __m512i top = _mm512_loadu_si512(l[k].top), bottom = _mm512_loadu_si512(l[k].bottom);
                const __mmask16 m =
                    _mm512_mask_cmple_epi32_mask(_mm512_cmple_epi32_mask(top, vy), vy, bottom) & __mmask16(~taken);
                p = _mm512_mask_mov_epi32(p, m, _mm512_set1_epi32(l[k].color[0]));
                taken |= m;
                if (taken == 0xffff) break;
            }
            _mm512_mask_storeu_epi32(bits + y * stride + qsizetype(x0) * 4, taken, p);
        }
    }
}
}  // namespace
#endif

bool SpanCanvas::maskedStoresSupported() {
#ifdef COSCOPE_SPAN_MASKED
    static const bool avx512 = __builtin_cpu_supports("avx512f");
    return avx512;
#else
    return false;
#endif
}

void SpanCanvas::setMaskedStores(bool on) { masked_ = on && maskedStoresSupported(); }

void SpanCanvas::begin(QImage* image) {
    image_ = image;
    used_ = 0;
}

bool SpanCanvas::add(const QImage* image, uint32_t px, const QVector<QRect>& spans, int dx, int dy, const QRect& clip) {
    if (!image_ || image != image_) return false;
    for (qsizetype i = 1; i < spans.size(); ++i)
        if (spans[i].x() <= spans[i - 1].x()) return false;
    const QRect c = clip & image_->rect();
    if (used_ == traces_.size()) traces_.emplace_back();
    Trace& t = traces_[used_++];
    t.px = px;
    t.spans.clear();
    for (const QRect& s : spans) {
        const int x = s.x() + dx, top = std::max(s.top() + dy, c.top()), bottom = std::min(s.bottom() + dy, c.bottom());
        if (x >= c.left() && x <= c.right() && top <= bottom) t.spans.push_back({x, top, bottom});
    }
    return true;
}

void SpanCanvas::flush() {
    if (!image_ || used_ == 0) {
        used_ = 0;
        return;
    }
    // Groups in column order; a cursor per trace walks its spans along.
    std::vector<size_t> cursor(used_, 0);
    for (;;) {
        int x = INT_MAX;
        for (size_t k = 0; k < used_; ++k)
            if (cursor[k] < traces_[k].spans.size()) x = std::min(x, traces_[k].spans[cursor[k]].x);
        if (x == INT_MAX) break;
        writeGroup(x & ~(kGroup - 1), 0, used_, cursor);
    }
    used_ = 0;
}

void SpanCanvas::writeGroup(int x0, size_t first, size_t last, std::vector<size_t>& cursor) {
    Lanes lanes[16];
    std::vector<Lanes> more;
    Lanes* l = lanes;
    if (last - first > 16) {
        more.resize(last - first);
        l = more.data();
    }
    size_t n = 0;
    int64_t pixels = 0;  // what the spans cover, counted once per trace
    for (size_t k = first; k < last; ++k) {
        const Trace& t = traces_[k];
        alignas(16) int32_t top[kGroup], bottom[kGroup];
        std::fill(std::begin(top), std::end(top), INT32_MAX);
        std::fill(std::begin(bottom), std::end(bottom), INT32_MIN);
        int from = INT_MAX, to = INT_MIN, covered = 0;
        size_t& i = cursor[k];
        for (; i < t.spans.size() && t.spans[i].x < x0 + kGroup; ++i) {
            const Span& s = t.spans[i];
            top[s.x - x0] = s.top;
            bottom[s.x - x0] = s.bottom;
            covered += s.bottom - s.top + 1;
            from = std::min(from, s.top);
            to = std::max(to, s.bottom);
        }
        if (from > to) continue;
        Lanes& a = l[n++];
        std::memcpy(a.top, top, sizeof a.top);
        std::memcpy(a.bottom, bottom, sizeof a.bottom);
        a.from = from;
        a.to = to;
        a.pixels = covered;
        pixels += covered;
        const auto c = int32_t(t.px);
        a.color = V4{c, c, c, c};
    }
    if (n == 0) return;
    uchar* bits = image_->bits();
    const qsizetype stride = image_->bytesPerLine();
    // Row by row: the row's 16 pixels once, every trace covering the row. Only the
    // rows some trace covers (stacked traces leave the rows between their rects alone).
    std::pair<int, int> bands[16];
    std::vector<std::pair<int, int>> moreBands;
    std::pair<int, int>* band = bands;
    if (n > 16) {
        moreBands.resize(n);
        band = moreBands.data();
    }
    for (size_t k = 0; k < n; ++k) band[k] = {l[k].from, l[k].to};
    std::sort(band, band + n);
    size_t merged = 0;  // merged in place: the rows some trace covers
    int64_t rows = 0;
    for (size_t b = 0; b < n;) {
        std::pair<int, int> m = band[b];
        for (++b; b < n && band[b].first <= m.second + 1; ++b) m.second = std::max(m.second, band[b].second);
        band[merged++] = m;
        rows += m.second - m.first + 1;
    }
    // Thin spans (a short recording, a zoom): each trace's spans column by column, one store a
    // pixel they cover, within the group's stripe of the image (a few tens of KiB, kept in the
    // cache across the traces). Tall overlaid spans (a long recording's envelopes) cover each
    // other: row by row below, every pixel once. The row sweep costs about a store's worth per
    // trace on a row; measured (8 x 1 kHz, shared axes, one way or the other for every group):
    // columns 3.5x cheaper at 10 min, rows 4x cheaper at 1 h. With AVX-512 both write a row's
    // 16 pixels with one masked store (above).
    constexpr int64_t kRowSweepAbove = 32;  // span pixels per row of the union
    const bool thin = pixels <= kRowSweepAbove * rows, inside = x0 >= 0 && x0 + kGroup <= image_->width();
#ifdef COSCOPE_SPAN_MASKED
    if (masked_ && inside) {
        if (thin) writeLanesMasked(bits, stride, x0, l, n);
        else sweepRowsMasked(bits, stride, x0, l, n, band, merged);
        return;
    }
#endif
    if (!inside || thin) {  // the image's edge, or thin spans: lane by lane
        for (size_t k = 0; k < n; ++k) writeColumns(bits, stride, x0, l[k]);
        return;
    }
    for (size_t b = 0; b < merged; ++b) {
        const auto [from, to] = band[b];
        for (int y = from; y <= to; ++y) {
            uchar* row = bits + y * stride + qsizetype(x0) * 4;
            V4 p[4];
            std::memcpy(p, row, sizeof p);
            // The last trace first: a pixel it covers is final (it would be painted over the
            // earlier ones), so each lane takes the first trace that covers it, and once all 16
            // lanes are taken the traces below are not looked at (overlaid bands cover each other).
            V4 taken[4] = {};
            for (size_t k = n; k-- > 0;) {
                const Lanes& a = l[k];
                if (y < a.from || y > a.to) continue;
                for (int q = 0; q < 4; ++q) {
                    const V4 m = (a.top[q] <= y) & (a.bottom[q] >= y) & ~taken[q];
                    p[q] = (p[q] & ~m) | (a.color & m);
                    taken[q] |= m;
                }
                const V4 all = taken[0] & taken[1] & taken[2] & taken[3];
                if ((all[0] & all[1] & all[2] & all[3]) == -1) break;
            }
            std::memcpy(row, p, sizeof p);
        }
    }
}

}  // namespace coscope::gui
