// SPDX-License-Identifier: GPL-3.0-or-later
// Opening a log that skips lines, or yields no frame, says so in the Trace dock: the format
// taken, lines read and skipped, and the first skipped lines with their numbers and why.
#include "app/gui/MainWindow.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/LogLoadJob.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "eds/SimulatorDictionaries.h"

#include <QFile>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::answerFileDialog;
using coscope::testing::clickMenuItem;
using coscope::testing::waitFor;

namespace {
// File ▸ item, by clicks on the menu bar and the menu.

// Opens `path` by File ▸ Open log… and its file dialog; waits until it is read.
bool openByMenu(MainWindow& w, const QString& path) {
    auto name = answerFileDialog(path);
    if (!clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Open log")) ||
        !waitFor([&] { return name->answered(); }))
        return false;
    w.activateWindow();
    if (!QTest::qWaitForWindowActive(&w)) return false;
    return waitFor([&] { return w.workspace()->loadJob() && w.workspace()->loadJob()->isDone(); });
}

QWidget* report(MainWindow& w) { return w.traceDock()->findChild<QWidget*>(QStringLiteral("loadReport")); }
QString reportText(MainWindow& w) {
    auto* label = w.traceDock()->findChild<QLabel*>(QStringLiteral("loadReportText"));
    return label ? label->text() : QString();
}
}  // namespace

class TestLogLoadReport : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_log_load_report"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
        QVERIFY(dir_.isValid());
    }

    // A BUSMASTER log with two bad lines: the frames load, and the dock says what was skipped.
    void skippedLinesAreExplained() {
        const QString path = dir_.filePath(QStringLiteral("bench.log"));
        QVERIFY(QFile::copy(QStringLiteral(COSCOPE_SOURCE_DIR "/tests/data/logs/busmaster_v3_hex_system.log"), path));
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openByMenu(w, path));
        QVERIFY(waitFor([&] { return report(w) && report(w)->isVisible(); }));
        const QString text = reportText(w);
        QVERIFY2(text.contains(QStringLiteral("busmaster")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("22 lines, 5 frames, 2 lines skipped")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("line 18: bad time")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("line 19:")), qPrintable(text));
        QCOMPARE(w.traceDock()->model()->rowCount(), 5);
        // The report closes by its button.
        auto* close = report(w)->findChild<QToolButton*>(QStringLiteral("loadReportClose"));
        QVERIFY(close);
        QTest::mouseClick(close, Qt::LeftButton);
        QVERIFY(!report(w)->isVisible());
    }

    // A text file that is no log is refused (what was shown stays, issue 36) and the Trace dock
    // says why: no format CoScope reads, and which were tried (issue 37).
    void noLogIsRefusedWithTheFormatsTried() {
        const QString path = dir_.filePath(QStringLiteral("notes.log"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("Meeting notes\nnode 5 reboots at power-up\n");
        f.close();
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        auto name = answerFileDialog(path);
        QVERIFY(clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Open log")));
        QVERIFY(waitFor([&] { return name->answered(); }));
        QVERIFY(waitFor([&] { return report(w) && report(w)->isVisible(); }));
        QVERIFY(!w.workspace()->loadJob());  // refused before anything was thrown away
        const QString text = reportText(w);
        QVERIFY2(text.contains(QStringLiteral("notes.log: not a format CoScope reads")) &&
                     text.contains(QStringLiteral("BUSMASTER")),
                 qPrintable(text));
        QCOMPARE(w.traceDock()->model()->rowCount(), 0);
    }
};

QTEST_MAIN(TestLogLoadReport)
#include "test_log_load_report.moc"
