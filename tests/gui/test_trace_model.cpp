// SPDX-License-Identifier: GPL-3.0-or-later
// The trace model and filters over a trace store: columns, time modes, latest-per-COB-ID,
// bookmarks, filter parsing and the off-thread filter job; the trace decoder (dissectors with
// their network context, snapshots every 4096 frames) behind the summary column.
#include "app/gui/trace/TraceDecoder.h"
#include "app/gui/trace/TraceFilter.h"
#include "app/gui/trace/TraceModel.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::gui;

namespace {
CanFrame at(int64_t ms, CanFrame f) {
    f.timestampNs = 1'700'000'000'000'000'000LL + ms * 1'000'000;
    return f;
}
QString cell(const TraceModel& m, int row, int col) { return m.data(m.index(row, col), Qt::DisplayRole).toString(); }
// SDO expedited download request (client -> node) and its confirmation.
void sdoWrite(TraceStore& s, int64_t ms, int node, uint16_t index, uint8_t sub, uint32_t v, int size) {
    const uint8_t cs = static_cast<uint8_t>(0x23 | ((4 - size) << 2));
    s.append(at(ms, CanFrame::classic(0x600 + node, {cs, uint8_t(index), uint8_t(index >> 8), sub, uint8_t(v),
                                                     uint8_t(v >> 8), uint8_t(v >> 16), uint8_t(v >> 24)})));
    s.append(at(ms + 1, CanFrame::classic(0x580 + node, {0x60, uint8_t(index), uint8_t(index >> 8), sub, 0, 0, 0, 0})));
}
}  // namespace

class TestTraceModel : public QObject {
    Q_OBJECT
    std::shared_ptr<TraceStore> store_;

private slots:
    void init() {
        store_ = std::make_shared<TraceStore>();
        store_->append(at(0, CanFrame::classic(0x705, {0x00})));        // 0 boot-up node 5
        store_->append(at(1, CanFrame::classic(0x000, {0x01, 0x05})));  // 1 NMT start node 5
        store_->append(at(3, CanFrame::classic(0x705, {0x05})));        // 2 heartbeat operational
        store_->append(at(4, CanFrame::classic(0x605, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0})));  // 3 SDO upload 1000h
        store_->append(
            at(6, CanFrame::classic(0x585, {0x80, 0x00, 0x20, 0x01, 0x00, 0x00, 0x02, 0x06})));  // 4 abort 06020000h
        store_->append(at(10, CanFrame::classic(0x085, {0x10, 0x23, 0x05, 0, 0, 0, 0, 0})));     // 5 EMCY 2310h
        store_->append(at(11, CanFrame::classic(0x186, {1, 2, 3, 4})));                          // 6 TPDO1 node 6
    }

    void columns() {
        TraceModel m;
        m.setStore(store_);
        QCOMPARE(m.rowCount(), 7);
        QCOMPARE(m.columnCount(), int(TraceModel::ColumnCount));
        QCOMPARE(cell(m, 0, TraceModel::Number), QStringLiteral("1"));
        QCOMPARE(cell(m, 0, TraceModel::CobId), QStringLiteral("705"));
        QCOMPARE(cell(m, 0, TraceModel::Node), QStringLiteral("5"));
        QCOMPARE(cell(m, 0, TraceModel::Service), QStringLiteral("NMT_EC"));
        QVERIFY(cell(m, 0, TraceModel::Summary).contains(QStringLiteral("Boot-up")));
        QCOMPARE(cell(m, 1, TraceModel::Service), QStringLiteral("NMT"));
        QCOMPARE(cell(m, 1, TraceModel::Node), QString());  // NMT's COB-ID carries no node
        QVERIFY(cell(m, 1, TraceModel::Summary).contains(QStringLiteral("node 5")));
        QCOMPARE(cell(m, 3, TraceModel::Data), QStringLiteral("40 00 10 00 00 00 00 00"));
        QVERIFY(cell(m, 3, TraceModel::Summary).contains(QStringLiteral("1000:00")));
        QVERIFY2(cell(m, 4, TraceModel::Summary).contains(QStringLiteral("06020000")),
                 qPrintable(cell(m, 4, TraceModel::Summary)));
        QVERIFY(cell(m, 5, TraceModel::Summary).contains(QStringLiteral("2310")));
        QCOMPARE(cell(m, 6, TraceModel::Service), QStringLiteral("TPDO1"));
        QCOMPARE(cell(m, 6, TraceModel::Direction), QStringLiteral("Rx"));
        QCOMPARE(cell(m, 6, TraceModel::Length), QStringLiteral("4"));
    }

    void timeModes() {
        TraceModel m;
        m.setStore(store_);
        QCOMPARE(cell(m, 2, TraceModel::Time), QStringLiteral("0.003000"));
        m.setTimeMode(TraceModel::TimeMode::Delta);
        QCOMPARE(cell(m, 2, TraceModel::Time), QStringLiteral("0.002000"));
        QCOMPARE(cell(m, 0, TraceModel::Time), QStringLiteral("0.000000"));
        m.setTimeMode(TraceModel::TimeMode::Absolute);
        QVERIFY(cell(m, 2, TraceModel::Time).contains(u':'));  // wall-clock time of day
        QCOMPARE(cell(m, 2, TraceModel::Time).right(6), QStringLiteral("003000"));
    }

    void liveRowsAppearOnRefresh() {
        TraceModel m;
        m.setStore(store_);
        QSignalSpy inserted(&m, &QAbstractItemModel::rowsInserted);
        store_->append(at(20, CanFrame::classic(0x705, {0x05})));
        store_->append(at(21, CanFrame::classic(0x705, {0x05})));
        QCOMPARE(m.rowCount(), 7);  // nothing until the timer pulls
        m.refresh();
        QCOMPARE(m.rowCount(), 9);
        QCOMPARE(inserted.count(), 1);  // one batch, not one signal per frame
    }

    void latestPerCobId() {
        TraceModel m;
        m.setStore(store_);
        m.setLatestPerCobId(true);
        QCOMPARE(m.rowCount(), 6);  // 705 000 605 585 085 186
        const int row705 = [&] {
            for (int r = 0; r < m.rowCount(); ++r)
                if (cell(m, r, TraceModel::CobId) == u"705") return r;
            return -1;
        }();
        QVERIFY(row705 >= 0);
        QCOMPARE(m.frameAt(row705), FrameNo(2));
        store_->append(at(30, CanFrame::classic(0x705, {0x7F})));
        m.refresh();
        QCOMPARE(m.rowCount(), 6);
        QCOMPARE(m.frameAt(row705), FrameNo(7));
        QVERIFY(cell(m, row705, TraceModel::Summary).contains(QStringLiteral("Pre-operational"), Qt::CaseInsensitive));
    }

    void bookmarks() {
        TraceModel m;
        m.setStore(store_);
        m.toggleBookmark(3);
        QVERIFY(m.isBookmarked(3));
        QVERIFY(m.data(m.index(3, 0), TraceModel::BookmarkRole).toBool());
        QVERIFY(m.data(m.index(3, 0), Qt::BackgroundRole).isValid());
        m.toggleBookmark(3);
        QVERIFY(!m.isBookmarked(3));
    }

    void filterParsing() {
        QString error;
        auto f = TraceFilter::parse(QStringLiteral("node:5 svc:sdo id:580-5FF abort"), &error);
        QVERIFY2(f, qPrintable(error));
        QCOMPARE(f->nodes, std::vector<int>{5});
        QCOMPARE(f->services.size(), size_t(2));
        QCOMPARE(f->idRanges.front(), std::make_pair(0x580u, 0x5FFu));
        QCOMPARE(f->text, QStringLiteral("abort"));
        QVERIFY(!TraceFilter::parse(QStringLiteral("node:200"), &error));
        QVERIFY(error.contains(QStringLiteral("200")));
        QVERIFY(!TraceFilter::parse(QStringLiteral("svc:bogus"), &error));
        QVERIFY(error.contains(QStringLiteral("bogus")));
        QVERIFY(!TraceFilter::parse(QStringLiteral("id:5FF-580"), &error));
        QVERIFY(TraceFilter::parse(QString(), &error)->isEmpty());
    }

    void filterResults_data() {
        QTest::addColumn<QString>("query");
        QTest::addColumn<std::vector<FrameNo>>("expected");
        QTest::newRow("node") << "node:5" << std::vector<FrameNo>{0, 2, 3, 4, 5};
        QTest::newRow("service") << "svc:sdo" << std::vector<FrameNo>{3, 4};
        QTest::newRow("heartbeats") << "svc:nmt_ec" << std::vector<FrameNo>{0, 2};
        QTest::newRow("range") << "id:000-0FF" << std::vector<FrameNo>{1, 5};
        QTest::newRow("text") << "boot-up" << std::vector<FrameNo>{0};
        QTest::newRow("and") << "node:5 svc:emcy,sdo_resp" << std::vector<FrameNo>{4, 5};
    }
    void filterResults() {
        QFETCH(QString, query);
        QFETCH(std::vector<FrameNo>, expected);
        const auto f = TraceFilter::parse(query, nullptr);
        QVERIFY(f);
        FilterJob job(store_, *f, defaultFrameDecoder());
        job.start();
        job.wait();
        QVERIFY(job.isDone());
        QCOMPARE(job.scannedUpTo(), FrameNo(7));
        const auto rows = job.takeResult();
        QCOMPARE(rows, expected);

        // The model shows them and keeps filtering what arrives later.
        TraceModel m;
        m.setStore(store_);
        m.setFilter(*f, rows, 7);
        QCOMPARE(m.rowCount(), int(expected.size()));
        store_->append(at(40, CanFrame::classic(0x705, {0x00})));  // boot-up node 5 again
        m.refresh();
        const bool matchesNew = query == u"node:5" || query == u"svc:nmt_ec" || query == u"boot-up";
        QCOMPARE(m.rowCount(), int(expected.size()) + (matchesNew ? 1 : 0));
        if (!expected.empty()) QCOMPARE(m.rowOf(expected.back()), int(expected.size()) - 1);
        m.clearFilter();
        QCOMPARE(m.rowCount(), 8);
    }

    void filterJobCancels() {
        auto big = std::make_shared<TraceStore>();
        std::vector<CanFrame> frames(100000, CanFrame::classic(0x181, {1, 2, 3}));
        for (int i = 0; i < 20; ++i) big->append(frames);
        FilterJob job(big, *TraceFilter::parse(QStringLiteral("tpdo1"), nullptr), defaultFrameDecoder());
        job.start();
        job.cancel();
        job.wait();
        QVERIFY(job.isDone());
        QVERIFY(job.isCancelled());
        QVERIFY(job.takeResult().size() < 2'000'000);  // stopped early
    }

    // The virtual drives' traffic through the real dissectors: node 2 an AIMOTOR drive (TPDO1 =
    // 6041h statusword, 6061h mode display, 6064h position), node 1 without a dictionary.
    void traceDecoding() {
        auto store = std::make_shared<TraceStore>();
        store->append(at(0, CanFrame::classic(0x182, {0x37, 0x02, 0x08, 0x10, 0x27, 0x00, 0x00})));  // 0 TPDO1 node 2
        store->append(at(1, CanFrame::classic(0x602, {0x40, 0x64, 0x60, 0x00, 0, 0, 0, 0})));  // 1 SDO upload 6064h
        store->append(at(2, CanFrame::classic(0x582, {0x43, 0x64, 0x60, 0x00, 0x10, 0x27, 0, 0})));  // 2 = 10000
        store->append(at(3, CanFrame::classic(0x601, {0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0})));        // 3 node 1 6041h
        // Filler past the first snapshot, then node 2 remaps TPDO1 to 6064h only (CiA 301 §7.5.2.36).
        std::vector<CanFrame> sync(5000, at(4, CanFrame::classic(0x080, {})));
        store->append(sync);
        const FrameNo remapAt = static_cast<FrameNo>(store->size());
        sdoWrite(*store, 10, 2, 0x1800, 1, 0x80000182, 4);
        sdoWrite(*store, 12, 2, 0x1A00, 0, 0, 1);
        sdoWrite(*store, 14, 2, 0x1A00, 1, 0x60640020, 4);
        sdoWrite(*store, 16, 2, 0x1A00, 0, 1, 1);
        sdoWrite(*store, 18, 2, 0x1800, 1, 0x182, 4);
        const FrameNo remapped = store->append(at(20, CanFrame::classic(0x182, {0x20, 0x4E, 0x00, 0x00})));  // 20000

        auto decoder = std::make_shared<TraceDecoder>(false);
        decoder->setStore(store);
        decoder->setDictionaries({{2, QStringLiteral("aimotor")}});
        QVERIFY2(decoder->lastError().isEmpty(), qPrintable(decoder->lastError()));

        TraceModel m;
        m.setStore(store);
        m.setDecoder(decoder);
        // Far frame first (builds the snapshot at 4096), then the early ones from snapshot 0.
        const QString late = m.summaryOf(remapped);
        QVERIFY2(late.contains(QStringLiteral("Position actual value")), qPrintable(late));
        QVERIFY2(!late.contains(QStringLiteral("Statusword")), qPrintable(late));
        QCOMPARE(decoder->checkpointCount(), size_t{2});
        const QString pdo = m.summaryOf(0);
        QVERIFY2(pdo.contains(QStringLiteral("Statusword")), qPrintable(pdo));
        QVERIFY2(pdo.contains(QStringLiteral("Position actual value")), qPrintable(pdo));
        const QString sdo = m.summaryOf(2);
        QVERIFY2(sdo.contains(QStringLiteral("Position actual value")), qPrintable(sdo));
        const QString generic = m.summaryOf(3);  // no dictionary: generic CiA 402 names
        QVERIFY2(generic.contains(QStringLiteral("Statusword")), qPrintable(generic));
        QVERIFY(!m.summaryOf(remapAt).isEmpty());

        // The details pane's field tree: the named signal with its bit positions.
        dissect::Dissection d;
        d.reset(dissect::Dissection::Level::Tree);
        decoder->decodeAt(*store, 0, d);
        QStringList tree;
        bool statuswordBits = false;
        for (const auto& t : d.tree) {
            tree << t.label + QLatin1Char('=') + t.value;
            if (t.label.contains(QStringLiteral("Statusword")) && t.byteOffset == 0 && t.byteLength == 2)
                statuswordBits = true;
        }
        QVERIFY2(statuswordBits, qPrintable(tree.join(QLatin1Char('\n'))));

        // A filter on decoded text sees the dissectors' summaries.
        const auto rows = runFilter(*store, *TraceFilter::parse(QStringLiteral("position actual"), nullptr), *decoder,
                                    0, static_cast<FrameNo>(store->size()), {});
        QVERIFY(rows && rows->size() >= 3);

        // Reassigning dictionaries is a new revision: the model decodes again.
        const uint64_t rev = decoder->revision();
        decoder->setDictionaries({});
        QVERIFY(decoder->revision() != rev);
        m.refresh();
        const QString unnamed = m.summaryOf(0);  // no mapping known for node 2 any more
        QVERIFY2(!unnamed.contains(QStringLiteral("Position actual value")), qPrintable(unnamed));
    }

    // The worker builds the snapshots as the store grows, one per 4096 frames.
    void traceDecoderWorker() {
        auto store = std::make_shared<TraceStore>();
        TraceDecoder decoder;
        decoder.setStore(store);
        std::vector<CanFrame> frames(3 * 4096 + 10, CanFrame::classic(0x181, {0x37, 0x02}));
        store->append(frames);
        QTRY_COMPARE_WITH_TIMEOUT(decoder.checkpointCount(), size_t{4}, 5000);
        store->append(frames);
        QTRY_COMPARE_WITH_TIMEOUT(decoder.checkpointCount(), size_t{7}, 5000);
        dissect::Dissection d;
        d.reset(dissect::Dissection::Level::Flat);
        decoder.decodeAt(*store, static_cast<FrameNo>(store->size() - 1), d);
        QCOMPARE(d.service, canopen::Service::Tpdo1);
        decoder.setStore(std::make_shared<TraceStore>());  // another source: snapshots forgotten
        QCOMPARE(decoder.checkpointCount(), size_t{1});
    }
};

QTEST_GUILESS_MAIN(TestTraceModel)
#include "test_trace_model.moc"
