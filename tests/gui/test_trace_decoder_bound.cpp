// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 38 (a day-long capture in bounded memory): the trace decoder keeps a bounded number of
// context snapshots however long the trace, and an old frame whose snapshot was dropped is still
// decoded in the context of everything before it (a PDO mapping written by SDO at the start):
// readyAt() says "not yet" and the worker rebuilds it; decodeAt() rebuilds it itself.
#include "app/gui/trace/TraceDecoder.h"
#include "dissectors/NetworkContext.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::gui;

namespace {
CanFrame at(int64_t us, CanFrame f) {
    f.timestampNs = 1'700'000'000'000'000'000LL + us * 1'000;
    return f;
}
void sdoWrite(std::vector<CanFrame>& s, int node, uint16_t index, uint8_t sub, uint32_t v, int size) {
    const uint8_t cs = static_cast<uint8_t>(0x23 | ((4 - size) << 2));
    const auto t = int64_t(s.size());
    s.push_back(at(t, CanFrame::classic(0x600 + node, {cs, uint8_t(index), uint8_t(index >> 8), sub, uint8_t(v),
                                                       uint8_t(v >> 8), uint8_t(v >> 16), uint8_t(v >> 24)})));
    s.push_back(
        at(t + 1, CanFrame::classic(0x580 + node, {0x60, uint8_t(index), uint8_t(index >> 8), sub, 0, 0, 0, 0})));
}
constexpr size_t kInterval = dissect::NetworkContext::checkpointInterval();
}  // namespace

class TestTraceDecoderBound : public QObject {
    Q_OBJECT
private slots:
    void oldFramesDecodedFromFewSnapshots() {
        // Node 2's TPDO1 remapped to 6064h alone at the start, then its PDOs for long enough that
        // the snapshots would be far more than the bound.
        std::vector<CanFrame> frames;
        sdoWrite(frames, 2, 0x1A00, 0, 0, 1);
        sdoWrite(frames, 2, 0x1A00, 1, 0x60640020, 4);
        sdoWrite(frames, 2, 0x1A00, 0, 1, 1);
        const size_t positions = TraceDecoder::kRecent + 3 * TraceDecoder::kSparse;
        while (frames.size() < positions * kInterval + 100) {
            const auto v = uint32_t(frames.size());
            frames.push_back(
                at(int64_t(frames.size()),
                   CanFrame::classic(0x182, {uint8_t(v), uint8_t(v >> 8), uint8_t(v >> 16), uint8_t(v >> 24)})));
        }
        auto store = std::make_shared<TraceStore>();
        store->append(frames);
        TraceDecoder decoder;
        decoder.setDictionaries({{2, QStringLiteral("aimotor")}});
        QVERIFY2(decoder.lastError().isEmpty(), qPrintable(decoder.lastError()));
        decoder.setStore(store);
        QTRY_COMPARE_WITH_TIMEOUT(decoder.checkpointCount(), positions + 1, 120000);
        // Bounded: the newest, the grid and nothing else.
        QVERIFY2(decoder.keptCheckpoints() <= TraceDecoder::kRecent + TraceDecoder::kSparse + 1,
                 qPrintable(QString::number(decoder.keptCheckpoints())));
        QVERIFY(decoder.checkpointStride() >= 4);

        // The reference: one context over every frame before n.
        auto reference = [&](FrameNo n) {
            dissect::NetworkContext ctx;
            QString error;
            [&] { QVERIFY(ctx.assignDictionary(2, QStringLiteral("aimotor"), &error)); }();
            dissect::Dissection d;
            for (FrameNo i = 0; i < n; ++i) {
                d.reset(dissect::Dissection::Level::Stats);
                ctx.dissect(store->frame(i), d, dissect::Dissection::Level::Stats);
            }
            d.reset(dissect::Dissection::Level::Flat);
            ctx.dissect(store->frame(n), d, dissect::Dissection::Level::Flat);
            return d.summary;
        };
        auto decoded = [&](FrameNo n) {
            dissect::Dissection d;
            d.reset(dissect::Dissection::Level::Flat);
            decoder.decodeAt(*store, n, d);
            return d.summary;
        };

        // An old frame off the grid: not ready, rebuilt by the worker, then decoded as the
        // reference does.
        const size_t stride = decoder.checkpointStride();
        const auto old = static_cast<FrameNo>((20 * stride + 1) * kInterval + 17);
        QVERIFY(!decoder.readyAt(*store, old));
        QTRY_VERIFY_WITH_TIMEOUT(decoder.readyAt(*store, old), 20000);
        QVERIFY(decoder.readyCount() >= 1);
        const QString text = decoded(old);
        QVERIFY2(text.contains(QStringLiteral("Position actual value")), qPrintable(text));
        QCOMPARE(text, reference(old));
        // Another one decoded at once (no readyAt() first): rebuilt on the calling thread.
        const auto other = static_cast<FrameNo>((40 * stride + stride - 1) * kInterval + 5);
        QCOMPARE(decoded(other), reference(other));
        // The newest frames are decoded from the newest snapshots, as before.
        const auto last = static_cast<FrameNo>(store->size() - 1);
        QVERIFY(decoder.readyAt(*store, last));
        QCOMPARE(decoded(last), reference(last));
        QVERIFY(decoder.keptCheckpoints() <= TraceDecoder::kRecent + TraceDecoder::kSparse + 1 + TraceDecoder::kCached);
    }
};

QTEST_GUILESS_MAIN(TestTraceDecoderBound)
#include "test_trace_decoder_bound.moc"
