// SPDX-License-Identifier: GPL-3.0-or-later
// Resident memory flat in the live trace (issue 16 "Bounded memory"): the trace's table shows a
// window of at most about trace/windowRows rows (Qt keeps bytes per row in its views), set small
// here, and yet a live capture of many times that is followed to its newest frame, and End, Home,
// PgDn, the wheel, the trace's scroll bar and Find reach every frame with its own number, the details
// pane showing the selected one.
#include "app/gui/MainWindow.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/FrameDetailsView.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "eds/SimulatorDictionaries.h"

#include <QFile>
#include <QHeaderView>
#include <QLineEdit>
#include <QScrollBar>
#include <QSettings>
#include <QTableView>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QWheelEvent>
#include <QtTest>

#include "tests/gui/TypeText.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::typeAndEnter;
using coscope::testing::waitFor;

namespace {
constexpr int kWindowRows = 2000;
constexpr int kMaxRows = kWindowRows * 3 / 2;  // the window grows at the tail up to this
constexpr int kFrames = 40000;                 // 20 windows

// TPDO1 of node 1 carrying its frame number, 100 µs apart: 4 s of live capture at speed 1.
QString writeLog(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    QByteArray out;
    for (int i = 0; i < kFrames; ++i) {
        const qint64 us = qint64(i) * 100;
        out += '(' + QByteArray::number(1700000000 + us / 1000000) + '.' +
               QByteArray::number(us % 1000000).rightJustified(6, '0') + ") can0 ";
        out += "181#" + QByteArray::number(i, 16).rightJustified(8, '0').toUpper() + '\n';
    }
    f.write(out);
    return path;
}

// The frame number drawn in the row at viewport height y (0 when no row is there).
qulonglong numberAt(QTableView* view, int y) {
    const QModelIndex i = view->indexAt(QPoint(5, y));
    return i.isValid() ? view->model()->index(i.row(), TraceModel::Number).data().toULongLong() : 0;
}
qulonglong topNumber(QTableView* view) { return numberAt(view, 2); }
qulonglong bottomNumber(QTableView* view) {
    const int y = view->viewport()->height() - 2;
    for (int dy = 0; dy < 40; dy += 2)
        if (const qulonglong n = numberAt(view, y - dy)) return n;
    return 0;
}
qulonglong currentNumber(QTableView* view) {
    const QModelIndex i = view->currentIndex();
    return i.isValid() ? view->model()->index(i.row(), TraceModel::Number).data().toULongLong() : 0;
}
QString detailsTitle(TraceDock* dock) {
    QTreeWidget* tree = dock->details()->tree();
    return tree->topLevelItemCount() > 0 ? tree->topLevelItem(0)->text(0) : QString();
}
void wheelDown(QWidget* viewport, int notches) {
    const QPointF at(viewport->width() / 2.0, viewport->height() / 2.0);
    for (int i = 0; i < notches; ++i) {
        QWheelEvent e(at, viewport->mapToGlobal(at), QPoint(), QPoint(0, -120), Qt::NoButton, Qt::NoModifier,
                      Qt::NoScrollPhase, false);
        QApplication::sendEvent(viewport, &e);
    }
}

}  // namespace

class TestTraceWindow : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        qputenv("XDG_DATA_HOME", dir_.path().toUtf8());  // this test's own journal folder
        eds::installSimulatorDictionaries();
        QSettings().setValue(QStringLiteral("trace/windowRows"), kWindowRows);
    }
    void cleanupTestCase() { QSettings().remove(QStringLiteral("trace/windowRows")); }

    void viewRowsStayBoundedAndEveryFrameIsReachable() {
        const QString log = writeLog(dir_.filePath(QStringLiteral("in.log")));
        QVERIFY(!log.isEmpty());
        MainWindow w;
        w.setQuiet(true);
        w.resize(1200, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        TraceDock* dock = w.traceDock();
        QTableView* view = dock->view();
        QVERIFY(w.connectBus(QStringLiteral("replay://") + log + QStringLiteral("?speed=1")));
        auto store = w.workspace()->store();

        // While capturing: the view follows the newest frames, far past the first window, and
        // holds no more rows than the window.
        QVERIFY(waitFor([&] { return store->size() > size_t(4 * kMaxRows); }, 30000));
        QVERIFY2(view->model()->rowCount() <= kMaxRows, qPrintable(QString::number(view->model()->rowCount())));
        QVERIFY(view->verticalHeader()->count() <= kMaxRows);
        QVERIFY2(waitFor([&] { return bottomNumber(view) > qulonglong(4 * kMaxRows); }, 3000),
                 qPrintable(QString::number(bottomNumber(view))));
        // At the end of the capture the newest frame is the last row shown.
        QVERIFY(
            waitFor([&] { return store->size() == size_t(kFrames) && dock->model()->rowCount() == kFrames; }, 60000));
        QVERIFY2(waitFor([&] { return bottomNumber(view) == qulonglong(kFrames); }, 3000),
                 qPrintable(QString::number(bottomNumber(view))));
        QVERIFY(view->model()->rowCount() <= kMaxRows);
        QVERIFY(view->verticalHeader()->count() <= kMaxRows);

        // A click on a row selects it; End goes to the last frame, Home to the first.
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {},
                          QPoint(view->viewport()->width() / 2, view->viewport()->height() / 2));
        QVERIFY(view->currentIndex().isValid());
        QTest::keyClick(view, Qt::Key_End);
        QCOMPARE(currentNumber(view), qulonglong(kFrames));
        QVERIFY(waitFor([&] { return detailsTitle(dock) == QStringLiteral("Frame %1").arg(kFrames); }, 3000));
        QTest::keyClick(view, Qt::Key_Home);
        QCOMPARE(currentNumber(view), qulonglong(1));
        QCOMPARE(topNumber(view), qulonglong(1));
        QVERIFY(waitFor([&] { return detailsTitle(dock) == QStringLiteral("Frame 1"); }, 3000));
        QTest::qWait(200);  // a few refresh ticks: the view stays where the keys took it
        QCOMPARE(topNumber(view), qulonglong(1));

        // PgDn pages on across the window's edges: each press a page further, numbers in order.
        QTest::keyClick(view, Qt::Key_PageDown);
        const qulonglong page = currentNumber(view) - 1;
        QVERIFY(page > 3);
        const int presses = 3 * kWindowRows / int(page);
        for (int i = 2; i <= presses; ++i) {
            QTest::keyClick(view, Qt::Key_PageDown);
            QCOMPARE(currentNumber(view), 1 + qulonglong(i) * page);
        }
        QVERIFY(currentNumber(view) > qulonglong(2 * kMaxRows));
        QVERIFY(
            waitFor([&] { return detailsTitle(dock) == QStringLiteral("Frame %1").arg(currentNumber(view)); }, 3000));
        QTest::keyClick(view, Qt::Key_Down);
        QCOMPARE(currentNumber(view), 2 + qulonglong(presses) * page);
        QVERIFY(view->model()->rowCount() <= kMaxRows);

        // The wheel scrolls three rows a notch, across the window's edges too.
        QTest::keyClick(view, Qt::Key_Home);
        QCOMPARE(topNumber(view), qulonglong(1));
        wheelDown(view->viewport(), kWindowRows);  // 3 windows
        QCOMPARE(topNumber(view), 1 + qulonglong(3 * kWindowRows));
        QCOMPARE(detailsTitle(dock), QStringLiteral("Frame 1"));  // the selection stays on its frame
        QVERIFY(view->model()->rowCount() <= kMaxRows);

        // The trace's scroll bar spans every frame: its end shows the last, its start the first.
        auto* bar = dock->findChild<QScrollBar*>(QStringLiteral("traceScrollBar"));
        QVERIFY(bar && bar->isVisible());
        QTest::keyClick(bar, Qt::Key_End);
        QCOMPARE(bottomNumber(view), qulonglong(kFrames));
        QTest::keyClick(bar, Qt::Key_Home);
        QCOMPARE(topNumber(view), qulonglong(1));
        QVERIFY(view->model()->rowCount() <= kMaxRows);
        QVERIFY(view->verticalHeader()->count() <= kMaxRows);
        // Back to the selected frame, kept through the window's moves.
        QTest::keyClick(view, Qt::Key_Down);
        QCOMPARE(currentNumber(view), qulonglong(2));
        QVERIFY(waitFor([&] { return detailsTitle(dock) == QStringLiteral("Frame 2"); }, 3000));

        // Find reaches a frame many windows away (frame 40000 carries 0x9C3F): it is selected,
        // shown with its own number, its details in the pane.
        // (A long search goes on on a worker, which selects the frame when done: wait for it.)
        typeAndEnter(dock->findChild<QLineEdit*>(QStringLiteral("findEdit")), QStringLiteral("00 9C 3F"));
        QVERIFY2(waitFor([&] { return currentNumber(view) == qulonglong(kFrames); }, 30000),
                 qPrintable(QString::number(currentNumber(view))));
        QVERIFY(waitFor([&] { return detailsTitle(dock) == QStringLiteral("Frame %1").arg(kFrames); }, 3000));
        QVERIFY(view->model()->rowCount() <= kMaxRows);
    }
};

QTEST_MAIN(TestTraceWindow)
#include "test_trace_window.moc"
