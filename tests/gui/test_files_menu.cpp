// SPDX-License-Identifier: GPL-3.0-or-later
// Files as a user expects (issue 36 item 7): the Open log dialog starts in the folder of the last
// log (each kind of file its own), File ▸ Recent logs, and a file that cannot be opened leaves
// the log, the nodes and the raw signals shown as they were, with a message box that says why.
#include "app/gui/MainWindow.h"
#include "app/gui/plot/PlotDock.h"
#include "app/gui/plot/PlotView.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "eds/SimulatorDictionaries.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/OpenLog.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::answerFileDialog;
using coscope::testing::clickMenuItem;
using coscope::testing::menuItem;
using coscope::testing::ModalAnswerer;
using coscope::testing::openLogByMenu;
using coscope::testing::openMenu;
using coscope::testing::waitFor;
using coscope::testing::withoutAccelerator;

namespace {
// candump -L: two boot-ups and `frames` frames of a PDO (COB-ID 2A0h) nothing describes.
QString writeLog(const QString& path, int frames) {
    QStringList l = {QStringLiteral("(100.000000) can0 710#00"), QStringLiteral("(100.001000) can0 720#00")};
    for (int i = 0; i < frames; ++i)
        l << QStringLiteral("(%1) can0 2A0#00%2").arg(101.0 + 0.01 * i, 0, 'f', 6).arg(i, 2, 16, QLatin1Char('0'));
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    f.write(l.join(u'\n').toUtf8() + "\n");
    return path;
}

// Opens File ▸ `item`'s dialog, notes the folder it starts in and closes it with Escape.
QString dialogFolder(MainWindow& w, const QString& item) {
    QString folder;
    ModalAnswerer look([&](QWidget* modal) {
        auto* dialog = qobject_cast<QFileDialog*>(modal);
        if (!dialog) return false;
        folder = dialog->directory().absolutePath();
        QTest::keyClick(dialog, Qt::Key_Escape);
        return true;
    });
    if (!clickMenuItem(w, QStringLiteral("File"), item) || !waitFor([&] { return look.answered(); }))
        return QStringLiteral("(no dialog)");
    w.activateWindow();
    return folder;
}

// File ▸ Recent logs, opened by clicks: the submenu shown (or null when it is disabled).
QMenu* openRecent(MainWindow& w) {
    QMenu* file = openMenu(w, QStringLiteral("File"));
    if (!file) return nullptr;
    QAction* recent = menuItem(file, QStringLiteral("Recent logs"));
    if (!recent || !recent->isEnabled()) {
        QTest::keyClick(file, Qt::Key_Escape);
        return nullptr;
    }
    QTest::mouseClick(file, Qt::LeftButton, {}, file->actionGeometry(recent).center());
    if (!waitFor([&] { return recent->menu()->isVisible(); })) return nullptr;
    return recent->menu();
}
QStringList texts(QMenu* m) {
    QStringList t;
    for (QAction* a : m->actions())
        if (!a->isSeparator()) t << withoutAccelerator(a->text());
    return t;
}
void closeMenus(MainWindow& w, QMenu* sub) {
    QTest::keyClick(sub, Qt::Key_Escape);
    for (QAction* a : w.menuBar()->actions())
        if (a->menu() && a->menu()->isVisible()) QTest::keyClick(a->menu(), Qt::Key_Escape);
}
}  // namespace

class TestFilesMenu : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_files_menu"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
        QVERIFY(dir_.isValid());
    }

    // The first time, the dialog opens in Documents (or home), never in the working folder;
    // then in the folder of the log opened last; another kind (exports) keeps its own.
    void dialogStartsInTheLastFolder() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
        const QString first = QFileInfo(documents).isDir() ? documents : QDir::homePath();
        QCOMPARE(dialogFolder(w, QStringLiteral("Open log")), QDir(first).absolutePath());

        const QString log = writeLog(dir_.filePath(QStringLiteral("field/machine7/a.log")), 10);
        QVERIFY(openLogByMenu(w, log));
        QCOMPARE(dialogFolder(w, QStringLiteral("Open log")), QFileInfo(log).absolutePath());
        QCOMPARE(dialogFolder(w, QStringLiteral("Save trace as")), QFileInfo(log).absolutePath());  // the same kind
        QCOMPARE(dialogFolder(w, QStringLiteral("Export filtered rows")), QDir(first).absolutePath());
    }

    // File ▸ Recent logs: newest first with the full path as tooltip, a file that went is shown
    // disabled, a click opens one, Clear recent empties the list.
    void recentLogs() {
        QSettings().remove(QStringLiteral("files/recent/logs"));
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(!openRecent(w));  // nothing yet: disabled
        const QString a = writeLog(dir_.filePath(QStringLiteral("recent/a.log")), 5);
        const QString b = writeLog(dir_.filePath(QStringLiteral("recent/b.log")), 6);
        const QString c = writeLog(dir_.filePath(QStringLiteral("recent/c.log")), 7);
        QVERIFY(openLogByMenu(w, a));
        QVERIFY(openLogByMenu(w, b));
        QVERIFY(openLogByMenu(w, c));
        QVERIFY(QFile::remove(c));

        QMenu* recent = openRecent(w);
        QVERIFY(recent);
        QCOMPARE(texts(recent), (QStringList{QStringLiteral("1 c.log (not found)"), QStringLiteral("2 b.log"),
                                             QStringLiteral("3 a.log"), QStringLiteral("Clear recent")}));
        QVERIFY(!recent->actions().at(0)->isEnabled());
        QCOMPARE(recent->actions().at(1)->toolTip(), QDir::toNativeSeparators(b));
        // A click on a.log opens it.
        QTest::mouseClick(recent, Qt::LeftButton, {}, recent->actionGeometry(recent->actions().at(2)).center());
        QVERIFY(waitFor([&] {
            return w.workspace()->sourceName() == QStringLiteral("a.log") && w.workspace()->loadJob()->isDone();
        }));
        QVERIFY(waitFor([&] { return w.traceDock()->model()->rowCount() == 7; }));

        recent = openRecent(w);
        QVERIFY(recent);
        QCOMPARE(texts(recent).value(0), QStringLiteral("1 a.log"));  // opened again: first
        QAction* clear = menuItem(recent, QStringLiteral("Clear recent"));
        QVERIFY(clear);
        QTest::mouseClick(recent, Qt::LeftButton, {}, recent->actionGeometry(clear).center());
        QVERIFY(waitFor([&] { return !recent->isVisible(); }));
        closeMenus(w, recent);
        QVERIFY(!openRecent(w));
    }

    // A good log with a raw signal plotted, then a file that is no log: the box names the file
    // and the lines, and the trace, nodes and plotted raw signal are those of the first log.
    void failedOpenKeepsTheLog() {
        QSettings().remove(QStringLiteral("plot/rawSignals"));
        MainWindow w;  // not quiet: errors come as message boxes
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        const QString good = writeLog(dir_.filePath(QStringLiteral("keep/good.log")), 30);
        QVERIFY(openLogByMenu(w, good));
        QVERIFY(waitFor([&] { return w.traceDock()->model()->rowCount() == 32; }));

        // A raw signal on 2A0h byte 1, added through the Plot dock's dialog.
        QVERIFY(w.showView(QStringLiteral("plot")));
        PlotDock* dock = w.plotDock();
        bool typed = false;
        ModalAnswerer fill([&](QWidget* modal) {
            auto* name = modal->findChild<QLineEdit*>(QStringLiteral("rawName"));
            if (!name) return false;
            auto type = [](QWidget* field, const QString& text) {
                QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
                QTest::keyClicks(field, text);
            };
            type(name, QStringLiteral("counter"));
            type(modal->findChild<QLineEdit*>(QStringLiteral("rawCobId")), QStringLiteral("0x2A0"));
            type(modal->findChild<QSpinBox*>(QStringLiteral("rawStart")), QStringLiteral("8"));
            type(modal->findChild<QSpinBox*>(QStringLiteral("rawLength")), QStringLiteral("8"));
            QTest::mouseClick(
                modal->findChild<QDialogButtonBox*>(QStringLiteral("buttonBox"))->button(QDialogButtonBox::Ok),
                Qt::LeftButton);
            typed = true;
            return true;
        });
        QTest::mouseClick(dock->findChild<QToolButton*>(QStringLiteral("addRawSignal")), Qt::LeftButton);
        QVERIFY(typed);
        QVERIFY(
            waitFor([&] { return dock->view()->plotted().size() == 1 && dock->view()->drawnPoints(0).size() == 30u; }));
        const auto recorder = w.workspace()->signalRecorder();
        const auto store = w.workspace()->store();

        // A text file of notes named .log: read as candump, every line bad.
        const QString junk = dir_.filePath(QStringLiteral("keep/notes.log"));
        QFile f(junk);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("Meeting notes\nnode 5 reboots at power-up\n");
        f.close();
        QString said;
        QString detail;
        ModalAnswerer box([&](QWidget* modal) {
            auto* b = qobject_cast<QMessageBox*>(modal);
            if (!b) return false;
            said = b->text();
            detail = b->informativeText();
            QTest::mouseClick(b->button(QMessageBox::Ok), Qt::LeftButton);
            return true;
        });
        auto name = answerFileDialog(junk);
        QVERIFY(clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Open log")));
        QVERIFY(waitFor([&] { return name->answered(); }));
        QVERIFY(waitFor([&] { return box.answered(); }));
        QVERIFY2(said.contains(QStringLiteral("notes.log")), qPrintable(said));
        QVERIFY2(detail.contains(QStringLiteral("line 1:")) && detail.contains(QStringLiteral("line 2:")),
                 qPrintable(detail));

        // Nothing changed: the same trace, nodes, recorder and plotted points.
        QCOMPARE(w.workspace()->sourceName(), QStringLiteral("good.log"));
        QCOMPARE(w.workspace()->store(), store);
        QCOMPARE(w.workspace()->signalRecorder(), recorder);
        QTest::qWait(200);  // a few of the window's pulls
        QCOMPARE(w.traceDock()->model()->rowCount(), 32);
        QCOMPARE(dock->view()->plotted().size(), size_t(1));
        QCOMPARE(dock->view()->drawnPoints(0).size(), size_t(30));
        QCOMPARE(w.windowTitle(), QStringLiteral("good.log — CoScope"));

        // A binary file of no known format: the same, with the reason.
        const QString bin = dir_.filePath(QStringLiteral("keep/junk.bin"));
        QFile j(bin);
        QVERIFY(j.open(QIODevice::WriteOnly));
        j.write(QByteArray(64, '\xff'));
        j.close();
        said.clear();
        ModalAnswerer box2([&](QWidget* modal) {
            auto* b = qobject_cast<QMessageBox*>(modal);
            if (!b) return false;
            said = b->text() + u'\n' + b->informativeText();
            QTest::mouseClick(b->button(QMessageBox::Ok), Qt::LeftButton);
            return true;
        });
        auto name2 = answerFileDialog(bin);
        QVERIFY(clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Open log")));
        QVERIFY(waitFor([&] { return box2.answered(); }));
        QVERIFY2(
            said.contains(QStringLiteral("junk.bin")) && said.contains(QStringLiteral("not a format CoScope reads")),
            qPrintable(said));
        QCOMPARE(w.workspace()->store(), store);
        QCOMPARE(w.traceDock()->model()->rowCount(), 32);
    }
};

QTEST_MAIN(TestFilesMenu)
#include "test_files_menu.moc"
