// SPDX-License-Identifier: GPL-3.0-or-later
// Bounded memory (issue 16): the GUI thread never pages a chunk back from the capture journal.
// With a tiny trace budget, File ▸ Export PDO layout as DBC reads the whole trace on a worker,
// and the trace filter's test of the frames that arrived since the filter ran waits for the
// store's loader instead of reading paged-out frames itself; both results stay complete.
#include "app/gui/MainWindow.h"
#include "app/gui/session/MemoryBudget.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/TraceDecoder.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceFilter.h"
#include "app/gui/trace/TraceModel.h"
#include "core/trace/CaptureJournal.h"
#include "core/trace/TracePager.h"
#include "eds/SimulatorDictionaries.h"

#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

#include <thread>

#include "DbcReader.h"
#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::answerFileDialog;
using coscope::testing::clickMenuItem;
using coscope::testing::waitFor;

namespace {
constexpr int kChunk = int(TraceStore::kChunkSize);

// A pager holding the frames in RAM (the journal, durable ahead of the store).
class RamPager : public TracePager {
public:
    std::vector<CanFrame> frames;
    uint64_t durableFrames() const override { return frames.size(); }
    bool load(uint64_t first, uint32_t count, std::vector<CanFrame>& out, std::string*) override {
        out.assign(frames.begin() + static_cast<std::ptrdiff_t>(first),
                   frames.begin() + static_cast<std::ptrdiff_t>(first + count));
        return true;
    }
};

// TPDO1 of node 1 with its frame number; an EMCY of node 1 at frame 5 of every chunk.
CanFrame frameAt(int i) {
    if (i % kChunk == 5) return CanFrame::classic(0x81, {0x10, 0x23, 0x05, 0, 0, 0, 0, 0});
    return CanFrame::classic(0x181, {uint8_t(i >> 24), uint8_t(i >> 16), uint8_t(i >> 8), uint8_t(i)});
}
}  // namespace

class TestPagingGuiThread : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        qputenv("XDG_DATA_HOME", dir_.path().toUtf8());  // this test's own journal folder
        eds::installSimulatorDictionaries();
        QSettings().setValue(kMemoryBudgetKey, 1);
    }
    void cleanupTestCase() { QSettings().remove(kMemoryBudgetKey); }

    // Node 16's TPDO1 mapping is written by SDO in the first frames (CiA 301 §7.5.2.36: 1A00h
    // sub 0 = 0, the entries, sub 0 = 2), then three chunks of its TPDO1: the mapping's frames
    // are paged out when the layout is exported, and read back by the export's worker.
    void dbcExportReadsOnAWorker() {
        const QString log = dir_.filePath(QStringLiteral("pdo.log"));
        constexpr int kFrames = 3 * kChunk + 100;
        {
            QFile f(log);
            QVERIFY(f.open(QIODevice::WriteOnly));
            QByteArray out =
                "(100.000000) can0 710#00\n"
                "(100.010000) can0 610#2F001A0000000000\n(100.011000) can0 590#60001A0000000000\n"
                "(100.012000) can0 610#23001A0110004160\n(100.013000) can0 590#60001A0100000000\n"
                "(100.014000) can0 610#23001A0220006460\n(100.015000) can0 590#60001A0200000000\n"
                "(100.016000) can0 610#2F001A0002000000\n(100.017000) can0 590#60001A0000000000\n";
            for (int i = 9; i < kFrames; ++i)
                out += "(101." + QByteArray::number(i).rightJustified(6, '0') + ") can0 190#3716" +
                       QByteArray::number(i & 0xFF, 16).rightJustified(2, '0') + "000000\n";
            f.write(out);
        }
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(w.connectBus(QStringLiteral("replay://") + log + QStringLiteral("?speed=0")));
        auto store = w.workspace()->store();
        QVERIFY(waitFor([&] { return store->size() == size_t(kFrames); }, 120000));
        QVERIFY(waitFor(
            [&] {
                const CaptureJournal* j = w.workspace()->journal();
                return !j || j->framesWritten() == uint64_t(kFrames);
            },
            60000));
        QVERIFY2(waitFor([&] { return !store->isResident(0); }, 60000),
                 qPrintable(QString::number(store->residentChunks())));
        store->watchPageInsOn(std::this_thread::get_id());
        const uint64_t pageIns = store->pageIns();

        const QString dbcPath = dir_.filePath(QStringLiteral("layout.dbc"));
        auto answer = answerFileDialog(dbcPath);
        QVERIFY(clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Export PDO layout as DBC")));
        QVERIFY(waitFor([&] { return answer->answered(); }));
        QVERIFY2(waitFor([&] { return QFileInfo::exists(dbcPath); }, 60000), qPrintable(w.lastError()));
        QFile f(dbcPath);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const dbc::File file = dbc::parse(f.readAll());
        QVERIFY2(file.errors.isEmpty(), qPrintable(file.errors.join(u'\n')));
        QVERIFY(file.messages.count(0x190));
        QCOMPARE(file.messages.at(0x190).sigs.size(), size_t(2));
        QVERIFY(store->pageIns() > pageIns);  // the mapping's chunk came back from the journal
        QCOMPARE(store->watchedPageIns(), uint64_t(0));
        QCOMPARE(store->pageErrors(), uint64_t(0));
    }

    // A text filter ran up to frame 1000; four chunks arrived since (the filter job ran long),
    // the older ones paged out. The trace model's refresh tests them as the loader brings them
    // back, on the GUI thread without reading the disk, and finds every match.
    void filterOfNewFramesWaitsForTheLoader() {
        constexpr int kFrames = 4 * kChunk + 100;
        auto pager = std::make_shared<RamPager>();
        for (int i = 0; i < kFrames; ++i) pager->frames.push_back(frameAt(i));
        auto store = std::make_shared<TraceStore>();
        store->setPager(pager);
        store->setMemoryBudget(1u << 20);
        store->append(std::span<const CanFrame>(pager->frames.data(), 1000));
        auto decoder = std::make_shared<TraceDecoder>(true);
        decoder->setStore(store);
        QString error;
        const auto filter = TraceFilter::parse(QStringLiteral("emcy"), &error);
        QVERIFY2(filter, qPrintable(error));
        FilterJob job(store, *filter, decoder);
        job.start();
        job.wait();
        QCOMPARE(job.scannedUpTo(), FrameNo(1000));

        store->append(std::span<const CanFrame>(pager->frames.data() + 1000, pager->frames.size() - 1000));
        // The decoder's own snapshots are built by its worker (not part of this question), which
        // reads the chunks back in turn; the budget sends them out again.
        QVERIFY(waitFor(
            [&] {
                return decoder->checkpointCount() >= size_t(kFrames) / dissect::NetworkContext::checkpointInterval();
            },
            60000));
        QVERIFY2(waitFor([&] { return !store->isResident(1000) && !store->isResident(kChunk + 5); }, 30000),
                 qPrintable(QString::number(store->residentChunks())));

        store->watchPageInsOn(std::this_thread::get_id());
        const uint64_t pageIns = store->pageIns();
        TraceModel m;
        m.setStore(store);
        m.setDecoder(decoder);
        m.setFilter(job.filter(), job.takeResult(), job.scannedUpTo());  // tests the new frames at once
        QCOMPARE(store->watchedPageIns(), uint64_t(0));
        QVERIFY2(waitFor(
                     [&] {
                         m.refresh();
                         return m.rowCount() == 5;
                     },
                     60000),
                 qPrintable(QString::number(m.rowCount())));
        for (int c = 0; c < 5; ++c) QCOMPARE(m.frameAt(c), FrameNo(c * kChunk + 5));
        QVERIFY(store->pageIns() > pageIns);  // by the store's loader
        QCOMPARE(store->watchedPageIns(), uint64_t(0));
        QCOMPARE(store->pageErrors(), uint64_t(0));
    }
};

QTEST_MAIN(TestPagingGuiThread)
#include "test_paging_gui_thread.moc"
