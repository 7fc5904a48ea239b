// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 36: a project keeps the window's work beside the machine (plot layout, trace filter and
// Group SDO, the transmit list). A technician picks a signal, filters the trace, adds a frame to
// the transmit list, saves the project, changes all of it, and File ▸ Open project brings it back;
// the project file holds it as documented (README "Projects").

#include "app/gui/MainWindow.h"
#include "app/gui/master/TransmitDock.h"
#include "app/gui/master/TransmitModel.h"
#include "app/gui/plot/PlotDock.h"
#include "app/gui/plot/SignalPicker.h"
#include "app/gui/project/ProjectActions.h"
#include "app/gui/project/ProjectSession.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/TraceDock.h"
#include "core/project/ProjectFile.h"

#include <QAction>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QTemporaryDir>
#include <QToolBar>
#include <QTreeWidget>
#include <QtTest>

#include "tests/gui/DriveLog.h"
#include "tests/gui/ItemClick.h"
#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/TraceBar.h"
#include "tests/gui/TypeText.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::answerFileDialog;
using coscope::testing::clickCheckBox;
using coscope::testing::clickDockTab;
using coscope::testing::clickMenuItem;
using coscope::testing::DriveLog;
using coscope::testing::groupSdoButton;
using coscope::testing::signalItem;
using coscope::testing::typeAndEnter;
using coscope::testing::waitFor;

namespace {
// A Delta ASDA-A2 (node 5, identified by its 1018h answers) whose TPDO1 carries 6064h and 606Ch.
QString writeLog(const QString& path) {
    DriveLog log(1700000000.0);
    log.identifyDeltaAsda(5);
    log.mapTpdo(5, 1, {0x60640020, 0x606C0020});
    for (uint32_t i = 0; i < 200; ++i)
        log.line(QStringLiteral("185#") + DriveLog::le(i % 256, 4) + DriveLog::le(i * 3 % 256, 4), 0.01);
    return log.write(path) ? path : QString();
}

// Ticks or unticks a signal in the Plot dock's tree as a user does.
bool clickSignal(MainWindow& w, const QString& name) {
    auto* tree = w.plotDock()->findChild<QTreeWidget*>(QStringLiteral("signalTree"));
    QTreeWidgetItem* item = nullptr;
    if (!tree ||
        !waitFor([&] { return (item = signalItem(tree, 5, name)) && tree->visualItemRect(item).isValid(); }, 10000))
        return false;
    tree->scrollToItem(item);
    return clickCheckBox(tree, item);
}

QStringList picked(MainWindow& w) {
    QStringList out;
    for (const dissect::SignalKey& k : w.plotDock()->pickedSignals()) out << k.text();
    out.sort();
    return out;
}

}  // namespace

class TestProjectWindow : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_project_window"));
        QSettings().clear();
    }

    void plotFilterAndTransmitListComeBackWithTheProject() {
        const QString log = writeLog(dir_.filePath(QStringLiteral("axis.log")));
        QVERIFY(!log.isEmpty());
        MainWindow w;
        w.setQuiet(true);
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        {
            auto name = answerFileDialog(log);
            QVERIFY(clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Open log")));
            QVERIFY(waitFor([&] { return name->answered(); }));
        }
        QVERIFY(waitFor([&] { return w.workspace()->loadJob() && w.workspace()->loadJob()->isDone(); }));

        // The work: only the position plotted, overlaid; the trace filtered to node 5 with SDO
        // transfers grouped; a frame in the transmit list.
        QVERIFY(clickDockTab(w, QStringLiteral("Plot")));
        QVERIFY(waitFor(
            [&] {
                w.refresh();
                return picked(w).size() == 2;
            },
            10000));  // the position/velocity pair picked by itself
        QVERIFY(clickSignal(w, QStringLiteral("Velocity actual value")));
        QCOMPARE(picked(w), QStringList{QStringLiteral("n5 6064:00")});
        QVERIFY(clickDockTab(w, QStringLiteral("Trace")));
        auto* filter = w.traceDock()->findChild<QLineEdit*>(QStringLiteral("filterEdit"));
        QVERIFY(filter);
        typeAndEnter(filter, QStringLiteral("node:5"));
        QWidget* group = groupSdoButton(w);
        QVERIFY(group);
        QTest::mouseClick(group, Qt::LeftButton);
        QVERIFY(w.traceDock()->groupsSdo());
        QVERIFY(clickDockTab(w, QStringLiteral("Transmit")));
        TransmitDock* tx = w.transmitDock();
        QVERIFY(waitFor([&] { return tx->frameEdit()->isVisible(); }));
        QTest::mouseClick(tx->frameEdit(), Qt::LeftButton);
        QTest::keyClicks(tx->frameEdit(), QStringLiteral("123#1122"));
        QTest::mouseClick(tx->findChild<QPushButton*>(QStringLiteral("transmitAdd")), Qt::LeftButton);
        QCOMPARE(tx->model()->rowCount(), 1);

        const QString path = dir_.filePath(QStringLiteral("axis.coscope"));
        {
            auto name = answerFileDialog(path);
            QVERIFY(clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Save project as")));
            QVERIFY(waitFor([&] { return QFile::exists(path) && !w.projectActions()->session()->isModified(); }));
        }
        // In the file as documented.
        const auto saved = project::ProjectFile::read(path).project;
        QVERIFY(saved.has_value());
        QCOMPARE(saved->plots.value(QStringLiteral("signals")).toArray(), QJsonArray{QStringLiteral("n5 6064:00")});
        QCOMPARE(saved->traceFilters.value(QStringLiteral("filter")).toString(), QStringLiteral("node:5"));
        QVERIFY(saved->traceFilters.value(QStringLiteral("groupSdo")).toBool());
        QCOMPARE(saved->transmit.size(), qsizetype(1));

        // Everything changed after the save.
        QVERIFY(clickDockTab(w, QStringLiteral("Plot")));
        QVERIFY(clickSignal(w, QStringLiteral("Velocity actual value")));
        QVERIFY(clickSignal(w, QStringLiteral("Position actual value")));
        QCOMPARE(picked(w), QStringList{QStringLiteral("n5 606C:00")});
        QVERIFY(clickDockTab(w, QStringLiteral("Trace")));
        typeAndEnter(filter, QStringLiteral("svc:sdo"));
        QTest::mouseClick(group, Qt::LeftButton);
        QVERIFY(!w.traceDock()->groupsSdo());
        QVERIFY(clickDockTab(w, QStringLiteral("Transmit")));
        QTest::mouseClick(tx->view()->viewport(), Qt::LeftButton, {},
                          tx->view()->visualRect(tx->model()->index(0, TransmitModel::Id)).center());
        QTest::mouseClick(tx->findChild<QPushButton*>(QStringLiteral("transmitRemove")), Qt::LeftButton);
        QCOMPARE(tx->model()->rowCount(), 0);

        // File ▸ Open project gives the work back.
        {
            auto name = answerFileDialog(path);
            QVERIFY(clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Open project")));
            QVERIFY(waitFor([&] { return name->answered(); }));
        }
        QVERIFY(waitFor(
            [&] {
                w.refresh();
                return picked(w) == QStringList{QStringLiteral("n5 6064:00")};
            },
            10000));
        QCOMPARE(filter->text(), QStringLiteral("node:5"));
        QVERIFY(w.traceDock()->groupsSdo());
        QCOMPARE(tx->model()->rowCount(), 1);
        QCOMPARE(tx->model()->data(tx->model()->index(0, TransmitModel::Id)).toString(), QStringLiteral("123h"));
        QVERIFY(!w.projectActions()->session()->isModified());
    }
};

QTEST_MAIN(TestProjectWindow)
#include "test_project_window.moc"
