// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 16 "Lost adapter": the gaps of a capture survive File ▸ Save trace as. A Vector ASC with
// a gap comment opens with the gap in the trace; saved to ASC the gap is there again; saved to
// candump, which cannot hold it, the window asks first (Cancel writes nothing, "Save anyway"
// writes every frame).
#include "app/gui/MainWindow.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/LogSaveJob.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "app/gui/trace/TraceView.h"
#include "core/logio/LogFormats.h"

#include <QFileInfo>
#include <QLineEdit>
#include <QMessageBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/TypeText.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::answerBox;
using coscope::testing::answerFileDialog;
using coscope::testing::clickMenuItem;
using coscope::testing::typeAndEnter;
using coscope::testing::waitFor;

namespace {
constexpr int64_t kT0 = 1700000000000000000LL;
constexpr int64_t kLost = kT0 + 5000000, kBack = kT0 + 3005000000LL;
constexpr int kFrames = 12, kGapBefore = 5;

constexpr int64_t kLost2 = kBack + 1000000, kBack2 = kBack + 2000000;  // lost again at once

// `twice`: the adapter lost again right after it came back, before frame kGapBefore arrived.
bool writeAscWithGap(const QString& path, bool twice = false) {
    auto w = logio::LogFormats::createWriter(QStringLiteral("asc"));
    if (!w->open(path)) return false;
    for (int i = 0; i < kFrames; ++i) {
        CanFrame f;
        f.timestampNs = kT0 + i * 1000000LL + (i >= kGapBefore ? 3000000000LL : 0);
        f.id = 0x181;
        f.len = 2;
        f.data[0] = uint8_t(i);
        if (i == kGapBefore) w->markGap(kLost, kBack);
        if (i == kGapBefore && twice) w->markGap(kLost2, kBack2);
        w->write(f);
    }
    return w->close();
}
}  // namespace

class TestSaveGaps : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    // File ▸ `item` with `path` typed into its file dialog.
    bool chooseFile(MainWindow& w, const QString& item, const QString& path) {
        auto name = answerFileDialog(path);
        if (!clickMenuItem(w, QStringLiteral("File"), item) || !waitFor([&] { return name->answered(); })) return false;
        w.activateWindow();  // offscreen there is no window manager to give the focus back
        return QTest::qWaitForWindowActive(&w);
    }

private slots:
    void saveAsKeepsOrAsksAboutGaps() {
        const QString in = dir_.filePath(QStringLiteral("gap.asc"));
        QVERIFY(writeAscWithGap(in));
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));

        // Reopening an ASC with a gap comment shows the gap.
        QVERIFY(chooseFile(w, QStringLiteral("Open log"), in));
        QVERIFY(waitFor([&] {
            return w.workspace()->loadJob() && w.workspace()->loadJob()->isDone() &&
                   w.traceDock()->model()->rowCount() > 0;
        }));
        QCOMPARE(w.workspace()->store()->size(), size_t(kFrames));
        QCOMPARE(w.workspace()->store()->gaps().size(), size_t(1));
        QCOMPARE(w.workspace()->store()->gaps()[0].firstFrame, FrameNo(kGapBefore));
        QCOMPARE(w.workspace()->store()->gaps()[0].lostNs, kLost);
        // Find (the find field, Enter) reaches the row by the gap's text it shows.
        auto* find = w.traceDock()->findChild<QLineEdit*>(QStringLiteral("findEdit"));
        QVERIFY(find);
        typeAndEnter(find, QStringLiteral("bus lost at"));
        QVERIFY2(waitFor([&] { return w.traceDock()->view()->currentRow() == kGapBefore; }),
                 qPrintable(w.statusBar()->currentMessage()));

        // To candump: the question; Cancel saves nothing.
        const QString log = dir_.filePath(QStringLiteral("out.log"));
        {
            QString asked;
            auto box = answerBox(QMessageBox::Cancel, &asked);
            QVERIFY(chooseFile(w, QStringLiteral("Save trace as"), log));
            QVERIFY(waitFor([&] { return box->answered(); }));
            QVERIFY2(asked.contains(QStringLiteral("1 gap")) &&
                         asked.contains(QStringLiteral("candump format cannot hold them")),
                     qPrintable(asked));
            QTest::qWait(200);
            QVERIFY(w.saveJob() == nullptr || w.saveJob()->isDone());
            QVERIFY(!QFileInfo::exists(log));
        }
        // "Save anyway" saves every frame.
        {
            QString asked;
            auto box = answerBox(QMessageBox::Save, &asked);
            QVERIFY(chooseFile(w, QStringLiteral("Save trace as"), log));
            QVERIFY(waitFor([&] { return box->answered(); }));
            QVERIFY(waitFor([&] { return w.saveJob() == nullptr && QFileInfo::exists(log); }));
            QString error;
            auto reader = logio::LogFormats::openReader(log, &error);
            QVERIFY2(reader, qPrintable(error));
            QCOMPARE(reader->readAll().size(), size_t(kFrames));
        }
        // To ASC: no question, and the gap is in the file.
        const QString asc = dir_.filePath(QStringLiteral("out.asc"));
        {
            QString asked;
            auto box = answerBox(QMessageBox::Cancel, &asked);
            QVERIFY(chooseFile(w, QStringLiteral("Save trace as"), asc));
            QVERIFY(waitFor([&] { return w.saveJob() == nullptr && QFileInfo::exists(asc); }));
            QVERIFY2(!box->answered(), qPrintable(asked));
        }
        QString error;
        auto reader = logio::LogFormats::openReader(asc, &error);
        QVERIFY2(reader, qPrintable(error));
        QCOMPARE(reader->readAll().size(), size_t(kFrames));
        QCOMPARE(reader->gaps().size(), size_t(1));
        QCOMPARE(reader->gaps()[0].frame, uint64_t(kGapBefore));
        QCOMPARE(reader->gaps()[0].backNs, kBack);
    }

    // Two gaps before one frame: both in the trace, both in the pcapng Save As writes (two
    // comments of that packet), each with its own times, in order.
    void twoGapsBeforeOneFrameSurviveSaveAs() {
        const QString in = dir_.filePath(QStringLiteral("gaps2.asc"));
        QVERIFY(writeAscWithGap(in, true));
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(chooseFile(w, QStringLiteral("Open log"), in));
        QVERIFY(waitFor([&] {
            return w.workspace()->loadJob() && w.workspace()->loadJob()->isDone() &&
                   w.traceDock()->model()->rowCount() > 0;
        }));
        QCOMPARE(w.workspace()->store()->gaps().size(), size_t(2));
        const QString out = dir_.filePath(QStringLiteral("out2.pcapng"));
        QVERIFY(chooseFile(w, QStringLiteral("Save trace as"), out));
        QVERIFY(waitFor([&] { return w.saveJob() == nullptr && QFileInfo::exists(out); }));
        QString error;
        auto reader = logio::LogFormats::openReader(out, &error);
        QVERIFY2(reader, qPrintable(error));
        QCOMPARE(reader->readAll().size(), size_t(kFrames));
        QCOMPARE(reader->gaps().size(), size_t(2));
        QCOMPARE(reader->gaps()[0].frame, uint64_t(kGapBefore));
        QCOMPARE(reader->gaps()[1].frame, uint64_t(kGapBefore));
        QCOMPARE(reader->gaps()[0].lostNs, kLost);
        QCOMPARE(reader->gaps()[1].lostNs, kLost2);
        QCOMPARE(reader->gaps()[1].backNs, kBack2);
    }
};

QTEST_MAIN(TestSaveGaps)
#include "test_save_gaps.moc"
