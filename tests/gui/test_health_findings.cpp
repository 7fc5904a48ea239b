// SPDX-License-Identifier: GPL-3.0-or-later
// The Health view's findings lead to their frames (issue 37): a log where node 5's heartbeat
// (100 ms, CiA 301 §7.2.8.3.2) stops twice for 600 ms; the user opens it, clicks the Health tab,
// clicks the finding and the trace shows the frame that ended the first gap; F8 (Next
// occurrence) moves to the second, the Previous occurrence button back. The detail pane explains
// the finding, the verdict is on top. And the rule sentences listed for lupdate are the rule
// table's (dissectors/HealthRules.cpp), so the GUI can translate every one.
#include "app/gui/MainWindow.h"
#include "app/gui/health/HealthDock.h"
#include "app/gui/health/HealthModel.h"
#include "app/gui/health/HealthRuleText.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "app/gui/trace/TraceView.h"
#include "dissectors/HealthRules.h"
#include "tests/gui/ItemClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/WaitFor.h"

#include <QFile>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::waitFor;

class HealthFindingsTest : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    // 40 steps of 100 ms: node 6 (706h) then node 5 (705h) beat, operational (05h); node 5 is
    // silent in steps 10-14 and 25-29. Frame indexes (0-based): step i starts at 2i less the
    // skipped beats, so node 5's beats that end the gaps are frames 26 (step 15) and 51 (step 30);
    // the trace numbers them 27 and 52.
    QString writeLog() {
        const QString path = dir_.filePath(QStringLiteral("gaps.log"));
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly)) return {};
        for (int i = 0; i < 40; ++i) {
            const double t = 1.0 + i * 0.1;
            f.write(QStringLiteral("(%1) can0 706#05\n").arg(t, 0, 'f', 6).toUtf8());
            if ((i >= 10 && i < 15) || (i >= 25 && i < 30)) continue;
            f.write(QStringLiteral("(%1) can0 705#05\n").arg(t + 0.0005, 0, 'f', 6).toUtf8());
        }
        return path;
    }
    static FrameNo currentTraceFrame(MainWindow& w) {
        const QModelIndex i = w.traceDock()->view()->currentIndex();
        return i.isValid() ? w.traceDock()->model()->frameAt(i.row()) : FrameNo(~0u);
    }

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_health_findings"));
        QSettings().clear();
        QVERIFY(dir_.isValid());
    }

    void ruleSentencesAreListedForTranslation() {
        QSet<QString> listed;
        for (const char* s : healthRuleTexts()) listed.insert(QString::fromUtf8(s));
        int n = 0;
        for (const dissect::HealthRule& r : dissect::healthRules())
            for (const char* s : {r.what, r.why, r.check}) {
                QVERIFY2(listed.contains(QString::fromUtf8(s)), s);
                ++n;
            }
        QCOMPARE(listed.size(), n);
    }

    void clickLeadsToFramesAndStepsThroughThem() {
        const QString log = writeLog();
        QVERIFY(!log.isEmpty());
        MainWindow w;
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openLog(log));
        HealthDock* dock = w.healthDock();
        QVERIFY(testing::clickDockTab(w, dock->windowTitle()));
        QVERIFY(waitFor([&] { return dock->isVisible(); }, 3000));
        HealthModel* findings = dock->findingsModel();
        QVERIFY2(waitFor([&] { return findings->rowCount() > 0 && findings->report().bus.frames == 70; }, 10000),
                 qPrintable(QString::number(findings->rowCount())));
        // The verdict on top: one error (the lost heartbeat), nothing else.
        QCOMPARE(dock->verdictLabel()->text(), QStringLiteral("Problems found: 1 error"));
        const dissect::HealthFinding& f = findings->report().findings.front();
        QCOMPARE(f.rule, QStringLiteral("heartbeat.lost"));
        QCOMPARE(f.at.frames, (std::vector<uint64_t>{26, 51}));

        // Click the finding: the trace selects the frame that ended the first gap.
        QTableView* view = dock->findingsView();
        const QRect cell = view->visualRect(findings->index(0, HealthModel::Text));
        QVERIFY(cell.isValid());
        QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, cell.center());
        QVERIFY2(waitFor([&] { return currentTraceFrame(w) == 26; }, 5000),
                 qPrintable(QString::number(currentTraceFrame(w))));
        QVERIFY2(dock->detailLabel()->text().contains(
                     QStringLiteral("Node 5's heartbeat was missing 2 time(s) after regular beats")),
                 qPrintable(dock->detailLabel()->text()));
        QVERIFY(dock->detailLabel()->text().contains(QStringLiteral("Check:")));
        QVERIFY(!dock->previousButton()->isEnabled());
        QVERIFY(dock->nextButton()->isEnabled());

        // F8 (Next occurrence) in the findings list: the second frame.
        view->setFocus();
        QTest::keyClick(view, Qt::Key_F8);
        QVERIFY2(waitFor([&] { return currentTraceFrame(w) == 51; }, 5000),
                 qPrintable(QString::number(currentTraceFrame(w))));
        QVERIFY(!dock->nextButton()->isEnabled());
        QVERIFY(dock->previousButton()->isEnabled());
        // The Previous occurrence button: back to the first.
        QTest::mouseClick(dock->previousButton(), Qt::LeftButton);
        QVERIFY2(waitFor([&] { return currentTraceFrame(w) == 26; }, 5000),
                 qPrintable(QString::number(currentTraceFrame(w))));
    }

    // Issue 37 item 8: Export report… writes the report for a ticket, as an HTML page (each
    // finding with its frame numbers, as the CLI's) and as a PDF; the chart scales to the load.
    void exportReportAsHtmlAndPdf() {
        const QString log = writeLog();
        MainWindow w;
        w.setQuiet(true);
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openLog(log));
        HealthDock* dock = w.healthDock();
        QVERIFY(testing::clickDockTab(w, dock->windowTitle()));
        QVERIFY(waitFor([&] { return dock->findingsModel()->report().bus.frames == 70; }, 10000));
        auto* button = dock->findChild<QPushButton*>(QStringLiteral("healthExport"));
        QVERIFY(button && button->isVisible());
        const QString html = dir_.filePath(QStringLiteral("gaps-health.html"));
        {
            auto name = testing::answerFileDialog(html);
            QTest::mouseClick(button, Qt::LeftButton);
            QVERIFY(waitFor([&] { return name->answered() && QFile::exists(html); }, 5000));
        }
        QFile page(html);
        QVERIFY(page.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(page.readAll());
        QVERIFY2(text.contains(QStringLiteral("CoScope network health: gaps.log")), qPrintable(text.left(400)));
        QVERIFY(text.contains(QStringLiteral("Problems found: 1 error")));
        QVERIFY2(text.contains(QStringLiteral(">#27</a>")) && text.contains(QStringLiteral(">#52</a>")),
                 "frame numbers");
        QVERIFY(!text.contains(QStringLiteral(">100 %</text>")));  // 2 beats every 100 ms: a small load
        const QString pdf = dir_.filePath(QStringLiteral("gaps-health.pdf"));
        {
            auto name = testing::answerFileDialog(pdf);
            QTest::mouseClick(button, Qt::LeftButton);
            QVERIFY(waitFor([&] { return name->answered() && QFile::exists(pdf); }, 5000));
        }
        QFile doc(pdf);
        QVERIFY(doc.open(QIODevice::ReadOnly));
        const QByteArray bytes = doc.readAll();
        QVERIFY(bytes.startsWith("%PDF-"));
        QVERIFY2(bytes.size() > 5000, qPrintable(QString::number(bytes.size())));
        QVERIFY2(w.statusBar()->currentMessage().contains(QStringLiteral("gaps-health.pdf")),
                 qPrintable(w.statusBar()->currentMessage()));
    }
};

QTEST_MAIN(HealthFindingsTest)
#include "test_health_findings.moc"
