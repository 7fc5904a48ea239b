// SPDX-License-Identifier: GPL-3.0-or-later
// Find in the trace's grouped view (SDO transfers as one row, issue #6): a transfer's row is
// found by its own texts, the ones the user sees in it (the reassembled summary), forward (Enter,
// F3) and backward (Shift+F3); the frames of an expanded transfer are rows in the order shown;
// the frames of a collapsed one are not shown, so not found.
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "app/gui/trace/TraceView.h"
#include "core/can/CanFrame.h"
#include "eds/SimulatorDictionaries.h"

#include <QFile>
#include <QLineEdit>
#include <QTemporaryDir>
#include <QToolBar>
#include <QtTest>

#include "tests/gui/TypeText.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::typeAndEnter;

namespace {

CanFrame at(int64_t ms, uint32_t id, std::vector<uint8_t> b) {
    CanFrame f = CanFrame::classic(id, {});
    f.len = static_cast<uint8_t>(b.size());
    std::copy(b.begin(), b.end(), f.data.begin());
    f.timestampNs = 1'700'000'000'000'000'000LL + ms * 1'000'000;
    return f;
}

// Three transfers of node 5 (CiA 301 §7.2.4.3): A an expedited upload of 1000h, B a segmented
// upload of 1008h "CoScope Dr1" with a heartbeat among its frames, D an upload of 3000h aborted.
std::vector<CanFrame> trace() {
    return {
        at(0, 0x705, {0x05}),                                             // 0 heartbeat
        at(1, 0x605, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}),               // 1 A: upload 1000h
        at(2, 0x585, {0x43, 0x00, 0x10, 0x00, 0x92, 0x01, 0x02, 0x00}),   // 2 A: expedited, 4 bytes
        at(3, 0x186, {1, 2, 3, 4}),                                       // 3 TPDO1 node 6
        at(4, 0x605, {0x40, 0x08, 0x10, 0x00, 0, 0, 0, 0}),               // 4 B: upload 1008h
        at(5, 0x585, {0x41, 0x08, 0x10, 0x00, 11, 0, 0, 0}),              // 5 B: segmented, 11 bytes
        at(6, 0x605, {0x60, 0, 0, 0, 0, 0, 0, 0}),                        // 6 B: segment request t=0
        at(7, 0x585, {0x00, 'C', 'o', 'S', 'c', 'o', 'p', 'e'}),          // 7 B: 7 bytes t=0
        at(8, 0x705, {0x05}),                                             // 8 heartbeat
        at(9, 0x605, {0x70, 0, 0, 0, 0, 0, 0, 0}),                        // 9 B: segment request t=1
        at(10, 0x585, {0x17, ' ', 'D', 'r', '1', 0, 0, 0}),               // 10 B: last, 4 bytes t=1
        at(11, 0x705, {0x05}),                                            // 11 heartbeat
        at(12, 0x605, {0x40, 0x00, 0x30, 0x00, 0, 0, 0, 0}),              // 12 D: upload 3000h
        at(13, 0x585, {0x80, 0x00, 0x30, 0x00, 0x00, 0x00, 0x02, 0x06}),  // 13 D: abort 06020000h
        at(14, 0x705, {0x05}),                                            // 14 heartbeat
    };
}

bool waitFor(const std::function<bool()>& done, TraceDock& dock, int ms = 10000) {
    QElapsedTimer t;
    t.start();
    while (!done()) {
        if (t.elapsed() > ms) return false;
        QTest::qWait(10);
        dock.refresh();
    }
    return true;
}

}  // namespace

class TestTraceFindGrouped : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        eds::installSimulatorDictionaries();
        QVERIFY(dir_.isValid());
    }

    void findMatchesWhatTheRowsShow() {
        const QString path = dir_.filePath(QStringLiteral("sdo.log"));
        {
            QFile file(path);
            QVERIFY(file.open(QIODevice::WriteOnly));
            for (const CanFrame& f : trace()) file.write((formatCandumpL(f, u"can0") + u'\n').toUtf8());
        }
        Workspace ws;
        TraceDock dock(&ws);
        dock.resize(1200, 700);
        dock.show();
        QVERIFY(QTest::qWaitForWindowActive(&dock));
        QString error;
        QVERIFY2(ws.openLog(path, &error), qPrintable(error));
        dock.rebind();
        TraceModel* m = dock.model();
        QVERIFY(waitFor([&] { return ws.loadJob() && ws.loadJob()->isDone() && m->rowCount() == 15; }, dock));
        auto* bar = dock.findChild<QToolBar*>(QStringLiteral("traceToolbar"));
        QVERIFY(bar);
        QTest::mouseClick(bar->widgetForAction(dock.groupSdoAction()), Qt::LeftButton);
        QVERIFY(waitFor([&] { return !dock.isFiltering() && m->isGrouped(); }, dock));
        // 0, A, 3, B, 8, 11, D, 14
        QCOMPARE(m->rowCount(), 8);
        QCOMPARE(m->rowKind(3), TraceModel::RowKind::Transfer);
        QVERIFY(
            m->data(m->index(3, TraceModel::Summary), Qt::DisplayRole).toString().contains(QStringLiteral("6 frames")));
        TraceView* view = dock.view();
        auto* find = dock.findChild<QLineEdit*>(QStringLiteral("findEdit"));
        QVERIFY(find);
        const auto current = [&] { return view->currentRow(); };

        // Text only in B's row (its summary): found, B's row selected.
        typeAndEnter(find, QStringLiteral("6 frames"));
        QVERIFY2(waitFor([&] { return current() == 3; }, dock), qPrintable(QString::number(current())));
        QVERIFY(!find->property("missed").toBool());
        // The reassembled value, split over two frames.
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {},
                          view->visualRect(view->model()->index(0, TraceModel::Summary)).center());
        QCOMPARE(current(), 0);
        typeAndEnter(find, QStringLiteral("coscope dr1"));
        QVERIFY2(waitFor([&] { return current() == 3; }, dock), qPrintable(QString::number(current())));

        // "2 frames": A (row 1) and D (row 6). Enter from B: D; Shift+F3: A; F3: D; F3: none after.
        typeAndEnter(find, QStringLiteral("2 frames"));
        QVERIFY2(waitFor([&] { return current() == 6; }, dock), qPrintable(QString::number(current())));
        QTest::keyClick(find, Qt::Key_F3, Qt::ShiftModifier);
        QVERIFY2(waitFor([&] { return current() == 1; }, dock), qPrintable(QString::number(current())));
        QTest::keyClick(find, Qt::Key_F3);
        QVERIFY2(waitFor([&] { return current() == 6; }, dock), qPrintable(QString::number(current())));
        QTest::keyClick(find, Qt::Key_F3);
        QVERIFY(waitFor([&] { return find->property("missed").toBool(); }, dock));
        QCOMPARE(current(), 6);
        // The aborted transfer's data text (the abort code) is in its row, backward too.
        QTest::keyClick(view->viewport(), Qt::Key_End, Qt::ControlModifier);
        QCOMPARE(current(), 7);
        QTest::keyClick(view->viewport(), Qt::Key_F, Qt::ControlModifier);  // Ctrl+F: to the find field
        QVERIFY(find->hasFocus());
        QTest::keyClicks(find, QStringLiteral("06020000"));
        QTest::keyClick(find, Qt::Key_F3, Qt::ShiftModifier);
        QVERIFY2(waitFor([&] { return current() == 6; }, dock), qPrintable(QString::number(current())));

        // Expand B (click its arrow): its six frames are rows 4..9, the heartbeat 8 row 10.
        const QRect arrow = view->visualRect(view->model()->index(3, TraceModel::Number));
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, arrow.center());
        QCOMPARE(m->rowCount(), 14);
        QCOMPARE(m->frameAt(10), FrameNo(8));
        QCOMPARE(current(), 3);
        // COB-ID 585: the server's frames of B, in row order; A's row shows 605 and hides its 585.
        QTest::keyClick(view->viewport(), Qt::Key_End, Qt::ControlModifier);
        QCOMPARE(current(), 13);
        typeAndEnter(find, QStringLiteral("585"));  // forward from the last row: none
        QVERIFY(waitFor([&] { return find->property("missed").toBool(); }, dock));
        for (const int row : {9, 7, 5}) {
            QTest::keyClick(find, Qt::Key_F3, Qt::ShiftModifier);
            QVERIFY2(waitFor([&] { return current() == row; }, dock),
                     qPrintable(QStringLiteral("%1 for %2").arg(current()).arg(row)));
        }
        QTest::keyClick(find, Qt::Key_F3, Qt::ShiftModifier);
        QVERIFY(waitFor([&] { return find->property("missed").toBool(); }, dock));
        QCOMPARE(current(), 5);
        // The heartbeat after B's frames on screen (frame 8, between them in time) comes after them.
        typeAndEnter(find, QStringLiteral("705"));
        QVERIFY2(waitFor([&] { return current() == 10; }, dock), qPrintable(QString::number(current())));
        QTest::keyClick(find, Qt::Key_F3, Qt::ShiftModifier);
        QVERIFY2(waitFor([&] { return current() == 0; }, dock), qPrintable(QString::number(current())));
    }
};

QTEST_MAIN(TestTraceFindGrouped)
#include "test_trace_find_grouped.moc"
