// SPDX-License-Identifier: GPL-3.0-or-later
// SDO transfers as one expandable row in the trace (issue #6): expedited, segmented, block and
// aborted transfers (CiA 301 §7.2.4.3) grouped, expand/collapse, filters with grouping, live
// transfers completing, the details of a transfer row; and one network context per bus in the
// trace decoder (the same node-ID on two buses with different PDO mappings).
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/FrameDetailsView.h"
#include "app/gui/trace/SdoGroups.h"
#include "app/gui/trace/TraceDecoder.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "core/canopen/Sdo.h"
#include "core/canopen/SdoClient.h"
#include "eds/SimulatorDictionaries.h"
#include "tests/CliRun.h"

#include <QAction>
#include <QTableView>
#include <QTreeWidget>
#include <QtTest>

using namespace coscope;
using namespace coscope::gui;

namespace {

CanFrame at(int64_t ms, uint32_t id, std::vector<uint8_t> b, uint8_t bus = 0) {
    CanFrame f = CanFrame::classic(id, {});
    f.len = static_cast<uint8_t>(b.size());
    std::copy(b.begin(), b.end(), f.data.begin());
    f.timestampNs = 1'700'000'000'000'000'000LL + ms * 1'000'000;
    f.bus = bus;
    return f;
}

QString cell(const TraceModel& m, int row, int col) { return m.data(m.index(row, col), Qt::DisplayRole).toString(); }

// The trace: 22 frames, four complete transfers of node 5 (A expedited upload 1000h, B
// segmented upload 1008h "CoScope Dr 1", C block download 2000:01 of 10 bytes with CRC, D an
// upload of 3000h aborted), other traffic in between and an unfinished upload of node 6.
std::vector<CanFrame> transfersTrace() {
    const QByteArray block("0123456789");
    const uint16_t crc =
        canopen::sdoBlockCrc(reinterpret_cast<const uint8_t*>(block.constData()), static_cast<size_t>(block.size()));
    return {
        at(0, 0x705, {0x05}),                                                   // 0 heartbeat
        at(1, 0x605, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}),                     // 1 A: upload 1000h
        at(2, 0x585, {0x43, 0x00, 0x10, 0x00, 0x92, 0x01, 0x02, 0x00}),         // 2 A: expedited, 4 bytes
        at(3, 0x186, {1, 2, 3, 4}),                                             // 3 TPDO1 node 6
        at(4, 0x605, {0x40, 0x08, 0x10, 0x00, 0, 0, 0, 0}),                     // 4 B: upload 1008h
        at(5, 0x585, {0x41, 0x08, 0x10, 0x00, 11, 0, 0, 0}),                    // 5 B: segmented, 11 bytes
        at(6, 0x605, {0x60, 0, 0, 0, 0, 0, 0, 0}),                              // 6 B: segment request t=0
        at(7, 0x585, {0x00, 'C', 'o', 'S', 'c', 'o', 'p', 'e'}),                // 7 B: 7 bytes t=0
        at(8, 0x705, {0x05}),                                                   // 8 heartbeat
        at(9, 0x605, {0x70, 0, 0, 0, 0, 0, 0, 0}),                              // 9 B: segment request t=1
        at(10, 0x585, {0x17, ' ', 'D', 'r', '1', 0, 0, 0}),                     // 10 B: last, 4 bytes t=1
        at(11, 0x605, {0xC6, 0x00, 0x20, 0x01, 10, 0, 0, 0}),                   // 11 C: block download, crc, size 10
        at(12, 0x585, {0xA4, 0x00, 0x20, 0x01, 127, 0, 0, 0}),                  // 12 C: blksize 127
        at(13, 0x605, {0x01, '0', '1', '2', '3', '4', '5', '6'}),               // 13 C: segment 1
        at(14, 0x605, {0x82, '7', '8', '9', 0, 0, 0, 0}),                       // 14 C: segment 2, last
        at(15, 0x585, {0xA2, 2, 127, 0, 0, 0, 0, 0}),                           // 15 C: ack 2
        at(16, 0x605, {0xD1, uint8_t(crc), uint8_t(crc >> 8), 0, 0, 0, 0, 0}),  // 16 C: end, 4 unused bytes
        at(17, 0x585, {0xA1, 0, 0, 0, 0, 0, 0, 0}),                             // 17 C: end response
        at(18, 0x605, {0x40, 0x00, 0x30, 0x00, 0, 0, 0, 0}),                    // 18 D: upload 3000h
        at(19, 0x585, {0x80, 0x00, 0x30, 0x00, 0x00, 0x00, 0x02, 0x06}),        // 19 D: abort 06020000h
        at(20, 0x606, {0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0}),                    // 20 node 6 upload, unanswered
        at(21, 0x705, {0x05}),                                                  // 21 heartbeat
    };
}

std::shared_ptr<TraceStore> storeOf(const std::vector<CanFrame>& frames) {
    auto s = std::make_shared<TraceStore>();
    s->append(std::span<const CanFrame>(frames.data(), frames.size()));
    return s;
}

// The transfer rows of a model, as (row, group).
std::vector<std::pair<int, int64_t>> transferRows(const TraceModel& m) {
    std::vector<std::pair<int, int64_t>> v;
    for (int r = 0; r < m.rowCount(); ++r)
        if (m.rowKind(r) == TraceModel::RowKind::Transfer) v.emplace_back(r, m.groupAt(r));
    return v;
}

bool waitFor(const std::function<bool()>& done, TraceDock* dock = nullptr, int ms = 10000) {
    QElapsedTimer t;
    t.start();
    while (!done()) {
        if (t.elapsed() > ms) return false;
        QTest::qWait(10);
        if (dock) dock->refresh();
    }
    return true;
}

}  // namespace

class TestTraceSdoGroups : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        eds::installSimulatorDictionaries();
        QVERIFY(dir_.isValid());
    }

    void indexFindsEachTransfer() {
        auto store = storeOf(transfersTrace());
        SdoGroupIndex idx;
        idx.scan(*store, static_cast<FrameNo>(store->size()));
        QCOMPARE(idx.size(), size_t(4));
        auto frames = [&](size_t g) { return std::vector<FrameNo>(idx.frames(g).begin(), idx.frames(g).end()); };
        QCOMPARE(frames(0), (std::vector<FrameNo>{1, 2}));
        QCOMPARE(frames(1), (std::vector<FrameNo>{4, 5, 6, 7, 9, 10}));
        QCOMPARE(frames(2), (std::vector<FrameNo>{11, 12, 13, 14, 15, 16, 17}));
        QCOMPARE(frames(3), (std::vector<FrameNo>{18, 19}));
        QCOMPARE(idx.groupOf(9), 1);
        QCOMPARE(idx.groupOf(8), -1);
        QCOMPARE(idx.groupOf(20), -1);  // unanswered: no transfer
        TraceDecoder decoder(false);
        decoder.setStore(store);
        const auto b = SdoGroupIndex::record(*store, idx, 1, decoder);
        QCOMPARE(b.data, QByteArray("CoScope Dr1"));
        QVERIFY(b.upload && b.segmented);
        const auto c = SdoGroupIndex::record(*store, idx, 2, decoder);
        QCOMPARE(c.status, QStringLiteral("ok"));  // the CRC matched
        QCOMPARE(c.data, QByteArray("0123456789"));
        QVERIFY(c.block && !c.upload);
        const auto d = SdoGroupIndex::record(*store, idx, 3, decoder);
        QCOMPARE(d.status, QStringLiteral("aborted"));
        QCOMPARE(d.abortCode, 0x06020000u);
        // The same transfers, scanned in pieces (live): same groups.
        SdoGroupIndex live;
        for (FrameNo to : {3u, 6u, 10u, 15u, 22u}) live.scan(*store, to);
        QCOMPARE(live.size(), size_t(4));
        QCOMPARE(std::vector<FrameNo>(live.frames(1).begin(), live.frames(1).end()), frames(1));
    }

    void groupedRowsExpandCollapse() {
        auto store = storeOf(transfersTrace());
        auto decoder = std::make_shared<TraceDecoder>(false);
        decoder->setStore(store);
        TraceModel m;
        m.setStore(store);
        m.setDecoder(decoder);
        QCOMPARE(m.rowCount(), 22);
        m.setGrouped(true);
        QVERIFY(m.isGrouped());
        // 5 frames outside transfers (0, 3, 8, 20, 21) + 4 transfer rows.
        QCOMPARE(m.rowCount(), 9);
        const auto rows = transferRows(m);
        QCOMPARE(rows.size(), size_t(4));
        QCOMPARE(rows[0].first, 1);  // A where its first frame was
        QCOMPARE(m.frameAt(1), FrameNo(1));
        QCOMPARE(m.frameAt(2), FrameNo(3));  // the TPDO after A
        QCOMPARE(m.frameAt(3), FrameNo(4));  // B
        QCOMPARE(m.frameAt(4), FrameNo(8));  // the heartbeat inside B's frames comes after it
        QCOMPARE(cell(m, 1, TraceModel::Service), QStringLiteral("SDO"));
        QCOMPARE(cell(m, 1, TraceModel::Node), QStringLiteral("5"));
        QCOMPARE(cell(m, 1, TraceModel::Time), QStringLiteral("0.001000"));
        QVERIFY(cell(m, 1, TraceModel::Number).startsWith(QStringLiteral("▸")));
        const QString b = cell(m, 3, TraceModel::Summary);
        QVERIFY2(b.contains(QStringLiteral("1008:00")) && b.contains(QStringLiteral("CoScope Dr1")) &&
                     b.contains(QStringLiteral("segmented")) && b.contains(QStringLiteral("6 frames")),
                 qPrintable(b));
        const QString c = cell(m, 5, TraceModel::Summary);
        QVERIFY2(c.contains(QStringLiteral("2000:01")) && c.contains(QStringLiteral("block")) &&
                     c.contains(QStringLiteral("10 bytes")),
                 qPrintable(c));
        const QString d = cell(m, 6, TraceModel::Summary);
        QVERIFY2(d.contains(QStringLiteral("aborted")) && d.contains(QStringLiteral("06020000")), qPrintable(d));
        QCOMPARE(cell(m, 7, TraceModel::Number), QStringLiteral("21"));  // node 6's unanswered request stays a frame

        // Expand B: its 6 frames under it, then the rest shifted.
        QSignalSpy resets(&m, &QAbstractItemModel::modelAboutToBeReset);
        QVERIFY(!m.toggleExpanded(0));  // not a transfer row
        QVERIFY(m.toggleExpanded(3));
        QCOMPARE(m.rowCount(), 15);
        QVERIFY(cell(m, 3, TraceModel::Number).startsWith(QStringLiteral("▾")));
        QCOMPARE(m.rowKind(4), TraceModel::RowKind::TransferFrame);
        const std::vector<FrameNo> members{4, 5, 6, 7, 9, 10};
        for (int i = 0; i < 6; ++i) QCOMPARE(m.frameAt(4 + i), members[size_t(i)]);
        QVERIFY(cell(m, 8, TraceModel::Summary).contains(QStringLiteral("↳")));
        QCOMPARE(m.frameAt(10), FrameNo(8));
        QCOMPARE(m.rowOf(9), 8);    // a frame of an expanded transfer: its own row
        QCOMPARE(m.rowOf(12), 11);  // of a collapsed one: the transfer row (C after B's members)
        // Expand D too, then collapse B: D's frames follow D.
        QVERIFY(m.toggleExpanded(12));
        QCOMPARE(m.rowCount(), 17);
        QCOMPARE(m.frameAt(13), FrameNo(18));
        QCOMPARE(m.frameAt(14), FrameNo(19));
        QCOMPARE(m.frameAt(15), FrameNo(20));
        QVERIFY(m.toggleExpanded(3));
        QCOMPARE(m.rowCount(), 11);
        QCOMPARE(m.frameAt(7), FrameNo(18));
        QCOMPARE(m.rowKind(7), TraceModel::RowKind::TransferFrame);
        QCOMPARE(resets.count(), 0);
        // What "save shown frames" writes: every frame once, in order.
        const auto shown = m.shownFrames();
        QCOMPARE(shown.size(), size_t(22));
        QVERIFY(std::is_sorted(shown.begin(), shown.end()));
        m.setGrouped(false);
        QCOMPARE(m.rowCount(), 22);
    }

    void filtersWithGrouping() {
        auto store = storeOf(transfersTrace());
        auto decoder = std::make_shared<TraceDecoder>(false);
        decoder->setStore(store);
        auto view = [&](const QString& query) {
            QString error;
            const auto f = TraceFilter::parse(query, &error);
            FilterJob job(store, *f, decoder, true);
            job.start();
            job.wait();
            auto m = std::make_unique<TraceModel>();
            m->setStore(store);
            m->setDecoder(decoder);
            const FrameNo upTo = job.scannedUpTo();
            m->setView(*f, job.takeResult(), upTo, job.takeGroups(), job.takeGroupedRows());
            return m;
        };
        auto sdo = view(QStringLiteral("node:5 svc:sdo"));
        QCOMPARE(sdo->rowCount(), 4);
        QCOMPARE(transferRows(*sdo).size(), size_t(4));
        auto six = view(QStringLiteral("node:6"));
        QCOMPARE(six->rowCount(), 2);
        QCOMPARE(transferRows(*six).size(), size_t(0));
        // Only the server's responses: the transfers stay, expanding shows their responses.
        auto resp = view(QStringLiteral("node:5 svc:sdo_resp"));
        QCOMPARE(resp->rowCount(), 4);
        QCOMPARE(resp->frameAt(1), FrameNo(5));  // B stands at its first response
        QVERIFY(resp->toggleExpanded(1));
        QCOMPARE(resp->rowCount(), 7);
        QCOMPARE(resp->frameAt(2), FrameNo(5));
        QCOMPARE(resp->frameAt(3), FrameNo(7));
        QCOMPARE(resp->frameAt(4), FrameNo(10));
        // Text in the summary: the abort frame's transfer.
        auto abort = view(QStringLiteral("abort"));
        QCOMPARE(abort->rowCount(), 1);
        QCOMPARE(abort->rowKind(0), TraceModel::RowKind::Transfer);
        QVERIFY(cell(*abort, 0, TraceModel::Summary).contains(QStringLiteral("aborted")));
        QVERIFY(abort->toggleExpanded(0));
        QCOMPARE(abort->rowCount(), 2);
        QCOMPARE(abort->frameAt(1), FrameNo(19));
        QCOMPARE(abort->shownFrames(), std::vector<FrameNo>{19});
    }

    void liveTransfersCompleteWithoutReset() {
        const auto all = transfersTrace();
        auto store = std::make_shared<TraceStore>();
        store->append(std::span<const CanFrame>(all.data(), 7));  // B is under way (frames 4..6)
        auto decoder = std::make_shared<TraceDecoder>(false);
        decoder->setStore(store);
        TraceModel m;
        m.setStore(store);
        m.setDecoder(decoder);
        m.setGrouped(true);
        QCOMPARE(m.rowCount(), 6);  // 0, A, 3, 4, 5, 6
        QCOMPARE(m.rowKind(3), TraceModel::RowKind::Frame);
        QSignalSpy resets(&m, &QAbstractItemModel::modelAboutToBeReset);
        QSignalSpy removed(&m, &QAbstractItemModel::rowsRemoved);
        QSignalSpy changed(&m, &QAbstractItemModel::dataChanged);
        store->append(std::span<const CanFrame>(all.data() + 7, 4));  // 7..10: B completes
        m.refresh();
        QCOMPARE(resets.count(), 0);
        QVERIFY(removed.count() >= 1);
        QVERIFY(changed.count() >= 1);
        QCOMPARE(m.rowCount(), 5);  // 0, A, 3, B, 8
        QCOMPARE(m.rowKind(3), TraceModel::RowKind::Transfer);
        QCOMPARE(m.frameAt(4), FrameNo(8));
        store->append(std::span<const CanFrame>(all.data() + 11, all.size() - 11));
        m.refresh();
        QCOMPARE(resets.count(), 0);
        QCOMPARE(m.rowCount(), 9);
        QCOMPARE(transferRows(m).size(), size_t(4));
        // With a filter, live too.
        auto store2 = std::make_shared<TraceStore>();
        store2->append(std::span<const CanFrame>(all.data(), 12));  // C has just started
        TraceModel f;
        f.setStore(store2);
        f.setDecoder(decoder);
        f.setFilter(*TraceFilter::parse(QStringLiteral("svc:sdo"), nullptr), {}, 0);
        f.refresh();
        f.setGrouped(true);
        QCOMPARE(f.rowCount(), 3);  // A, B, C's first frame
        store2->append(std::span<const CanFrame>(all.data() + 12, all.size() - 12));
        QSignalSpy resets2(&f, &QAbstractItemModel::modelAboutToBeReset);
        f.refresh();
        QCOMPARE(resets2.count(), 0);
        QCOMPARE(f.rowCount(), 5);  // A, B, C, D, node 6's request
        QCOMPARE(transferRows(f).size(), size_t(4));
    }

    void dockToggleAndDetails() {
        // A candump -L log with the transfers, opened in a workspace; the dock groups off-thread.
        const QString path = dir_.filePath(QStringLiteral("sdo.log"));
        {
            QFile file(path);
            QVERIFY(file.open(QIODevice::WriteOnly));
            for (const CanFrame& f : transfersTrace()) file.write((formatCandumpL(f, u"can0") + u'\n').toUtf8());
        }
        Workspace ws;
        TraceDock dock(&ws);
        dock.resize(1200, 700);
        dock.show();
        QString error;
        QVERIFY2(ws.openLog(path, &error), qPrintable(error));
        dock.rebind();
        QVERIFY(
            waitFor([&] { return ws.loadJob() && ws.loadJob()->isDone() && dock.model()->rowCount() == 22; }, &dock));
        QAction* group = dock.groupSdoAction();
        QVERIFY(group && group->isCheckable());
        group->setChecked(true);
        QVERIFY(waitFor([&] { return !dock.isFiltering() && dock.model()->isGrouped(); }, &dock));
        QCOMPARE(dock.model()->rowCount(), 9);
        // Details of the segmented transfer's row: the record's fields.
        dock.view()->setCurrentIndex(dock.view()->model()->index(3, TraceModel::Summary));
        QTreeWidget* tree = dock.details()->tree();
        QCOMPARE(tree->topLevelItemCount(), 1);
        QTreeWidgetItem* top = tree->topLevelItem(0);
        QCOMPARE(top->text(0), QStringLiteral("SDO transfer"));
        QStringList fields;
        for (int i = 0; i < top->childCount(); ++i) fields << top->child(i)->text(0) + u'=' + top->child(i)->text(1);
        const QString all = fields.join(u'|');
        QVERIFY2(all.contains(QStringLiteral("Mode=segmented")) && all.contains(QStringLiteral("Status=ok")) &&
                     all.contains(QStringLiteral("Frames=6 (frames 5–11)")) &&
                     all.contains(QStringLiteral("Size=11 byte")),
                 qPrintable(all));
        // The aborted one.
        dock.view()->setCurrentIndex(dock.view()->model()->index(6, TraceModel::Summary));
        top = tree->topLevelItem(0);
        fields.clear();
        for (int i = 0; i < top->childCount(); ++i) fields << top->child(i)->text(0) + u'=' + top->child(i)->text(1);
        QVERIFY2(fields.join(u'|').contains(QStringLiteral("Status=aborted")) &&
                     fields.join(u'|').contains(QStringLiteral("Abort code=0x06020000")),
                 qPrintable(fields.join(u'|')));
        // A click on the arrow expands; a frame under it shows the frame's own details.
        const QRect arrow = dock.view()->visualRect(dock.view()->model()->index(3, TraceModel::Number));
        QTest::mouseClick(dock.view()->viewport(), Qt::LeftButton, {}, arrow.center());
        QCOMPARE(dock.model()->rowCount(), 15);
        dock.view()->setCurrentIndex(dock.view()->model()->index(5, TraceModel::Summary));
        QVERIFY(tree->topLevelItem(0)->text(0).startsWith(QStringLiteral("Frame 6")));
        if (const QString grab = qEnvironmentVariable("COSCOPE_TEST_GRAB"); !grab.isEmpty()) {  // to look at it
            dock.view()->setCurrentIndex(dock.view()->model()->index(3, TraceModel::Summary));
            dock.grab().save(grab);
        }
        // A filter keeps the grouping.
        QVERIFY(dock.applyFilter(QStringLiteral("node:5 svc:sdo")));
        QVERIFY(waitFor([&] { return !dock.isFiltering(); }, &dock));
        QCOMPARE(dock.model()->rowCount(), 4);
        group->setChecked(false);
        QVERIFY(waitFor([&] { return !dock.isFiltering(); }, &dock));
        QVERIFY(!dock.model()->isGrouped());
        QCOMPARE(dock.model()->rowCount(), 17);  // node 5's SDO frames, one by one
    }

    // Live capture from the virtual drives: SDO transfers made while grouping is on appear as
    // transfer rows as they complete, with row inserts/updates only (no model reset).
    void liveCaptureGroupsTransfers() {
        Workspace ws;
        TraceDock dock(&ws);
        dock.resize(1200, 700);
        dock.show();
        QString error;
        QVERIFY2(ws.connectBus(QStringLiteral("sim://"), &error), qPrintable(error));
        dock.rebind();
        QVERIFY(waitFor(
            [&] { return ws.bus() && ws.bus()->state() == CanBus::State::Open && dock.model()->rowCount() >= 3; },
            &dock));
        dock.setGroupSdo(true);
        QVERIFY(waitFor([&] { return !dock.isFiltering() && dock.model()->isGrouped(); }, &dock));
        QSignalSpy resets(dock.model(), &QAbstractItemModel::modelAboutToBeReset);
        const size_t before = dock.model()->groups()->size();
        int done = 0;
        std::vector<canopen::SdoResult> results;
        auto collect = [&](const canopen::SdoResult& r) {
            results.push_back(r);
            ++done;
        };
        canopen::SdoOptions block;
        block.protocol = canopen::SdoOptions::Protocol::Block;
        ws.sdo()->upload(3, 0x1000, 0, collect);         // expedited
        ws.sdo()->upload(3, 0x1008, 0, collect);         // segmented
        ws.sdo()->upload(3, 0x1008, 0, collect, block);  // block (or segmented when declined)
        ws.sdo()->upload(3, 0x3FFF, 0, collect);         // aborted: no such object
        QVERIFY(waitFor([&] { return done == 4; }, &dock));
        QStringList outcome;
        for (const auto& r : results) outcome << QStringLiteral("%1:%2 %3").arg(r.index, 4, 16).arg(r.ok).arg(r.error);
        QVERIFY2(results[0].ok && results[1].ok && !results[3].ok, qPrintable(outcome.join(u'|')));
        QVERIFY(waitFor([&] { return dock.model()->groups()->size() >= before + 4; }, &dock));
        dock.refresh();
        QCOMPARE(resets.count(), 0);
        // The last four transfer rows of node 3: 1000h, 1008h, 1008h, 3FFFh aborted.
        QStringList summaries;
        for (int r = 0; r < dock.model()->rowCount(); ++r)
            if (dock.model()->rowKind(r) == TraceModel::RowKind::Transfer &&
                cell(*dock.model(), r, TraceModel::Node) == QStringLiteral("3"))
                summaries << cell(*dock.model(), r, TraceModel::Summary);
        QVERIFY(summaries.size() >= 4);
        summaries = summaries.mid(summaries.size() - 4);
        QVERIFY2(summaries[0].contains(QStringLiteral("1000:00")) && summaries[0].contains(QStringLiteral("expedited")),
                 qPrintable(summaries.join('\n')));
        QVERIFY2(summaries[1].contains(QStringLiteral("1008:00")) && summaries[1].contains(QStringLiteral("segmented")),
                 qPrintable(summaries.join('\n')));
        QVERIFY2(summaries[2].contains(QStringLiteral("1008:00")), qPrintable(summaries.join('\n')));
        QVERIFY2(summaries[3].contains(QStringLiteral("3FFF:00")) && summaries[3].contains(QStringLiteral("aborted")),
                 qPrintable(summaries.join('\n')));
        ws.disconnectBus();
    }

    // One network context per bus: node 5 on bus 0 and node 5 on bus 1 have TPDO1 mapped to
    // different objects; the trace decoder (with snapshots every 4096 frames) keeps them apart.
    void perBusContextsInTraceDecoder() {
        std::vector<CanFrame> frames;
        auto mapTpdo1 = [&](uint8_t bus, uint32_t entry) {
            const std::vector<std::vector<uint8_t>> writes = {
                {0x2F, 0x00, 0x1A, 0x00, 0x00, 0, 0, 0},
                {0x23, 0x00, 0x1A, 0x01, uint8_t(entry), uint8_t(entry >> 8), uint8_t(entry >> 16),
                 uint8_t(entry >> 24)},
                {0x2F, 0x00, 0x1A, 0x00, 0x01, 0, 0, 0}};
            for (const auto& w : writes) {
                frames.push_back(at(0, 0x605, w, bus));
                frames.push_back(at(0, 0x585, {0x60, w[1], w[2], w[3], 0, 0, 0, 0}, bus));
            }
        };
        mapTpdo1(0, 0x60410010);                                                            // statusword
        mapTpdo1(1, 0x60640020);                                                            // position actual value
        for (int i = 0; i < 9000; ++i) frames.push_back(at(i, 0x080, {}, uint8_t(i & 1)));  // SYNC on both buses
        frames.push_back(at(9000, 0x185, {0x37, 0x06}, 0));
        frames.push_back(at(9001, 0x185, {0x00, 0x88, 0x13, 0x00}, 1));
        auto store = storeOf(frames);
        TraceDecoder decoder(false);
        decoder.setStore(store);
        dissect::Dissection d;
        d.reset(dissect::Dissection::Level::Flat);
        decoder.decodeAt(*store, static_cast<FrameNo>(frames.size() - 2), d);
        QCOMPARE(d.signalCount, 1);
        QCOMPARE(d.pdoSignals[0].index, 0x6041);
        d.reset(dissect::Dissection::Level::Flat);
        decoder.decodeAt(*store, static_cast<FrameNo>(frames.size() - 1), d);
        QCOMPARE(d.signalCount, 1);
        QCOMPARE(d.pdoSignals[0].index, 0x6064);
        QCOMPARE(d.pdoSignals[0].value.i, 1280000);
        QVERIFY(decoder.checkpointCount() >= 3);  // decoded from snapshots
        // The CLI decodes a two-bus candump the same way (it shares the network context).
        const QString path = dir_.filePath(QStringLiteral("two-buses.log"));
        {
            QFile file(path);
            QVERIFY(file.open(QIODevice::WriteOnly));
            for (const CanFrame& f : frames)
                if (f.id != 0x080) file.write((formatCandumpL(f, f.bus ? u"can1" : u"can0") + u'\n').toUtf8());
        }
        const Run r = cli({QStringLiteral("decode"), QStringLiteral("--format"), QStringLiteral("jsonl"), path}, 30000);
        QCOMPARE(r.code, 0);
        const QList<QByteArray> lines = r.out.toUtf8().split('\n');
        QStringList pdos;
        for (const QByteArray& line : lines) {
            const QJsonObject o = QJsonDocument::fromJson(line).object();
            if (o.value(QStringLiteral("service")).toString() == QStringLiteral("TPDO1"))
                pdos << o.value(QStringLiteral("bus")).toString() + u' ' +
                            o.value(QStringLiteral("fields"))
                                .toObject()
                                .value(QStringLiteral("pdo.signals"))
                                .toArray()
                                .at(0)
                                .toObject()
                                .value(QStringLiteral("obj"))
                                .toString();
        }
        QCOMPARE(pdos, (QStringList{QStringLiteral("can0 6041:00"), QStringLiteral("can1 6064:00")}));
    }
};

QTEST_MAIN(TestTraceSdoGroups)
#include "test_trace_sdo_groups.moc"
