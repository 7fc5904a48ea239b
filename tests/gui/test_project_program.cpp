// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 36, through input events on the real window:
// - the project's program from the Nodes dock: a project names the image node 1 runs
//   (nodes[].firmware); File ▸ Open project…, right-click node 1 ▸ "Download the project's
//   program…" opens the program download dialog with that image, Download (the question answered)
//   loads it and the virtual drive answers the project's version in 100Ah; a node the project
//   names no program for has the entry disabled;
// - Project ▸ Back up the machine also keeps the program each node runs (1F56h, 100Ah);
// - a backup whose bus closes half-way (Bus ▸ Disconnect) says so and leaves the project as it was.
#include "app/gui/MainWindow.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/program/ProgramDownloadDialog.h"
#include "app/gui/project/ProjectActions.h"
#include "app/gui/project/ProjectSession.h"
#include "app/gui/session/Workspace.h"
#include "core/sim/ProgramFlash.h"
#include "core/sim/ProgramImage.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"

#include <QFile>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QtTest>

#include "tests/gui/ContextMenuClick.h"
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
using coscope::testing::contextMenuClick;
using coscope::testing::waitFor;

namespace {
sim::SimNetwork* net(MainWindow& w) { return static_cast<SimBus*>(w.workspace()->bus())->network(); }

bool connectVirtualDrives(MainWindow& w) {
    if (!clickMenuItem(w, QStringLiteral("Bus"), QStringLiteral("Connect to virtual drives"))) return false;
    return waitFor(
        [&] {
            return w.workspace()->bus() && w.workspace()->bus()->state() == CanBus::State::Open &&
                   w.workspace()->nodes().node(3).has_value();
        },
        10000);
}

// Right-click on node `node`'s row of the Nodes dock (its tab first), then the menu's `text`.
bool nodeMenu(MainWindow& w, int node, const QString& text) {
    NodesDock* dock = w.nodesDock();
    QTableView* view = dock->view();
    if (!view->isVisible()) clickDockTab(w, dock->windowTitle());
    if (!waitFor(
            [&] {
                dock->refresh();
                return view->isVisible() && dock->model()->rowOfNode(node) >= 0;
            },
            5000))
        return false;
    const QPoint pos = view->visualRect(view->model()->index(dock->model()->rowOfNode(node), 0)).center();
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, pos);
    return contextMenuClick(view, pos, text);
}

bool openProject(MainWindow& w, const QString& path) {
    auto name = answerFileDialog(path);
    if (!clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Open project"))) return false;
    return waitFor([&] { return name->answered() && w.projectActions()->session()->path() == path; }, 10000);
}
}  // namespace

class TestProjectProgram : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_project_program"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
    }

    void nodesDockDownloadsTheProjectsProgram() {
        // The image beside the project, named relative to it, as the README's example does.
        QByteArray payload(64 * 1024, Qt::Uninitialized);
        for (qsizetype i = 0; i < payload.size(); ++i) payload[i] = static_cast<char>(i * 7 + (i >> 8));
        QFile image(dir_.filePath(QStringLiteral("asda-a2-2.0.img")));
        QVERIFY(image.open(QIODevice::WriteOnly));
        image.write(sim::makeProgramImage(payload, QStringLiteral("2.0")));
        image.close();
        const QString path = dir_.filePath(QStringLiteral("line.coscope"));
        QFile project(path);
        QVERIFY(project.open(QIODevice::WriteOnly));
        project.write(R"({"format": 1, "name": "Line 2", "nodes": [
            {"id": 1, "name": "ASDA-A2", "dictionary": "delta-asda-a2",
             "firmware": {"file": "asda-a2-2.0.img", "program": 1, "version": "2.0"}},
            {"id": 2, "name": "AIMOTOR", "dictionary": "aimotor"}]})");
        project.close();

        MainWindow w;
        w.setQuiet(true);
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(connectVirtualDrives(w));
        QVERIFY(openProject(w, path));

        // Node 2: the project names no program for it, the entry is there but disabled.
        QVERIFY(!nodeMenu(w, 2, QStringLiteral("Download the project's program…")));
        // Node 1: the dialog opens with the project's image.
        QVERIFY(nodeMenu(w, 1, QStringLiteral("Download the project's program…")));
        ProgramDownloadDialog* dialog = nullptr;
        QVERIFY(waitFor([&] { return (dialog = w.findChild<ProgramDownloadDialog*>()) && dialog->isVisible(); }, 5000));
        auto* file = dialog->findChild<QLineEdit*>(QStringLiteral("programFile"));
        auto* download = dialog->findChild<QPushButton*>(QStringLiteral("downloadButton"));
        QVERIFY(file && download);
        QCOMPARE(file->text(), image.fileName());
        QVERIFY(waitFor([&] { return download->isEnabled(); }, 5000));
        QString asked;
        {
            auto yes = answerBox(QMessageBox::Yes, &asked);
            QTest::mouseClick(download, Qt::LeftButton);
            QVERIFY(waitFor([&] { return dialog->outcome().has_value(); }, 30000));
        }
        QVERIFY2(asked.contains(QStringLiteral("node 1")), qPrintable(asked));
        QVERIFY(dialog->outcome()->ok);
        QString version;
        net(w)->runOnNetworkThread([&] { version = net(w)->device(1)->programFlash().version(); });
        QCOMPARE(version, QStringLiteral("2.0"));
        dialog->close();

        // Back up: the program each node runs is kept with the image the project names.
        {
            QString said;
            auto ok = answerBox(QMessageBox::Ok, &said);
            QVERIFY(clickMenuItem(w, QStringLiteral("Project"), QStringLiteral("Back up the machine")));
            QVERIFY(waitFor([&] { return ok->answered(); }, 30000));
            QVERIFY2(said.contains(QStringLiteral("software version 2.0")), qPrintable(said));
        }
        const project::ProjectNode* n1 = w.projectActions()->session()->project().node(1);
        QVERIFY(n1 && n1->firmware);
        QCOMPARE(n1->firmware->version, QStringLiteral("2.0"));
        QCOMPARE(n1->firmware->file, QStringLiteral("asda-a2-2.0.img"));
        const project::ProjectNode* n3 = w.projectActions()->session()->project().node(3);
        QVERIFY(n3 && n3->firmware);
        QVERIFY(!n3->firmware->version.isEmpty());

        auto discard = answerBox(QMessageBox::Discard);
        w.close();
        QVERIFY(waitFor([&] { return discard->answered(); }, 5000));
    }

    void backupCutByDisconnectSaysSo() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QVERIFY(connectVirtualDrives(w));
        ProjectSession* session = w.projectActions()->session();
        QVERIFY(clickMenuItem(w, QStringLiteral("Project"), QStringLiteral("Back up the machine")));
        // Half-way: the first node's objects are being read.
        QVERIFY(
            waitFor([&] { return w.statusBar()->currentMessage().contains(QStringLiteral("reading node")); }, 10000));
        QString said;
        auto ok = answerBox(QMessageBox::Ok, &said);
        QVERIFY(clickMenuItem(w, QStringLiteral("Bus"), QStringLiteral("Disconnect")));
        QVERIFY(waitFor([&] { return ok->answered(); }, 10000));
        QVERIFY2(said.contains(QStringLiteral("before the backup was finished")), qPrintable(said));
        QVERIFY(session->project().nodes.empty());
        // A second backup can start on the next bus (the first one is over).
        QVERIFY(connectVirtualDrives(w));
        QString second;
        auto done = answerBox(QMessageBox::Ok, &second);
        QVERIFY(clickMenuItem(w, QStringLiteral("Project"), QStringLiteral("Back up the machine")));
        QVERIFY(waitFor([&] { return done->answered(); }, 30000));
        QVERIFY2(second.contains(QStringLiteral("Node 3:")), qPrintable(second));
        auto discard = answerBox(QMessageBox::Discard);
        w.close();
        QVERIFY(waitFor([&] { return discard->answered(); }, 5000));
    }
};

QTEST_MAIN(TestProjectProgram)
#include "test_project_program.moc"
