// SPDX-License-Identifier: GPL-3.0-or-later
// The real main window against the virtual drives (sim://): connect, nodes appear, events,
// NMT from the Nodes dock, listen-only refuses to send, filter the trace, open and save logs,
// layout saved, --screenshot.
#include "app/gui/MainWindow.h"
#include "app/gui/MenuTitle.h"
#include "app/gui/console/ConsoleDock.h"
#include "app/gui/events/EventsDock.h"
#include "app/gui/events/EventsModel.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/session/SimulationDemo.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/status/BusStatusBar.h"
#include "app/gui/trace/LogSaveJob.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "core/log/Logging.h"
#include "core/logio/LogFormats.h"

#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QScrollBar>
#include <QSettings>
#include <QStatusBar>
#include <QTabBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QToolBar>
#include <QToolButton>
#include <QTreeWidget>
#include <QtTest>

#include "tests/gui/ItemClick.h"
#include "tests/gui/MenuClick.h"
#include "tests/gui/OpenLog.h"
#include "tests/gui/TypeText.h"
#include "tests/gui/WaitFor.h"

#include <spdlog/spdlog.h>

#include "eds/SimulatorDictionaries.h"
#include "tests/gui/ModalAnswer.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::answerBox;
using coscope::testing::answerFileDialog;
using coscope::testing::openLogByMenu;

namespace {
// Waits (running the event loop, so the window's timer ticks) until `pred` holds.
using coscope::testing::clickMenuItem;
using coscope::testing::typeAndEnter;
using coscope::testing::waitFor;
QString cell(const TraceModel* m, int row, int col) { return m->data(m->index(row, col), Qt::DisplayRole).toString(); }

QToolBar* traceBar(MainWindow& w) { return w.traceDock()->findChild<QToolBar*>(QStringLiteral("traceToolbar")); }
QAction* barAction(MainWindow& w, const QString& text) {
    for (QAction* a : traceBar(w)->actions())
        if (a->text() == text) return a;
    return nullptr;
}
QString countText(MainWindow& w) { return w.traceDock()->findChild<QLabel*>(QStringLiteral("traceCount"))->text(); }
// Opens a log in the window and waits until it is read and shown.
bool openLoaded(MainWindow& w, const QString& path) {
    if (!w.openLog(path) || !waitFor([&] { return w.workspace()->loadJob()->isDone(); })) return false;
    w.refresh();
    return true;
}

// Clicks a trace row as a user does (the row must be scrolled into view first).
void clickRow(QTableView* view, int row) {
    view->scrollTo(view->model()->index(row, 0));
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, view->visualRect(view->model()->index(row, 1)).center());
}
// Saves by File ▸ `item` and its file dialog; waits until the file is written.
bool saveByMenu(MainWindow& w, const QString& item, const QString& path) {
    auto name = answerFileDialog(path);
    if (!clickMenuItem(w, QStringLiteral("File"), item) || !waitFor([&] { return name->answered(); })) return false;
    return waitFor([&] { return w.saveJob() == nullptr && QFileInfo::exists(path); });
}

// A log of 200 PDOs and one EMCY.
QString writeJumpLog(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    for (int i = 0; i < 200; ++i)
        f.write(QStringLiteral("(1700000000.%1) can0 181#0102\n").arg(i * 1000, 6, 10, QLatin1Char('0')).toLatin1());
    f.write("(1700000001.000000) can0 081#1023050000000000\n");
    return path;
}
}  // namespace

class TestMainWindow : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_main_window"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
        QVERIFY(dir_.isValid());
    }

    void simulateShowsTrafficNodesAndEvents() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(w.connectBus(QStringLiteral("sim://")));
        QVERIFY2(waitFor([&] { return w.workspace()->bus()->state() == CanBus::State::Open; }),
                 qPrintable(w.lastError()));
        TraceModel* m = w.traceDock()->model();
        QVERIFY(waitFor([&] { return m->rowCount() >= 3; }));  // the boot-ups
        // Nodes appear from boot-ups/heartbeats of the default virtual drives (1, 2, 3).
        QVERIFY(waitFor([&] { return w.nodesDock()->model()->rowCount() >= 3; }));
        QCOMPARE(w.nodesDock()->model()->nodeAt(0), 1);
        QVERIFY(w.eventsDock()->model()->rowCount() >= 3);  // three boot-ups
        QCOMPARE(w.eventsDock()
                     ->model()
                     ->data(w.eventsDock()->model()->index(0, EventsModel::Kind), Qt::DisplayRole)
                     .toString(),
                 QStringLiteral("Boot-up"));
        // The status bar shows the bus state and a rate.
        QVERIFY(
            waitFor([&] { return w.busStatus()->stateText().contains(QStringLiteral("open"), Qt::CaseInsensitive); }));
        QVERIFY(w.busStatus()->rateText().contains(QStringLiteral("frames/s")));
        // Selecting a row fills the details pane.
        w.traceDock()->view()->selectRow(0);
        QVERIFY(w.traceDock()->findChild<QTreeWidget*>(QStringLiteral("frameFields"))->topLevelItemCount() >= 2);

        // Scan from the Nodes dock: SDO reads identify the nodes (identity 1018h).
        w.nodesDock()->setAutoConfirm(true);
        QVERIFY(w.nodesDock()->scanAction()->isEnabled());
        w.nodesDock()->scan();
        QVERIFY(waitFor([&] {
            auto* nm = w.nodesDock()->model();
            return nm->rowCount() >= 3 && nm->infoAt(0).scanned && nm->infoAt(0).vendorId.has_value();
        }));
        QCOMPARE(w.nodesDock()->model()->rowCount(), 3);  // nobody else answered

        // NMT from the Nodes dock goes out (and shows as a Tx frame in the trace).
        for (QAction* a : w.nodesDock()->commandActions())
            QVERIFY(a->objectName() == u"scanAction" || a->text().isEmpty() || a->isEnabled() ||
                    a->text().contains(QStringLiteral("identity")));
        const size_t before = w.workspace()->store()->size();
        QVERIFY(w.nodesDock()->sendNmt(0x01, 2));  // start node 2
        QVERIFY(waitFor([&] {
            const auto& s = *w.workspace()->store();
            for (size_t n = before; n < s.size(); ++n) {
                const auto& r = s.record(static_cast<FrameNo>(n));
                if (r.id == 0 && (r.flags & CanFrame::Tx) && r.len == 2 && r.data[0] == 1 && r.data[1] == 2)
                    return true;
            }
            return false;
        }));
        // The event log shows the command.
        QVERIFY(waitFor([&] {
            auto* em = w.eventsDock()->model();
            for (int r = 0; r < em->rowCount(); ++r)
                if (em->eventAt(r).kind == TraceEvent::Kind::NmtCommand) return true;
            return false;
        }));
    }

    void listenOnlyRefusesToSend() {
        MainWindow w;
        w.setQuiet(true);
        QVERIFY(w.connectBus(QStringLiteral("sim://?listen-only=1")));
        QVERIFY(waitFor([&] { return w.workspace()->bus()->state() == CanBus::State::Open; }));
        QVERIFY(waitFor([&] { return w.traceDock()->model()->rowCount() >= 3; }));
        w.refresh();
        QVERIFY(!w.workspace()->canTransmit());
        for (QAction* a : w.nodesDock()->commandActions()) QVERIFY2(!a->isEnabled(), qPrintable(a->text()));
        QVERIFY(!w.nodesDock()->scanAction()->isEnabled());
        w.nodesDock()->setAutoConfirm(true);
        QVERIFY(!w.nodesDock()->sendNmt(0x01, 0));
        QString error;
        QVERIFY(!w.workspace()->bus()->send(CanFrame::classic(0x000, {0x01, 0x00}), &error));
        QVERIFY(!error.isEmpty());
        QTest::qWait(200);
        const auto& s = *w.workspace()->store();
        for (size_t n = 0; n < s.size(); ++n) QVERIFY(!(s.record(static_cast<FrameNo>(n)).flags & CanFrame::Tx));
        QVERIFY(w.busStatus()->stateText().contains(QStringLiteral("listen-only")));
    }

    void filterTheLiveTrace() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(w.connectBus(QStringLiteral("sim://")));
        startSimulationDemo(w.workspace());  // heartbeats on, network started
        QVERIFY(waitFor([&] { return w.traceDock()->model()->rowCount() > 20; }));
        auto* edit = w.traceDock()->findChild<QLineEdit*>(QStringLiteral("filterEdit"));
        // A filter that means nothing: said in the status bar, the field turns red, nothing hidden.
        typeAndEnter(edit, QStringLiteral("svc:nonsense"));
        QVERIFY2(w.statusBar()->currentMessage().contains(QStringLiteral("nonsense")),
                 qPrintable(w.statusBar()->currentMessage()));
        QVERIFY(!edit->toolTip().isEmpty());
        TraceModel* m = w.traceDock()->model();
        QVERIFY(!m->isFiltered());
        typeAndEnter(edit, QStringLiteral("svc:nmt_ec node:1"));
        QVERIFY(waitFor([&] { return !w.traceDock()->isFiltering() && m->isFiltered() && m->rowCount() >= 2; }));
        for (int r = 0; r < m->rowCount(); ++r) {
            QCOMPARE(cell(m, r, TraceModel::Service), QStringLiteral("NMT_EC"));
            QCOMPARE(cell(m, r, TraceModel::Node), QStringLiteral("1"));
        }
        QVERIFY(m->rowCount() < int(w.workspace()->store()->size()));
        QVERIFY2(countText(w).contains(QStringLiteral(" of ")), qPrintable(countText(w)));
        // The live trace goes on under the filter: new heartbeats of node 1 keep coming.
        const int rows = m->rowCount();
        QVERIFY(waitFor([&] { return m->rowCount() > rows; }, 5000));
        // Emptying the field by keys removes the filter.
        QTest::keyClick(edit, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClick(edit, Qt::Key_Delete);
        QVERIFY(waitFor([&] { return !m->isFiltered(); }));
    }

    void openAndSaveLogs() {
        // A candump log with one bad line: the rest loads, the problem is reported with its line.
        const QString path = dir_.filePath(QStringLiteral("in.log"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(
            "(1700000000.000000) can0 701#00\n"
            "(1700000000.100000) can0 701#7F\n"
            "this is not a candump line\n"
            "(1700000000.200000) can0 081#1023050000000000\n"
            "(1700000000.300000) can0 601#4000100000000000\n");
        f.close();
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openLogByMenu(w, path));
        QVERIFY(waitFor([&] { return w.statusBar()->currentMessage().contains(QStringLiteral(":3")); }));
        QCOMPARE(w.traceDock()->model()->rowCount(), 4);
        QVERIFY(waitFor([&] { return w.nodesDock()->model()->rowCount() == 1; }));
        QVERIFY(w.eventsDock()->model()->rowCount() >= 2);  // boot-up, EMCY

        // Save in two formats (named by the extension); read back with the log layer.
        for (const QString& name : {QStringLiteral("out.log"), QStringLiteral("out.asc")}) {
            const QString out = dir_.filePath(name);
            QVERIFY(saveByMenu(w, QStringLiteral("Save trace as"), out));
            QVERIFY(waitFor([&] { return w.statusBar()->currentMessage().contains(out); }));
            QString error;
            auto reader = logio::LogFormats::openReader(out, &error);
            QVERIFY2(reader, qPrintable(error));
            QCOMPARE(reader->readAll().size(), size_t(4));
        }
        // Export only the filtered rows.
        typeAndEnter(w.traceDock()->findChild<QLineEdit*>(QStringLiteral("filterEdit")), QStringLiteral("svc:emcy"));
        QVERIFY(waitFor([&] { return !w.traceDock()->isFiltering() && w.traceDock()->model()->rowCount() == 1; }));
        const QString filtered = dir_.filePath(QStringLiteral("filtered.log"));
        QVERIFY(saveByMenu(w, QStringLiteral("Export filtered rows"), filtered));
        auto reader = logio::LogFormats::openReader(filtered, nullptr);
        QVERIFY(reader);
        const auto frames = reader->readAll();
        QCOMPARE(frames.size(), size_t(1));
        QCOMPARE(frames[0].id, 0x81u);

        // A file that is no log is an error in the window that names it, not a crash.
        const QString junk = dir_.filePath(QStringLiteral("junk.bin"));
        QFile j(junk);
        QVERIFY(j.open(QIODevice::WriteOnly));
        j.write(QByteArray(64, '\xff'));
        j.close();
        auto name = answerFileDialog(junk);
        QVERIFY(clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Open log")));
        QVERIFY(waitFor([&] { return name->answered(); }));
        QVERIFY2(waitFor([&] { return w.statusBar()->currentMessage().contains(QStringLiteral("junk.bin")); }),
                 qPrintable(w.statusBar()->currentMessage()));
    }

    // A log opened for review starts at its first frame with Follow off (the view does not
    // chase a file still loading); Follow, clicked, goes to the newest frame.
    void openedLogStartsAtItsFirstFrame() {
        const QString path = dir_.filePath(QStringLiteral("long.log"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        for (int i = 0; i < 5000; ++i)
            f.write(QStringLiteral("(1700000000.%1) can0 181#%2\n")
                        .arg(i * 100, 6, 10, QLatin1Char('0'))
                        .arg(i, 4, 16, QLatin1Char('0'))
                        .toLatin1());
        f.close();
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openLogByMenu(w, path));
        QVERIFY(waitFor([&] { return w.traceDock()->model()->rowCount() == 5000; }));
        QTableView* view = w.traceDock()->view();
        QAction* follow = barAction(w, QStringLiteral("Follow"));
        QVERIFY(follow);
        QTest::qWait(200);  // a few of the window's pulls
        QVERIFY(!follow->isChecked());
        QCOMPARE(view->rowAt(0), 0);
        QTest::mouseClick(traceBar(w)->widgetForAction(follow), Qt::LeftButton);
        QVERIFY(follow->isChecked());
        QVERIFY(waitFor([&] { return view->rowAt(view->viewport()->height() - 2) == 4999; }));
    }

    void eventJumpsToFrame() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(openLogByMenu(w, writeJumpLog(dir_.filePath(QStringLiteral("jump.log")))));
        QVERIFY(waitFor([&] { return w.eventsDock()->model()->rowCount() == 1; }));
        // Enter on the event (chosen by a click) selects its frame in the trace.
        QVERIFY(coscope::testing::clickDockTab(w, QStringLiteral("Events")));
        auto* events = w.eventsDock()->findChild<QTableView*>();
        QVERIFY(events);
        QVERIFY(waitFor([&] { return events->isVisible(); }));
        QTest::mouseClick(events->viewport(), Qt::LeftButton, {},
                          events->visualRect(events->model()->index(0, 1)).center());
        QTest::keyClick(events, Qt::Key_Return);
        QTableView* view = w.traceDock()->view();
        QVERIFY(waitFor([&] { return view->currentIndex().isValid(); }));
        QCOMPARE(w.traceDock()->model()->frameAt(view->currentIndex().row()), FrameNo(200));
        // Find by typing in the Find field and Enter.
        clickRow(view, 0);
        QCOMPARE(view->currentIndex().row(), 0);
        typeAndEnter(w.traceDock()->findChild<QLineEdit*>(QStringLiteral("findEdit")), QStringLiteral("EMCY"));
        QCOMPARE(view->currentIndex().row(), 200);
        // Bookmark by its button, then from the top F2 jumps back to it.
        QWidget* mark = traceBar(w)->widgetForAction(barAction(w, QStringLiteral("Bookmark")));
        QVERIFY(mark && mark->isVisible());
        QTest::mouseClick(mark, Qt::LeftButton);
        QCOMPARE(w.traceDock()->model()->bookmarks().size(), size_t(1));
        clickRow(view, 0);
        QCOMPARE(view->currentIndex().row(), 0);
        QTest::keyClick(view, Qt::Key_F2);
        QCOMPARE(view->currentIndex().row(), 200);
    }

    void clearingTheFilterWithItsButtonShowsAllFrames() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(openLoaded(w, writeJumpLog(dir_.filePath(QStringLiteral("clear.log")))));
        auto* edit = w.traceDock()->findChild<QLineEdit*>(QStringLiteral("filterEdit"));
        QTest::keyClicks(edit, QStringLiteral("svc:emcy"));
        QTest::keyClick(edit, Qt::Key_Return);
        QVERIFY(waitFor([&] { return countText(w) == QStringLiteral("1 of 201 frames"); }));
        // The ✕ inside the field: the line edit's clear action's button.
        QToolButton* clear = nullptr;
        for (auto* b : edit->findChildren<QToolButton*>())
            if (b->isVisible()) clear = b;
        QVERIFY(clear);
        QTest::mouseClick(clear, Qt::LeftButton);
        QVERIFY(edit->text().isEmpty());
        QVERIFY2(waitFor([&] { return countText(w) == QStringLiteral("201 frames"); }, 2000), qPrintable(countText(w)));
        QCOMPARE(w.traceDock()->model()->rowCount(), 201);
    }

    void findThatFindsNothingSaysSo() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(openLoaded(w, writeJumpLog(dir_.filePath(QStringLiteral("find.log")))));
        auto* find = w.traceDock()->findChild<QLineEdit*>(QStringLiteral("findEdit"));
        // What the eye sees: does the field's background turn red?
        auto looksRed = [find] {
            const QImage img = find->grab().toImage();
            int red = 0;
            for (int y = 0; y < img.height(); ++y)
                for (int x = 0; x < img.width(); ++x) {
                    const QColor c = img.pixelColor(x, y);
                    if (c.red() > 200 && c.red() - c.green() > 25 && c.red() - c.blue() > 25) ++red;
                }
            return red > img.width() * img.height() / 3;
        };
        QVERIFY(!looksRed());
        QTest::keyClicks(find, QStringLiteral("no such thing"));
        QTest::keyClick(find, Qt::Key_Return);
        QVERIFY2(w.statusBar()->currentMessage().contains(QStringLiteral("not found")),
                 qPrintable(w.statusBar()->currentMessage()));
        QVERIFY(looksRed());
        // Typing again clears the cue; a hit keeps it clear.
        QTest::keyClick(find, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(find, QStringLiteral("EMCY"));
        QVERIFY(!looksRed());
        QTest::keyClick(find, Qt::Key_Return);
        QCOMPARE(w.traceDock()->model()->frameAt(w.traceDock()->view()->currentIndex().row()), FrameNo(200));
        QVERIFY(!looksRed());
    }

    void toolbarShowsNextAndBookmarkAtDefaultSize() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QCOMPARE(w.size(), QSize(1360, 860));
        for (const QString& text : {QStringLiteral("Previous"), QStringLiteral("Next"), QStringLiteral("Bookmark")}) {
            QAction* a = barAction(w, text);
            QVERIFY2(a, qPrintable(text));
            QWidget* b = traceBar(w)->widgetForAction(a);
            QVERIFY2(b && b->isVisible(), qPrintable(text + QStringLiteral(" is behind the toolbar's »")));
        }
    }

    void consoleFollowsNewLines() {
        QStandardPaths::setTestModeEnabled(true);
        logging::init(QStringLiteral("gui_main_window"), spdlog::level::info);
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QPlainTextEdit* text = w.consoleDock()->text();
        QScrollBar* bar = text->verticalScrollBar();
        // Lines arrive while the Console is a tab behind Events; then the user clicks its tab.
        auto clickTab = [&](const QString& title) {
            for (QTabBar* t : w.findChildren<QTabBar*>())
                for (int i = 0; i < t->count(); ++i)
                    if (t->tabText(i) == title)
                        return QTest::mouseClick(t, Qt::LeftButton, {}, t->tabRect(i).center()), true;
            return false;
        };
        QVERIFY(clickTab(w.eventsDock()->windowTitle()));
        QVERIFY(waitFor([&] { return text->visibleRegion().isEmpty(); }));
        for (int i = 0; i < 300; ++i) spdlog::info("console line {}", i);
        QVERIFY(waitFor([&] { return text->toPlainText().contains(QStringLiteral("console line 299")); }));
        QVERIFY(clickTab(w.consoleDock()->windowTitle()));
        QVERIFY(waitFor([&] { return !text->visibleRegion().isEmpty(); }));
        QTest::qWait(100);
        QVERIFY(bar->maximum() > 0);
        QCOMPARE(bar->value(), bar->maximum());  // at the bottom: the newest line shows
        for (int i = 300; i < 320; ++i) spdlog::info("console line {}", i);
        QVERIFY(waitFor([&] { return text->toPlainText().contains(QStringLiteral("console line 319")); }));
        QTest::qWait(100);
        QCOMPARE(bar->value(), bar->maximum());
        // The user scrolls up: new lines leave the view where it is.
        QTest::keyClick(text->viewport(), Qt::Key_PageUp);
        QTest::keyClick(text, Qt::Key_PageUp);
        const int where = bar->value();
        QVERIFY(where < bar->maximum());
        for (int i = 320; i < 330; ++i) spdlog::info("console line {}", i);
        QVERIFY(waitFor([&] { return text->toPlainText().contains(QStringLiteral("console line 329")); }));
        QTest::qWait(100);
        QCOMPARE(bar->value(), where);
    }

    void listenOnlyDisablesTheCommissionMenu() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        auto commissionItems = [&] {
            QAction* title = nullptr;  // opens Commission by a click on the menu bar
            for (QAction* a : w.menuBar()->actions())
                if (a->text().contains(QStringLiteral("Commission"))) title = a;
            if (!title) return std::vector<bool>{};
            QTest::mouseClick(w.menuBar(), Qt::LeftButton, {}, w.menuBar()->actionGeometry(title).center());
            auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
            if (!menu) return std::vector<bool>{};
            std::vector<bool> enabled;
            for (QAction* a : menu->actions())
                if (!a->isSeparator()) enabled.push_back(a->isEnabled());
            QTest::keyClick(menu, Qt::Key_Escape);
            return enabled;
        };
        QVERIFY(w.connectBus(QStringLiteral("sim://?listen-only=1")));
        QVERIFY(waitFor([&] { return w.workspace()->bus()->state() == CanBus::State::Open; }));
        QTest::qWait(100);
        auto items = commissionItems();
        QVERIFY(!items.empty());
        for (bool on : items) QVERIFY2(!on, "a Commission item is enabled on a listen-only bus");
        QVERIFY(w.connectBus(QStringLiteral("sim://")));
        QVERIFY(waitFor([&] { return w.workspace()->bus()->state() == CanBus::State::Open; }));
        QTest::qWait(100);
        items = commissionItems();
        QVERIFY(!items.empty());
        for (bool on : items) QVERIFY(on);
    }

    void unsavedCaptureIsNotThrownAway() {
        MainWindow w;  // not quiet: the question is a modal box
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(w.connectBus(QStringLiteral("sim://")));
        QVERIFY(waitFor([&] { return w.workspace()->store()->size() >= 3; }));
        // Quit (Ctrl+Q), Cancel: the window stays with its frames.
        QString asked;
        auto cancel = answerBox(QMessageBox::Cancel, &asked);
        QTest::keyClick(&w, Qt::Key_Q, Qt::ControlModifier);
        QVERIFY2(asked.contains(QStringLiteral("Save")), qPrintable(asked));
        QVERIFY(w.isVisible());
        QVERIFY(w.workspace()->isLive());
        // Bus ▸ Connect to virtual drives (clicked in the menu), Discard: connects anew.
        asked.clear();
        QMenu* bus = nullptr;
        QAction* busTitle = nullptr;
        for (QAction* a : w.menuBar()->actions())
            if (a->menu() && a->text().contains(QStringLiteral("Bus"))) bus = a->menu(), busTitle = a;
        QVERIFY(bus);
        QAction* sim = nullptr;
        for (QAction* a : bus->actions())
            if (a->text().contains(QStringLiteral("virtual drives"))) sim = a;
        QVERIFY(sim);
        const auto before = w.workspace()->store();
        auto discard = answerBox(QMessageBox::Discard, &asked);
        QTest::mouseClick(w.menuBar(), Qt::LeftButton, {}, w.menuBar()->actionGeometry(busTitle).center());
        QVERIFY(waitFor([&] { return bus->isVisible(); }));
        QTest::mouseClick(bus, Qt::LeftButton, {}, bus->actionGeometry(sim).center());
        QVERIFY(waitFor([&] { return !asked.isEmpty() && w.workspace()->store() != before; }));
        QVERIFY(waitFor([&] { return w.workspace()->store()->size() >= 3; }));
        // Window close, Save: the normal Save As runs; the window closes once the file is written.
        const QString out = dir_.filePath(QStringLiteral("kept.log"));
        asked.clear();
        auto save = answerBox(QMessageBox::Save, &asked);
        auto name = answerFileDialog(out);
        w.close();
        QVERIFY(!asked.isEmpty());
        QVERIFY(waitFor([&] { return name->answered(); }));
        QVERIFY(waitFor([&] { return !w.isVisible(); }));
        auto reader = logio::LogFormats::openReader(out, nullptr);
        QVERIFY(reader);
        QVERIFY(reader->readAll().size() >= 3);

        // A log just opened and unchanged: nothing to ask.
        MainWindow again;
        again.show();
        QVERIFY(openLoaded(again, out));
        asked.clear();
        auto unused = answerBox(QMessageBox::Cancel, &asked);
        again.close();
        QVERIFY2(asked.isEmpty(), qPrintable(asked));
        QVERIFY(!again.isVisible());
    }

    void contextMenuTitleIsNotClipped() {
        // The OD dock's context menu title for a long object name, as the user sees it.
        QMenu menu;
        const QString text = QStringLiteral("1017:00 Producer heartbeat time");
        QAction* title = addMenuTitle(menu, text);
        menu.addAction(QStringLiteral("Read"));
        menu.addAction(QStringLiteral("Write…"));
        menu.popup(QPoint(10, 10));
        QVERIFY(QTest::qWaitForWindowExposed(&menu));
        QFont bold = menu.font();
        bold.setBold(true);
        QVERIFY2(menu.actionGeometry(title).width() > QFontMetrics(bold).horizontalAdvance(text),
                 qPrintable(QString::number(menu.actionGeometry(title).width())));
        QTest::keyClick(&menu, Qt::Key_Escape);
        QVERIFY(!menu.isVisible());
    }

    void layoutIsSaved() {
        {
            MainWindow w;
            w.show();
            w.nodesDock()->hide();
            w.close();
        }
        QVERIFY(QSettings().contains(QStringLiteral("window/state")));
        MainWindow again;
        again.show();
        QVERIFY(again.nodesDock()->isHidden());
        again.nodesDock()->show();
        again.close();
    }

    void screenshotOption() {
        const QString png = dir_.filePath(QStringLiteral("shot.png"));
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("offscreen"));
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(COSCOPE_GUI_PATH), {QStringLiteral("--simulate"), QStringLiteral("--screenshot"), png,
                                                   QStringLiteral("--view"), QStringLiteral("nodes")});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 0);
        QImage img(png);
        QVERIFY(!img.isNull());
        QVERIFY(img.width() > 600);
        p.start(QStringLiteral(COSCOPE_GUI_PATH), {QStringLiteral("--view"), QStringLiteral("bogus")});
        QVERIFY(p.waitForFinished(20000));
        QCOMPARE(p.exitCode(), 2);
    }
};

QTEST_MAIN(TestMainWindow)
#include "test_main_window.moc"
