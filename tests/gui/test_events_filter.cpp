// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 37 item 4, through input events: the Events dock narrowed by node, kind and severity,
// sorted by a click on a column's title, exported as CSV (the rows shown); an event's frame
// shown in the trace while the trace is filtered with SDO transfers grouped (the transfer opened,
// the frame selected, the filter kept); Group SDO and the filter toggled keep that frame selected;
// an event the filter hides clears the filter and selects its frame.
#include "app/gui/MainWindow.h"
#include "app/gui/events/EventsDock.h"
#include "app/gui/events/EventsFilterModel.h"
#include "app/gui/events/EventsModel.h"
#include "app/gui/health/HealthDock.h"
#include "app/gui/health/HealthModel.h"
#include "app/gui/plot/PlotDock.h"
#include "app/gui/plot/PlotView.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "app/gui/trace/TraceView.h"

#include <QComboBox>
#include <QFile>
#include <QHeaderView>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QTableView>
#include <QTemporaryDir>
#include <QToolBar>
#include <QtTest>

#include "tests/gui/ComboPick.h"
#include "tests/gui/ItemClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/OpenLog.h"
#include "tests/gui/TraceBar.h"
#include "tests/gui/TypeText.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::answerFileDialog;
using coscope::testing::clickDockTab;
using coscope::testing::groupSdoButton;
using coscope::testing::openLogByMenu;
using coscope::testing::pickInCombo;
using coscope::testing::typeAndEnter;
using coscope::testing::waitFor;

namespace {
// Two nodes: boot-ups, NMT Start, an SDO read of node 2 answered, an SDO write to node 2 aborted
// (0609 0030h, value range exceeded: CiA 301 §7.2.4.3.17), PDOs, an EMCY of node 1 (2310h,
// continuous over-current: CiA 301 §7.2.7.1).
QString writeLog(const QString& path) {
    QStringList lines;
    double t = 1700000000.0;
    auto put = [&](const char* frame) {
        lines << QStringLiteral("(%1) can0 %2").arg(t, 0, 'f', 6).arg(QLatin1String(frame));
        t += 0.001;
    };
    put("701#00");
    put("702#00");
    put("000#0100");
    put("602#4018100100000000");
    put("582#43181001DD010000");
    put("602#2F60600007000000");
    put("582#8060600030000906");
    for (int i = 0; i < 40; ++i) {
        put("181#0102");
        put("282#0304");
    }
    put("081#1023050000000000");
    for (int i = 0; i < 10; ++i) put("181#0102");
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    f.write(lines.join(u'\n').toUtf8() + "\n");
    return path;
}

QStringList column(QAbstractItemModel* m, int col) {
    QStringList out;
    for (int r = 0; r < m->rowCount(); ++r) out << m->index(r, col).data().toString();
    return out;
}

// The row of the Events view showing the first event of `kind`.
int rowOfKind(EventsDock* dock, TraceEvent::Kind kind) {
    EventsFilterModel* shown = dock->shown();
    for (int r = 0; r < shown->rowCount(); ++r)
        if (dock->model()->eventAt(shown->mapToSource(shown->index(r, 0)).row()).kind == kind) return r;
    return -1;
}

// Click on the event's row, then Enter: its frame is shown in the trace.
void activate(EventsDock* dock, int row) {
    QTableView* view = dock->view();
    const QModelIndex cell = view->model()->index(row, EventsModel::Text);
    view->scrollTo(cell);
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->visualRect(cell).center());
    QTest::keyClick(view, Qt::Key_Return);
}

FrameNo frameOf(EventsDock* dock, int row) {
    return dock->model()->eventAt(dock->shown()->mapToSource(dock->shown()->index(row, 0)).row()).frame;
}

FrameNo selectedFrame(MainWindow& w) {
    const int row = w.traceDock()->view()->currentRow();
    return row < 0 ? FrameNo(~0u) : w.traceDock()->model()->frameAt(row);
}

}  // namespace

class TestEventsFilter : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_events_filter"));
        QSettings().clear();
    }

    void narrowSortExportAndJump() {
        MainWindow w;
        w.setQuiet(true);
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openLogByMenu(w, writeLog(dir_.filePath(QStringLiteral("two-nodes.log")))));
        EventsDock* dock = w.eventsDock();
        QVERIFY(waitFor(
            [&] {
                w.refresh();
                return rowOfKind(dock, TraceEvent::Kind::Emcy) >= 0 && rowOfKind(dock, TraceEvent::Kind::SdoAbort) >= 0;
            },
            10000));
        QVERIFY(clickDockTab(w, dock->windowTitle()));
        QVERIFY(waitFor([&] { return dock->view()->isVisible(); }));
        QAbstractItemModel* shown = dock->view()->model();
        const int all = shown->rowCount();
        auto* severity = dock->findChild<QComboBox*>(QStringLiteral("eventsSeverityFilter"));
        auto* node = dock->findChild<QComboBox*>(QStringLiteral("eventsNodeFilter"));
        auto* kind = dock->findChild<QComboBox*>(QStringLiteral("eventsKindFilter"));
        QVERIFY(severity && node && kind);

        // Severity: errors only = the EMCY; warnings and errors = + the SDO abort.
        QVERIFY(pickInCombo(severity, QStringLiteral("Errors only")));
        QCOMPARE(column(shown, EventsModel::Kind), QStringList{QStringLiteral("EMCY")});
        QVERIFY(pickInCombo(severity, QStringLiteral("Warnings and errors")));
        QCOMPARE(column(shown, EventsModel::Kind), (QStringList{QStringLiteral("SDO abort"), QStringLiteral("EMCY")}));
        QCOMPARE(column(shown, EventsModel::Severity),
                 (QStringList{QStringLiteral("warning"), QStringLiteral("error")}));
        QVERIFY(pickInCombo(severity, QStringLiteral("All severities")));
        QCOMPARE(shown->rowCount(), all);

        // Node 2: only its events (its boot-up and the abort).
        QVERIFY(pickInCombo(node, QStringLiteral("Node 2")));
        QVERIFY(shown->rowCount() >= 2 && shown->rowCount() < all);
        for (const QString& n : column(shown, EventsModel::Node)) QCOMPARE(n, QStringLiteral("2"));
        QVERIFY(pickInCombo(node, QStringLiteral("All nodes")));

        // Kind: the boot-ups.
        QVERIFY(pickInCombo(kind, QStringLiteral("Boot-up")));
        QCOMPARE(column(shown, EventsModel::Node), (QStringList{QStringLiteral("1"), QStringLiteral("2")}));
        QVERIFY(pickInCombo(kind, QStringLiteral("All kinds")));

        // Sorted by a click on "Severity": info first, the EMCY (error) last; again: the EMCY first.
        QHeaderView* header = dock->view()->horizontalHeader();
        const QPoint severityTitle(
            header->sectionViewportPosition(EventsModel::Severity) + header->sectionSize(EventsModel::Severity) / 2,
            header->height() / 2);
        QTest::mouseClick(header->viewport(), Qt::LeftButton, {}, severityTitle);
        QCOMPARE(shown->index(all - 1, EventsModel::Kind).data().toString(), QStringLiteral("EMCY"));
        QCOMPARE(shown->index(all - 2, EventsModel::Kind).data().toString(), QStringLiteral("SDO abort"));
        QTest::mouseClick(header->viewport(), Qt::LeftButton, {}, severityTitle);
        QCOMPARE(shown->index(0, EventsModel::Kind).data().toString(), QStringLiteral("EMCY"));

        // Export CSV: the rows shown, in the order shown, with the titles.
        QVERIFY(pickInCombo(severity, QStringLiteral("Warnings and errors")));
        const QString csv = dir_.filePath(QStringLiteral("events.csv"));
        {
            auto name = answerFileDialog(csv);
            QTest::mouseClick(dock->findChild<QPushButton*>(QStringLiteral("eventsExportCsv")), Qt::LeftButton);
            QVERIFY(waitFor([&] { return name->answered() && QFile::exists(csv); }, 5000));
        }
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QStringList rows = QString::fromUtf8(file.readAll()).split(QStringLiteral("\r\n"), Qt::SkipEmptyParts);
        QCOMPARE(rows.size(), 3);
        QCOMPARE(rows[0], QStringLiteral("Time (s),Node,Event,Severity,Details,Frame"));
        QVERIFY2(rows[1].contains(QStringLiteral(",1,EMCY,error,")), qPrintable(rows[1]));
        QVERIFY2(rows[2].contains(QStringLiteral(",2,SDO abort,warning,")), qPrintable(rows[2]));

        // The trace filtered to node 2 with SDO transfers grouped; the abort's frame shown there:
        // its transfer opened, the frame selected, the filter kept.
        QVERIFY(clickDockTab(w, w.traceDock()->windowTitle()));
        auto* filter = w.traceDock()->findChild<QLineEdit*>(QStringLiteral("filterEdit"));
        QVERIFY(filter);
        typeAndEnter(filter, QStringLiteral("node:2"));
        QTest::mouseClick(groupSdoButton(w), Qt::LeftButton);
        QVERIFY(w.traceDock()->groupsSdo());
        QVERIFY(waitFor([&] {
            w.refresh();
            return !w.traceDock()->isFiltering();
        }));
        QVERIFY(clickDockTab(w, dock->windowTitle()));
        const int abortRow = rowOfKind(dock, TraceEvent::Kind::SdoAbort);
        QVERIFY(abortRow >= 0);
        const FrameNo abortFrame = frameOf(dock, abortRow);
        activate(dock, abortRow);
        QVERIFY(waitFor([&] {
            w.refresh();
            return selectedFrame(w) == abortFrame;
        }));
        QCOMPARE(filter->text(), QStringLiteral("node:2"));
        QVERIFY(w.traceDock()->model()->isGrouped());
        QCOMPARE(w.traceDock()->model()->rowKind(w.traceDock()->view()->currentRow()),
                 TraceModel::RowKind::TransferFrame);

        // Group SDO off, then the filter cleared by its box: the frame stays selected.
        QVERIFY(clickDockTab(w, w.traceDock()->windowTitle()));
        QTest::mouseClick(groupSdoButton(w), Qt::LeftButton);
        QVERIFY(!w.traceDock()->groupsSdo());
        QVERIFY(waitFor([&] {
            w.refresh();
            return !w.traceDock()->isFiltering() && selectedFrame(w) == abortFrame;
        }));
        typeAndEnter(filter, QStringLiteral("node:1,2"));
        QVERIFY(waitFor([&] {
            w.refresh();
            return !w.traceDock()->isFiltering() && w.traceDock()->model()->isFiltered() &&
                   selectedFrame(w) == abortFrame;
        }));
        typeAndEnter(filter, QStringLiteral("node:2"));
        QVERIFY(waitFor([&] {
            w.refresh();
            return !w.traceDock()->isFiltering() && selectedFrame(w) == abortFrame;
        }));

        // The EMCY of node 1 is hidden by the filter: showing it clears the filter.
        QVERIFY(clickDockTab(w, dock->windowTitle()));
        const int emcyRow = rowOfKind(dock, TraceEvent::Kind::Emcy);
        const FrameNo emcyFrame = frameOf(dock, emcyRow);
        activate(dock, emcyRow);
        QVERIFY(waitFor([&] {
            w.refresh();
            return selectedFrame(w) == emcyFrame;
        }));
        QVERIFY(filter->text().isEmpty());
        QVERIFY(!w.traceDock()->model()->isFiltered());
    }

    // Issue 37 item 3, one time base: the trace's time mode set to the wall clock (the log's
    // candump -L stamps are Unix time) shows the events' times, the Health findings' times and
    // the plot's time axis by the same clock; back to relative, all of them in seconds again.
    void oneTimeBaseForEveryView() {
        MainWindow w;
        w.setQuiet(true);
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openLogByMenu(w, writeLog(dir_.filePath(QStringLiteral("clock.log")))));
        EventsDock* dock = w.eventsDock();
        QVERIFY(waitFor([&] {
            w.refresh();
            return rowOfKind(dock, TraceEvent::Kind::Emcy) >= 0;
        }));
        const int emcy = rowOfKind(dock, TraceEvent::Kind::Emcy);
        QAbstractItemModel* events = dock->view()->model();
        QCOMPARE(events->headerData(EventsModel::Time, Qt::Horizontal).toString(), QStringLiteral("Time (s)"));
        const QString relative = events->index(emcy, EventsModel::Time).data().toString();
        QVERIFY2(QRegularExpression(QStringLiteral("^0\\.\\d{6}$")).match(relative).hasMatch(), qPrintable(relative));

        QVERIFY(clickDockTab(w, w.traceDock()->windowTitle()));
        auto* mode = w.traceDock()->findChild<QComboBox*>(QStringLiteral("timeMode"));
        QVERIFY(mode);
        QVERIFY(pickInCombo(mode, QStringLiteral("Absolute time")));
        QCOMPARE(w.workspace()->timeMode(), TimeBase::Mode::WallClock);
        // The event's time is its frame's time in the trace.
        const FrameNo frame = frameOf(dock, emcy);
        TraceModel* trace = w.traceDock()->model();
        const QString traceTime = trace->index(trace->rowOf(frame), TraceModel::Time).data().toString();
        const QString clock = events->index(emcy, EventsModel::Time).data().toString();
        QVERIFY2(QRegularExpression(QStringLiteral("^\\d\\d:\\d\\d:\\d\\d\\.\\d{6}$")).match(clock).hasMatch(),
                 qPrintable(clock));
        QCOMPARE(clock, traceTime);
        QCOMPARE(events->headerData(EventsModel::Time, Qt::Horizontal).toString(), QStringLiteral("Time"));
        // The Health findings (the EMCY's) by the same clock, to the millisecond.
        HealthModel* findings = w.healthDock()->findingsModel();
        QVERIFY(clickDockTab(w, w.healthDock()->windowTitle()));
        QVERIFY(waitFor([&] {
            w.healthDock()->refresh();
            for (int r = 0; r < findings->rowCount(); ++r)
                if (findings->index(r, HealthModel::Time).data().toString() == clock.left(12)) return true;
            return false;
        }));
        QCOMPARE(w.plotDock()->view()->timeAxisTitle(), QStringLiteral("Time"));

        QVERIFY(pickInCombo(mode, QStringLiteral("Relative time")));
        QCOMPARE(events->index(emcy, EventsModel::Time).data().toString(), relative);
        QCOMPARE(w.plotDock()->view()->timeAxisTitle(), QStringLiteral("Time [s]"));
    }
};

QTEST_MAIN(TestEventsFilter)
#include "test_events_filter.moc"
