// SPDX-License-Identifier: GPL-3.0-or-later
// Bounded memory in the app (issue 16): with a tiny trace budget (trace/memoryBudgetMB = 1) a
// live capture of several chunks keeps only a few in RAM, and yet scrolling to the top, Find,
// a filter and Save As reach the oldest frames, which come back from the capture journal.
#include "app/gui/MainWindow.h"
#include "app/gui/session/MemoryBudget.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "core/logio/LogFormats.h"
#include "core/trace/CaptureJournal.h"
#include "eds/SimulatorDictionaries.h"

#include <QFile>
#include <QFileInfo>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QTableView>
#include <QTemporaryDir>
#include <QtTest>

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

// TPDO1 of node 1 carrying its frame number; one EMCY of node 1 near the start.
QString writeLog(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    QByteArray out;
    for (int i = 0; i < kFrames; ++i) {
        out += "(1700000000." + QByteArray::number(i).rightJustified(6, '0') + ") can0 ";
        out += i == kEmcyAt ? QByteArray("081#1023050000000000") : "181#" + QByteArray::number(i, 16).rightJustified(8, '0').toUpper();
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

    void oldestFramesReachableWithTinyBudget() {
        const QString log = writeLog(dir_.filePath(QStringLiteral("in.log")));
        QVERIFY(!log.isEmpty());
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        // A live capture (through the journal) as fast as the capture path takes it.
        QVERIFY(w.connectBus(QStringLiteral("replay://") + log + QStringLiteral("?speed=0")));
        auto store = w.workspace()->store();
        QVERIFY(waitFor([&] { return store->size() == size_t(kFrames); }, 60000));
        QVERIFY(waitFor([&] {
            const CaptureJournal* j = w.workspace()->journal();  // none once the replay ended
            return !j || j->framesWritten() == uint64_t(kFrames);
        }, 20000));
        QVERIFY(waitFor([&] { return w.traceDock()->model()->rowCount() == kFrames; }, 10000));

        // Scrolling to the oldest rows (Ctrl+Home in the table) shows frame 0.
        QTableView* view = w.traceDock()->view();
        TraceModel* m = w.traceDock()->model();
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, QPoint(view->viewport()->width() / 2, 5));
        QTest::keyClick(view->viewport(), Qt::Key_Home, Qt::ControlModifier);
        QVERIFY2(waitFor([&] { return view->rowAt(0) == 0; }, 3000), qPrintable(QString::number(view->rowAt(0))));
        // The row is drawn as loading while the store's loader thread reads it back, then shown.
        QVERIFY2(waitFor([&] { return cell(m, 0, TraceModel::CobId) == QStringLiteral("181"); }, 10000), qPrintable(cell(m, 0, TraceModel::Summary)));
        QCOMPARE(store->frame(0).data[3], uint8_t(0));
        QCOMPARE(store->frame(kFrames - 1).data[3], uint8_t((kFrames - 1) & 0xFF));
        QVERIFY(store->pageIns() >= 1);  // frame 0 came back from the journal
        // Back within the budget (1 MiB of chunks + indexes) once the pages read are let go again
        // (evicted chunks are freed up to 1 s later, while a reader may still hold them).
        QVERIFY2(waitFor([&] { return store->memoryBytes() < (9u << 19); }, 5000), qPrintable(QString::number(store->memoryBytes())));

        // Find goes back to the one EMCY among the oldest frames.
        auto* find = w.traceDock()->findChild<QLineEdit*>(QStringLiteral("findEdit"));
        QVERIFY(find);
        typeAndEnter(find, QStringLiteral("EMCY"));
        QVERIFY(waitFor([&] { return view->currentIndex().isValid() && m->frameAt(view->currentIndex().row()) == FrameNo(kEmcyAt); }, 20000));

        // A filter finds it too.
        typeAndEnter(w.traceDock()->findChild<QLineEdit*>(QStringLiteral("filterEdit")), QStringLiteral("svc:emcy"));
        QVERIFY(waitFor([&] { return !w.traceDock()->isFiltering() && m->isFiltered() && m->rowCount() == 1; }, 30000));
        QCOMPARE(m->frameAt(0), FrameNo(kEmcyAt));
        // Back within the budget (1 MiB of chunks + indexes) once the pages read are let go again
        // (evicted chunks are freed up to 1 s later, while a reader may still hold them).
        QVERIFY2(waitFor([&] { return store->memoryBytes() < (9u << 19); }, 5000), qPrintable(QString::number(store->memoryBytes())));

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
};

QTEST_MAIN(TestTracePagingGui)
#include "test_trace_paging_gui.moc"
