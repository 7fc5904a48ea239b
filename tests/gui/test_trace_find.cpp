// SPDX-License-Identifier: GPL-3.0-or-later
// Find's row search (TraceFind.h) costs about one dissection per row in both directions. The
// trace decoder decodes frame N forward from the checkpoint before it and keeps a cursor after
// the frame it decoded last (TraceDecoder.h), so frames asked in falling order cost up to a
// checkpoint interval each: Find previous over 70,000 frames took minutes under ASan.
#include "app/gui/trace/TraceFind.h"
#include "dissectors/NetworkContext.h"

#include <QtTest>

#include <set>

using namespace coscope;
using namespace coscope::gui;

namespace {
constexpr uint64_t kInterval = dissect::NetworkContext::checkpointInterval();

// Summaries "PDO" except for the frames in `emcy`; counts the dissections a TraceDecoder would
// make for the frames asked, in the order asked (one cursor: forward from it, or from the
// checkpoint at or before the frame).
class CountingDecoder final : public FrameDecoder {
public:
    explicit CountingDecoder(std::set<FrameNo> emcy) : emcy_(std::move(emcy)) {}
    void decode(const CanFrame&, dissect::Dissection& out) const override { out.summary = QStringLiteral("PDO"); }
    void decodeAt(const TraceStore&, FrameNo n, dissect::Dissection& out) const override {
        const uint64_t checkpoint = n - n % kInterval;
        const uint64_t start = cursor_ >= checkpoint && cursor_ <= n ? cursor_ : checkpoint;
        dissections += n - start + 1;
        cursor_ = n + 1;
        out.summary = emcy_.count(n) ? QStringLiteral("EMCY") : QStringLiteral("PDO");
    }
    mutable uint64_t dissections = 0;

private:
    std::set<FrameNo> emcy_;
    mutable uint64_t cursor_ = ~uint64_t(0);
};

std::shared_ptr<TraceStore> makeStore(uint32_t frames) {
    auto store = std::make_shared<TraceStore>();
    for (uint32_t i = 0; i < frames; ++i) store->append(CanFrame::classic(0x181, {0, 0, uint8_t(i >> 8), uint8_t(i)}));
    return store;
}
}  // namespace

class TestTraceFind : public QObject {
    Q_OBJECT

private slots:
    // Find previous from the end back to the one EMCY near the start: about one dissection per
    // frame, as forward (row by row backward it was about half a checkpoint interval per frame).
    void backwardCostsOneDissectionPerRow() {
        constexpr uint32_t kFrames = 70000;
        auto store = makeStore(kFrames);
        const FindRows rows{nullptr, kFrames, nullptr};
        for (const bool forward : {false, true}) {
            auto decoder = std::make_shared<CountingDecoder>(std::set<FrameNo>{forward ? kFrames - 5 : 5});
            FrameMatcher matcher(QStringLiteral("emcy"), decoder);
            const FindStep step = findRows(*store, rows, matcher, forward ? 0 : kFrames - 1, forward, {});
            QCOMPARE(step.found, int64_t(forward ? kFrames - 5 : 5));
            QVERIFY2(decoder->dissections <= 2 * uint64_t(kFrames), qPrintable(QString::number(decoder->dissections)));
        }
    }

    // Backward, the match nearest before the start wins, also with several in one checkpoint
    // interval; the filtered rows (a subset of the frames) are searched the same way.
    void backwardFindsTheNearestMatch() {
        constexpr FrameNo kA = (kInterval / 50 + 1) * 50;  // three in the second interval, every 50th frame
        constexpr FrameNo kB = kA + 100, kC = kA + 200;
        static_assert(kC / kInterval == kA / kInterval);
        auto store = makeStore(3 * kInterval);
        auto decoder = std::make_shared<CountingDecoder>(std::set<FrameNo>{100, kA, kB, kC});
        FrameMatcher matcher(QStringLiteral("EMCY"), decoder);
        const FindRows all{nullptr, 3 * kInterval, nullptr};
        QCOMPARE(findRows(*store, all, matcher, kB + 50, false, {}).found, int64_t(kB));
        QCOMPARE(findRows(*store, all, matcher, kB, false, {}).found, int64_t(kB));  // inclusive
        QCOMPARE(findRows(*store, all, matcher, kB - 1, false, {}).found, int64_t(kA));
        QCOMPARE(findRows(*store, all, matcher, kA - 1, false, {}).found, int64_t(100));
        QCOMPARE(findRows(*store, all, matcher, 99, false, {}).found, int64_t(-1));
        QCOMPARE(findRows(*store, all, matcher, 99, false, {}).next, int64_t(-1));  // ran off the start

        // Every 50th frame: rows are positions in that list.
        auto every50 = std::make_shared<std::vector<FrameNo>>();
        for (FrameNo n = 0; n < 3 * kInterval; n += 50) every50->push_back(n);
        const FindRows filtered{every50, every50->size(), nullptr};
        const FindStep step = findRows(*store, filtered, matcher, int64_t(every50->size()) - 1, false, {});
        QCOMPARE(step.found, int64_t(kC / 50));
        QCOMPARE(filtered.frameAt(size_t(step.found)), kC);
        QCOMPARE(findRows(*store, filtered, matcher, int64_t(kC / 50) - 1, false, {}).found, int64_t(kB / 50));
    }

    // A row the caller may not read yet (paged out, or the GUI thread's time is up) stops the
    // search there, after the rows before it in search order were tested, and never tests it.
    void backwardStopsAtARowItMayNotRead() {
        auto store = makeStore(2 * kInterval);
        auto decoder = std::make_shared<CountingDecoder>(std::set<FrameNo>{kInterval + 100, kInterval + 300});
        FrameMatcher matcher(QStringLiteral("EMCY"), decoder);
        const FindRows all{nullptr, 2 * kInterval, nullptr};
        std::vector<int64_t> asked;
        const auto refuse200 = [&](int64_t row, FrameNo) {
            asked.push_back(row);
            return row != int64_t(kInterval + 200);
        };
        // The match after the refused row is found; the one before it is not reached.
        QCOMPARE(findRows(*store, all, matcher, kInterval + 400, false, refuse200).found, int64_t(kInterval + 300));
        asked.clear();
        const FindStep step = findRows(*store, all, matcher, kInterval + 299, false, refuse200);
        QCOMPARE(step.found, int64_t(-1));
        QCOMPARE(step.next, int64_t(kInterval + 200));
        QCOMPARE(asked.front(), int64_t(kInterval + 299));
        QCOMPARE(asked.back(), int64_t(kInterval + 200));
    }
};

QTEST_MAIN(TestTraceFind)
#include "test_trace_find.moc"
