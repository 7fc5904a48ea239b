// SPDX-License-Identifier: GPL-3.0-or-later
// Bounded memory in the app (issue 16): with a tiny trace budget (trace/memoryBudgetMB = 1) a
// live capture of several chunks keeps only a few in RAM, and yet scrolling to the top, Find,
// a filter and Save As reach the oldest frames, which come back from the capture journal; Find
// reaches frames that are all paged out when it is asked (it searches the store's frames on a
// worker, never the rows' "loading…" text).
#include "app/gui/MainWindow.h"
#include "app/gui/session/MemoryBudget.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/FrameDetailsView.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "app/gui/trace/TraceView.h"
#include "app/gui/trace/TraceWindow.h"
#include "core/logio/LogFormats.h"
#include "core/trace/CaptureJournal.h"
#include "eds/SimulatorDictionaries.h"

#include <QFile>
#include <QFileInfo>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QToolBar>
#include <QToolButton>
#include <QTreeWidget>
#include <QtTest>

#include <thread>

#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/TypeText.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::answerFileDialog;
using coscope::testing::clickMenuItem;
using coscope::testing::typeAndEnter;
using coscope::testing::waitFor;

namespace {
constexpr int kFrames = 3 * 65536 + 100;  // three whole chunks of the trace store and a bit
constexpr int kEmcyAt = 5;                // the one EMCY, in the oldest chunk

QString cell(const TraceModel* m, int row, int col) { return m->data(m->index(row, col), Qt::DisplayRole).toString(); }

// A segmented SDO upload of 1008h (Device name, 10 bytes "COSCOPESIM") from node 1, at frames
// kSdoAt.. (CiA 301 §7.2.4.3.4-7: initiate 40h / 41h with size, segments 60h/70h, answers
// 00h with 7 bytes, 19h = toggle 1, 4 bytes unused, last).
constexpr int kSdoAt = 20;
const char* const kSdo[] = {"601#4008100000000000", "581#410810000A000000", "601#6000000000000000",
                            "581#00434F53434F5045", "601#7000000000000000", "581#1953494D00000000"};

// TPDO1 of node 1 carrying its frame number; one EMCY of node 1 near the start; with `sdo`
// the upload above.
QString writeLog(const QString& path, bool sdo = false) {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    QByteArray out;
    for (int i = 0; i < kFrames; ++i) {
        out += "(1700000000." + QByteArray::number(i).rightJustified(6, '0') + ") can0 ";
        if (sdo && i >= kSdoAt && i < kSdoAt + 6) out += kSdo[i - kSdoAt];
        else
            out += i == kEmcyAt ? QByteArray("081#1023050000000000")
                                : "181#" + QByteArray::number(i, 16).rightJustified(8, '0').toUpper();
        out += '\n';
    }
    f.write(out);
    return path;
}

}  // namespace

class TestTracePagingGui : public QObject {
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

    // A live capture of the log (through the journal) as fast as the capture path takes it.
    static bool capture(MainWindow& w, const QString& log) {
        w.setQuiet(true);
        w.show();
        if (!QTest::qWaitForWindowActive(&w)) return false;
        if (!w.connectBus(QStringLiteral("replay://") + log + QStringLiteral("?speed=0"))) return false;
        auto store = w.workspace()->store();
        return waitFor([&] { return store->size() == size_t(kFrames); }, 120000) &&
               waitFor(
                   [&] {
                       const CaptureJournal* j = w.workspace()->journal();  // none once the replay ended
                       return !j || j->framesWritten() == uint64_t(kFrames);
                   },
                   60000) &&
               waitFor([&] { return w.traceDock()->model()->rowCount() == kFrames; }, 30000);
    }

    void oldestFramesReachableWithTinyBudget() {
        const QString log = writeLog(dir_.filePath(QStringLiteral("in.log")));
        QVERIFY(!log.isEmpty());
        MainWindow w;
        QVERIFY(capture(w, log));
        auto store = w.workspace()->store();

        // Scrolling to the oldest rows (Ctrl+Home in the table) shows frame 0.
        QTableView* view = w.traceDock()->view();
        TraceModel* m = w.traceDock()->model();
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, QPoint(view->viewport()->width() / 2, 5));
        // From the newest rows first: the view may still show the oldest ones when the capture
        // was quick, and the chunks of the rows shown (and of the current row) stay in memory.
        QTest::keyClick(view->viewport(), Qt::Key_End, Qt::ControlModifier);
        QVERIFY2(waitFor([&] { return !store->isResident(0); }, 30000),
                 qPrintable(QString::number(store->residentChunks())));
        QTest::keyClick(view->viewport(), Qt::Key_Home, Qt::ControlModifier);
        QVERIFY2(waitFor([&] { return view->rowAt(0) == 0; }, 10000), qPrintable(QString::number(view->rowAt(0))));
        // The row is drawn as loading while the store's loader thread reads it back, then shown.
        QVERIFY2(waitFor([&] { return cell(m, 0, TraceModel::CobId) == QStringLiteral("181"); }, 30000),
                 qPrintable(cell(m, 0, TraceModel::Summary)));
        QCOMPARE(store->frame(0).data[3], uint8_t(0));
        QCOMPARE(store->frame(kFrames - 1).data[3], uint8_t((kFrames - 1) & 0xFF));
        QVERIFY(store->pageIns() >= 1);  // frame 0 came back from the journal
        // Back within the budget (1 MiB of chunks + indexes) once the pages read are let go again
        // (evicted chunks are freed up to 1 s later, while a reader may still hold them).
        QVERIFY2(waitFor([&] { return store->memoryBytes() < (9u << 19); }, 30000),
                 qPrintable(QString::number(store->memoryBytes())));

        // Find goes back to the one EMCY among the oldest frames.
        auto* find = w.traceDock()->findChild<QLineEdit*>(QStringLiteral("findEdit"));
        QVERIFY(find);
        typeAndEnter(find, QStringLiteral("EMCY"));
        QVERIFY(waitFor(
            [&] {
                return view->currentIndex().isValid() && m->frameAt(view->currentIndex().row()) == FrameNo(kEmcyAt);
            },
            60000));

        // A filter finds it too.
        typeAndEnter(w.traceDock()->findChild<QLineEdit*>(QStringLiteral("filterEdit")), QStringLiteral("svc:emcy"));
        QVERIFY(waitFor([&] { return !w.traceDock()->isFiltering() && m->isFiltered() && m->rowCount() == 1; }, 60000));
        QCOMPARE(m->frameAt(0), FrameNo(kEmcyAt));
        // Back within the budget (1 MiB of chunks + indexes) once the pages read are let go again
        // (evicted chunks are freed up to 1 s later, while a reader may still hold them).
        QVERIFY2(waitFor([&] { return store->memoryBytes() < (9u << 19); }, 30000),
                 qPrintable(QString::number(store->memoryBytes())));

        // Save As writes every frame, the evicted ones from the journal.
        const QString out = dir_.filePath(QStringLiteral("saved.log"));
        auto name = answerFileDialog(out);
        QVERIFY(clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Save trace as")));
        QVERIFY(waitFor([&] { return name->answered(); }));
        QVERIFY(waitFor([&] { return w.saveJob() == nullptr && QFileInfo::exists(out); }, 60000));
        auto reader = logio::LogFormats::openReader(out, nullptr);
        QVERIFY(reader);
        const auto saved = reader->readAll();
        QCOMPARE(saved.size(), size_t(kFrames));
        QCOMPARE(saved[kEmcyAt].id, 0x81u);
        QCOMPARE(saved[1].data[3], uint8_t(1));
        QCOMPARE(saved[70000].data[2], uint8_t(70000 >> 8));
        QCOMPARE(store->pageErrors(), uint64_t(0));
    }

    // Find by the find field (Enter: next, the ▲ button: previous) while every frame it must
    // reach is paged out to the journal: the frame found is selected and shown.
    void findReachesPagedOutFrames() {
        const QString log = writeLog(dir_.filePath(QStringLiteral("find.log")));
        QVERIFY(!log.isEmpty());
        MainWindow w;
        QVERIFY(capture(w, log));
        auto store = w.workspace()->store();
        TraceView* view = w.traceDock()->view();
        TraceModel* m = w.traceDock()->model();
        QCOMPARE(view->currentRow(), -1);  // nothing selected: Find starts at the first row
        // The view follows the end (the chunks of its rows stay in RAM); the budget sends the
        // older chunks back to the journal.
        QVERIFY2(waitFor([&] { return !store->isResident(0) && !store->isResident(70000); }, 60000),
                 qPrintable(QString::number(store->residentChunks())));
        const uint64_t pageIns = store->pageIns();

        auto* find = w.traceDock()->findChild<QLineEdit*>(QStringLiteral("findEdit"));
        QVERIFY(find);
        typeAndEnter(find, QStringLiteral("EMCY"));  // in the summary only
        QVERIFY2(waitFor([&] { return view->currentRow() >= 0 && m->frameAt(view->currentRow()) == FrameNo(kEmcyAt); },
                         60000),
                 qPrintable(w.statusBar()->currentMessage()));
        QVERIFY(store->pageIns() > pageIns);  // read back from the journal
        QVERIFY(!find->property("missed").toBool());
        // Shown: its row is in view, with its own COB-ID once its chunk is in RAM.
        QVERIFY(waitFor([&] { return view->rowAt(view->viewport()->height() / 2) >= 0; }, 10000));
        QVERIFY(waitFor(
            [&] {
                const QModelIndex i = view->currentIndex();
                return i.isValid() && view->visualRect(i).intersects(view->viewport()->rect()) &&
                       view->model()->data(i.siblingAtColumn(TraceModel::CobId)).toString() == QStringLiteral("081");
            },
            30000));

        // Frame 70000 (data 00 01 11 70), in the second chunk, which is paged out now.
        QVERIFY(waitFor([&] { return !store->isResident(70000); }, 60000));
        QTest::keyClick(find, Qt::Key_A, Qt::ControlModifier);
        typeAndEnter(find, QStringLiteral("00 01 11 70"));
        QVERIFY2(
            waitFor([&] { return view->currentRow() >= 0 && m->frameAt(view->currentRow()) == FrameNo(70000); }, 60000),
            qPrintable(w.statusBar()->currentMessage()));

        // Back with Find previous from there: the EMCY again, its chunk paged out meanwhile.
        QVERIFY(waitFor([&] { return !store->isResident(kEmcyAt); }, 60000));
        QTest::keyClick(find, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(find, QStringLiteral("emcy"));
        auto* bar = w.traceDock()->findChild<QToolBar*>(QStringLiteral("traceToolbar"));
        QVERIFY(bar);
        QAction* prev = nullptr;
        for (QAction* a : bar->actions())
            if (a->objectName() == QStringLiteral("findPrevAction")) prev = a;
        QVERIFY(prev);
        QTest::mouseClick(bar->widgetForAction(prev), Qt::LeftButton);
        QVERIFY2(waitFor([&] { return m->frameAt(view->currentRow()) == FrameNo(kEmcyAt); }, 60000),
                 qPrintable(w.statusBar()->currentMessage()));

        // A text that is nowhere: searched to the end, then said so.
        QTest::keyClick(find, Qt::Key_A, Qt::ControlModifier);
        typeAndEnter(find, QStringLiteral("no such text"));
        QVERIFY2(waitFor([&] { return find->property("missed").toBool(); }, 120000),
                 qPrintable(w.statusBar()->currentMessage()));
        QVERIFY(w.statusBar()->currentMessage().contains(QStringLiteral("not found")));
        QCOMPARE(m->frameAt(view->currentRow()), FrameNo(kEmcyAt));
        QCOMPARE(store->pageErrors(), uint64_t(0));
    }

    // The grouped view's transfer row, its frames paged out: drawn as loading while the store's
    // loader reads them back, then its reassembled value; the GUI thread never read the disk.
    void groupedTransferRowComesBackFromTheJournal() {
        const QString log = writeLog(dir_.filePath(QStringLiteral("sdo.log")), true);
        QVERIFY(!log.isEmpty());
        MainWindow w;
        QVERIFY(capture(w, log));
        auto store = w.workspace()->store();
        store->watchPageInsOn(std::this_thread::get_id());
        TraceView* view = w.traceDock()->view();
        TraceModel* m = w.traceDock()->model();
        QVERIFY2(waitFor([&] { return !store->isResident(kSdoAt); }, 60000),
                 qPrintable(QString::number(store->residentChunks())));

        auto* bar = w.traceDock()->findChild<QToolBar*>(QStringLiteral("traceToolbar"));
        QVERIFY(bar);
        for (QAction* a : bar->actions())
            if (a->objectName() == QStringLiteral("groupSdoAction"))
                QTest::mouseClick(bar->widgetForAction(a), Qt::LeftButton);
        QVERIFY(w.traceDock()->groupsSdo());
        // One row for the six frames of the transfer.
        QVERIFY(waitFor([&] { return m->isGrouped() && m->rowCount() == kFrames - 5; }, 60000));
        QVERIFY(!store->isResident(kSdoAt));
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, QPoint(view->viewport()->width() / 2, 5));
        QTest::keyClick(view->viewport(), Qt::Key_Home, Qt::ControlModifier);
        QVERIFY(waitFor([&] { return view->rowAt(0) == 0; }, 10000));
        QCOMPARE(m->rowKind(kSdoAt), TraceModel::RowKind::Transfer);
        QVERIFY2(
            waitFor(
                [&] {
                    return cell(m, kSdoAt, TraceModel::Summary).contains(QStringLiteral("device name = COSCOPESIM"));
                },
                30000),
            qPrintable(cell(m, kSdoAt, TraceModel::Summary)));
        QCOMPARE(cell(m, kSdoAt, TraceModel::Length), QStringLiteral("10"));
        // Ctrl+Home selected the first frame, paged out when it was selected: the details pane
        // shows it once it is back.
        QCOMPARE(view->currentRow(), 0);
        QTreeWidget* details = w.traceDock()->details()->tree();
        QVERIFY2(
            waitFor(
                [&] {
                    return details->topLevelItemCount() > 0 &&
                           details->topLevelItem(0)->text(0) == QStringLiteral("Frame 1");
                },
                30000),
            qPrintable(details->topLevelItemCount() ? details->topLevelItem(0)->text(0) : QStringLiteral("(empty)")));
        // The transfer row, clicked: its reassembled value in the details.
        QTest::mouseClick(
            view->viewport(), Qt::LeftButton, {},
            view->visualRect(view->model()->index(view->traceWindow()->fromSource(kSdoAt), TraceModel::Summary))
                .center());
        QVERIFY2(waitFor(
                     [&] {
                         const auto found = details->findItems(QStringLiteral("COSCOPESIM"),
                                                               Qt::MatchContains | Qt::MatchRecursive, 1);
                         return !found.isEmpty();
                     },
                     30000),
                 qPrintable(QStringLiteral("row %1: %2 / %3")
                                .arg(view->currentRow())
                                .arg(details->topLevelItemCount() ? details->topLevelItem(0)->text(0) : QString(),
                                     details->topLevelItemCount() ? details->topLevelItem(0)->text(1) : QString())));

        // Find previous (Shift+F3) from the last row finds the transfer row by its own summary
        // ("6 frames" is in no frame's text) while its frames are paged out: a worker reads them.
        QTest::keyClick(view->viewport(), Qt::Key_End, Qt::ControlModifier);
        QVERIFY(waitFor([&] { return view->currentRow() == m->rowCount() - 1; }, 10000));
        QVERIFY2(waitFor([&] { return !store->isResident(kSdoAt); }, 60000),
                 qPrintable(QString::number(store->residentChunks())));
        auto* find = w.traceDock()->findChild<QLineEdit*>(QStringLiteral("findEdit"));
        QVERIFY(find);
        QTest::keyClick(view->viewport(), Qt::Key_F, Qt::ControlModifier);
        QTest::keyClicks(find, QStringLiteral("6 frames"));
        QTest::keyClick(find, Qt::Key_F3, Qt::ShiftModifier);
        QVERIFY2(waitFor([&] { return view->currentRow() == kSdoAt; }, 60000),
                 qPrintable(w.statusBar()->currentMessage()));
        QCOMPARE(m->rowKind(kSdoAt), TraceModel::RowKind::Transfer);
        QCOMPARE(store->watchedPageIns(), uint64_t(0));
        QCOMPARE(store->pageErrors(), uint64_t(0));
    }
};

QTEST_MAIN(TestTracePagingGui)
#include "test_trace_paging_gui.moc"
