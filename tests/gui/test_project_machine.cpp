// SPDX-License-Identifier: GPL-3.0-or-later
// The machine kept as a project (issue 36, "Done when"), through input events on the real window:
// connect to the virtual drives, Project ▸ Back up the machine, File ▸ Save project as… (the
// file dialog answered), change two parameters of node 1 in the Object Dictionary dock's editor,
// put another drive of the same type (another serial number) at node 3, File ▸ Open project… (the
// file dialog answered), Project ▸ Compare with the machine: exactly those two objects differ and node 3 is "replaced"; Apply the project (dry
// run shown, one confirmation) puts them back, and the comparison run again is clean.
#include "app/gui/MainWindow.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/od/IntegerSpinBox.h"
#include "app/gui/od/ObjectDictionaryDock.h"
#include "app/gui/od/OdFilterModel.h"
#include "app/gui/od/OdTreeModel.h"
#include "app/gui/project/ApplyDialog.h"
#include "app/gui/project/CompareDialog.h"
#include "app/gui/project/CompareModel.h"
#include "app/gui/project/ProjectActions.h"
#include "app/gui/project/ProjectSession.h"
#include "app/gui/session/Workspace.h"
#include "core/project/ProjectFile.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"

#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QTableView>
#include <QTemporaryDir>
#include <QTreeView>
#include <QtTest>

#include "tests/gui/ItemClick.h"
#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::answerBox;
using coscope::testing::answerFileDialog;
using coscope::testing::clickDockTab;
using coscope::testing::clickMenuItem;
using coscope::testing::waitFor;

namespace {
sim::SimNetwork* net(MainWindow& w) { return static_cast<SimBus*>(w.workspace()->bus())->network(); }

uint64_t driveValue(MainWindow& w, uint8_t node, uint16_t index, uint8_t sub) {
    uint64_t v = ~0ull;
    net(w)->runOnNetworkThread(
        [&] { v = net(w)->device(node)->value(index, sub).value_or(od::Value{}).toUInt64().value_or(~0ull); });
    return v;
}

// Double-click on the value of index:sub in the OD dock, type `text`, Enter, Yes to the question.
bool editValue(MainWindow& w, uint16_t index, uint8_t sub, const QString& text) {
    ObjectDictionaryDock* dock = w.odDock();
    QTreeView* view = dock->view();
    const QModelIndex cell = dock->filter()->mapFromSource(dock->model()->indexOf(index, sub, OdTreeModel::Value));
    if (!cell.isValid() || !(cell.flags() & Qt::ItemIsEditable)) return false;
    w.activateWindow();
    if (!QTest::qWaitForWindowActive(&w)) return false;
    view->scrollTo(cell);
    const QPoint at = view->visualRect(cell).center();
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, at);
    QTest::mouseDClick(view->viewport(), Qt::LeftButton, {}, at);
    QTest::mouseRelease(view->viewport(), Qt::LeftButton, {}, at);
    auto editor = [&] { return view->findChild<IntegerSpinBox*>(QStringLiteral("odValueEditor")); };
    if (!waitFor([&] { return editor() != nullptr; }, 3000)) return false;
    IntegerSpinBox* spin = editor();
    QTest::keyClick(spin, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(spin, text);
    auto yes = answerBox(QMessageBox::Yes);
    QTest::keyClick(spin, Qt::Key_Return);
    return waitFor([&] { return yes->answered(); }, 5000);
}

// The rows the comparison shows with "Only differences": (node, object or state).
QStringList shownRows(CompareDialog* d) {
    QStringList out;
    CompareModel* m = d->model();
    for (int r = 0; r < m->rowCount(); ++r) {
        const QString object = m->index(r, CompareModel::Object).data().toString();
        out << QStringLiteral("%1 %2")
                   .arg(m->index(r, CompareModel::Node).data().toInt())
                   .arg(object.isEmpty() ? m->index(r, CompareModel::State).data().toString() : object);
    }
    return out;
}
}  // namespace

class TestProjectMachine : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_project_machine"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
    }

    void commissionSaveChangeReplaceCompareApply() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));

        // Commission: the virtual drives, found by the scan that follows a connection.
        QVERIFY(clickMenuItem(w, QStringLiteral("Bus"), QStringLiteral("Connect to virtual drives")));
        QVERIFY(waitFor(
            [&] {
                return w.workspace()->bus() && w.workspace()->bus()->state() == CanBus::State::Open &&
                       w.workspace()->nodes().node(3).has_value();
            },
            10000));
        {
            QString said;
            auto ok = answerBox(QMessageBox::Ok, &said);
            QVERIFY(clickMenuItem(w, QStringLiteral("Project"), QStringLiteral("Back up the machine")));
            QVERIFY(waitFor([&] { return ok->answered(); }, 30000));
            QVERIFY2(said.contains(QStringLiteral("Node 1:")) && said.contains(QStringLiteral("Node 3:")),
                     qPrintable(said));
        }
        ProjectSession* session = w.projectActions()->session();
        QCOMPARE(session->project().nodes.size(), size_t(3));
        QVERIFY(session->isModified());
        QVERIFY2(w.windowTitle().contains(QStringLiteral("[*]")) && w.isWindowModified(), qPrintable(w.windowTitle()));

        const QString path = dir_.filePath(QStringLiteral("line.coscope"));
        {
            auto name = answerFileDialog(path);
            QVERIFY(clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Save project as")));
            QVERIFY(waitFor([&] { return QFile::exists(path) && !session->isModified(); }, 10000));
        }
        QVERIFY2(w.windowTitle().startsWith(QStringLiteral("line[*]")) && !w.isWindowModified(),
                 qPrintable(w.windowTitle()));
        QVERIFY(project::ProjectFile::read(path).project.has_value());
        const uint64_t heartbeat = driveValue(w, 1, 0x1017, 0);
        const uint64_t velocity = driveValue(w, 1, 0x6081, 0);

        // Two parameters of node 1 changed as a technician does: the OD dock's editor.
        // Node 1 chosen as a user does: its row clicked in the Nodes dock (its tab first when the
        // dock sits behind another), which shows it in the Object Dictionary dock.
        w.showView(QStringLiteral("od"));
        const int row = w.nodesDock()->model()->rowOfNode(1);
        QVERIFY(row >= 0);
        QTableView* nodesView = w.nodesDock()->view();
        if (!nodesView->isVisible()) QVERIFY(clickDockTab(w, w.nodesDock()->windowTitle()));
        QVERIFY(waitFor([&] { return nodesView->isVisible(); }, 3000));
        QTest::mouseClick(nodesView->viewport(), Qt::LeftButton, {},
                          nodesView->visualRect(w.nodesDock()->model()->index(row, 0)).center());
        QVERIFY(waitFor([&] { return w.odDock()->node() == 1; }, 3000));
        if (!w.odDock()->isVisible() || w.odDock()->visibleRegion().isEmpty())
            clickDockTab(w, w.odDock()->windowTitle());
        QVERIFY(waitFor(
            [&] {
                w.refresh();
                return w.odDock()->node() == 1 && w.odDock()->model()->hasDictionary();
            },
            5000));
        QVERIFY(editValue(w, 0x1017, 0, QStringLiteral("700")));
        QVERIFY(editValue(w, 0x6081, 0, QStringLiteral("4321")));
        QVERIFY(
            waitFor([&] { return driveValue(w, 1, 0x1017, 0) == 700 && driveValue(w, 1, 0x6081, 0) == 4321; }, 5000));

        // Node 3: another drive of the same type, another serial number, factory values.
        QString error;
        QVERIFY2(net(w)->replaceDevice(3, 0x51000099, &error), qPrintable(error));

        // The technician opens the project (File ▸ Open project…, the file dialog answered),
        // then compares: the machine against what was saved.
        // (File ▸ New project first: what the comparison uses then comes from the file.)
        QVERIFY(clickMenuItem(w, QStringLiteral("File"), QStringLiteral("New project")));
        QVERIFY(waitFor([&] { return session->path().isEmpty() && session->project().nodes.empty(); }, 3000));
        {
            auto name = answerFileDialog(path);
            QVERIFY(clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Open project")));
            QVERIFY(waitFor([&] { return name->answered() && session->path() == path; }, 10000));
        }
        QCOMPARE(session->project().nodes.size(), size_t(3));
        QVERIFY2(w.windowTitle().startsWith(QStringLiteral("line[*]")), qPrintable(w.windowTitle()));

        QVERIFY(clickMenuItem(w, QStringLiteral("Project"), QStringLiteral("Compare with the machine")));
        CompareDialog* compare = w.projectActions()->compareDialog();
        QVERIFY(compare);
        QVERIFY(waitFor([&] { return compare->hasResult() && !compare->isRunning(); }, 30000));
        QVERIFY(compare->onlyDifferencesBox()->isChecked());
        QCOMPARE(shownRows(compare),
                 (QStringList{QStringLiteral("1 1017:00"), QStringLiteral("1 6081:00"),
                              QStringLiteral("3 %1").arg(CompareModel::matchText(project::NodeMatch::Replaced))}));
        const auto& report = compare->model()->report();
        QCOMPARE(report.rows.front().node, uint8_t(1));

        // Apply the project: dry run, one confirmation, written; compared again at once.
        QTest::mouseClick(compare->applyButton(), Qt::LeftButton);
        QVERIFY(waitFor([&] { return compare->applyDialog() != nullptr; }, 3000));
        auto* apply = qobject_cast<ApplyDialog*>(compare->applyDialog());
        QVERIFY(waitFor([&] { return apply->applyButton()->isEnabled(); }, 20000));
        const QString dryRun = apply->reportText();
        QVERIFY2(dryRun.contains(QStringLiteral("write 1017:00")) && dryRun.contains(QStringLiteral("write 6081:00")),
                 qPrintable(dryRun));
        QString asked;
        {
            auto yes = answerBox(QMessageBox::Yes, &asked);
            QTest::mouseClick(apply->applyButton(), Qt::LeftButton);
            QVERIFY(waitFor([&] { return apply->finished(); }, 20000));
        }
        QVERIFY2(asked.contains(QStringLiteral("Write 2 object(s)")), qPrintable(asked));
        QVERIFY(apply->lastReport().ok());
        QCOMPARE(driveValue(w, 1, 0x1017, 0), heartbeat);
        QCOMPARE(driveValue(w, 1, 0x6081, 0), velocity);
        // The new drive at node 3 holds the project's values: the project expects it now.
        QCOMPARE(session->project().node(3)->identity.serial, std::optional<uint32_t>(0x51000099));
        QVERIFY(
            waitFor([&] { return compare->hasResult() && !compare->isRunning() && compare->model()->report().clean(); },
                    30000));
        QCOMPARE(compare->model()->rowCount(), 0);

        // Quitting asks about the project changed since it was saved (the new serial).
        QString quitAsked;
        auto discard = answerBox(QMessageBox::Discard, &quitAsked);
        apply->close();
        compare->close();
        w.close();
        QVERIFY(waitFor([&] { return discard->answered(); }, 5000));
        QVERIFY2(quitAsked.contains(QStringLiteral("line")), qPrintable(quitAsked));
    }
};

QTEST_MAIN(TestProjectMachine)
#include "test_project_machine.moc"
