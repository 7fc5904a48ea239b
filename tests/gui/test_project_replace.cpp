// SPDX-License-Identifier: GPL-3.0-or-later
// Replacing a drive, guided (issue 36 item 4), through input events on the real window and the
// virtual drives: the machine backed up and saved as a project; node 3's drive taken out and a
// new one of the same type put in, at its factory node-ID 127 (another serial number, factory
// values); Project ▸ Compare: node 3 missing, node 127 not in the project. Node 3's row selected,
// Replace drive…: the box names node 127, the node-ID wizard opens on it with node-ID 3 chosen;
// LSS picked, Next, "Change it now": the drive answers at node 3, the Apply dialog shows node 3's
// writes (its heartbeat time), one confirmation writes them, and the comparison run again is
// clean with the new drive expected by the project.
#include "app/gui/MainWindow.h"
#include "app/gui/project/ApplyDialog.h"
#include "app/gui/project/CompareDialog.h"
#include "app/gui/project/CompareModel.h"
#include "app/gui/project/ProjectActions.h"
#include "app/gui/project/ProjectSession.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/nodeid/NodeIdPages.h"
#include "app/gui/wizards/nodeid/NodeIdWizard.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"

#include <QMessageBox>
#include <QPushButton>
#include <QRadioButton>
#include <QSettings>
#include <QTableView>
#include <QTemporaryDir>
#include <QtTest>

#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::answerBox;
using coscope::testing::answerFileDialog;
using coscope::testing::clickMenuItem;
using coscope::testing::waitFor;

namespace {
sim::SimNetwork* net(MainWindow& w) { return static_cast<SimBus*>(w.workspace()->bus())->network(); }

void click(QAbstractButton* b) { QTest::mouseClick(b, Qt::LeftButton, {}, b->rect().center()); }

// Clicks the comparison's row of `node` whose state column says `state`.
bool clickCompareRow(CompareDialog* d, int node, const QString& state) {
    CompareModel* m = d->model();
    for (int r = 0; r < m->rowCount(); ++r)
        if (m->index(r, CompareModel::Node).data().toInt() == node &&
            m->index(r, CompareModel::State).data().toString() == state) {
            QTableView* t = d->table();
            t->scrollTo(m->index(r, 0));
            QTest::mouseClick(t->viewport(), Qt::LeftButton, {}, t->visualRect(m->index(r, 0)).center());
            return t->selectionModel()->isRowSelected(r, {});
        }
    return false;
}

NodeIdWizard* shownWizard() {
    for (QWidget* w : QApplication::topLevelWidgets())
        if (auto* x = qobject_cast<NodeIdWizard*>(w); x && x->isVisible()) return x;
    return nullptr;
}
}  // namespace

class TestProjectReplace : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_project_replace"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
    }

    void missingDriveReplacedByNewOne() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));

        QVERIFY(clickMenuItem(w, QStringLiteral("Bus"), QStringLiteral("Connect to virtual drives")));
        QVERIFY(waitFor(
            [&] {
                return w.workspace()->bus() && w.workspace()->bus()->state() == CanBus::State::Open &&
                       w.workspace()->nodes().node(3).has_value();
            },
            10000));
        // Node 3 as commissioned: its heartbeat time set (the drive's own value, as kept in it).
        net(w)->runOnNetworkThread([&] { net(w)->device(3)->setValue(0x1017, 0, od::Value::unsignedInt(333)); });
        {
            auto ok = answerBox(QMessageBox::Ok);
            QVERIFY(clickMenuItem(w, QStringLiteral("Project"), QStringLiteral("Back up the machine")));
            QVERIFY(waitFor([&] { return ok->answered(); }, 30000));
        }
        ProjectSession* session = w.projectActions()->session();
        QVERIFY(session->project().node(3) && session->project().node(3)->parameter(0x1017, 0));
        const QString path = dir_.filePath(QStringLiteral("cell.coscope"));
        {
            auto name = answerFileDialog(path);
            QVERIFY(clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Save project as")));
            QVERIFY(waitFor([&] { return QFile::exists(path) && !session->isModified(); }, 10000));
        }

        // Node 3's drive out; a new one of the same type in, at its factory node-ID 127.
        QString error;
        QVERIFY2(net(w)->replaceDevice(3, 0x51000042, &error, 127), qPrintable(error));

        QVERIFY(clickMenuItem(w, QStringLiteral("Project"), QStringLiteral("Compare with the machine")));
        CompareDialog* compare = w.projectActions()->compareDialog();
        QVERIFY(compare);
        QVERIFY(waitFor([&] { return compare->hasResult() && !compare->isRunning(); }, 30000));
        const QString missing = CompareModel::matchText(project::NodeMatch::Missing);
        QVERIFY(clickCompareRow(compare, 127, CompareModel::matchText(project::NodeMatch::NotInProject)));
        QVERIFY(!compare->replaceButton()->isEnabled());
        QVERIFY(clickCompareRow(compare, 3, missing));
        QVERIFY(compare->replaceButton()->isEnabled());

        // Replace drive…: the box names the new drive; its button opens the node-ID wizard on it.
        QString said;
        {
            auto open = answerBox(QMessageBox::Ok, &said);
            click(compare->replaceButton());
            QVERIFY(waitFor([&] { return open->answered(); }, 5000));
        }
        QVERIFY2(said.contains(QStringLiteral("node 127")), qPrintable(said));
        NodeIdWizard* wizard = nullptr;
        QVERIFY(waitFor([&] { return (wizard = shownWizard()) != nullptr; }, 5000));
        QCOMPARE(wizard->node(), 127);
        QSignalSpy finished(wizard, &NodeIdWizard::finished);
        click(wizard->button(QWizard::NextButton));
        QVERIFY(waitFor([&] { return wizard->currentId() == NodeIdWizard::ChangePageId; }, 3000));
        QCOMPARE(wizard->findChild<QAbstractSpinBox*>(QStringLiteral("newNodeId"))->text(), QStringLiteral("3"));
        click(wizard->findChild<QRadioButton*>(QStringLiteral("viaLss")));
        QSignalSpy ready(wizard, &NodeIdWizard::dryRunReady);
        click(wizard->button(QWizard::NextButton));
        QVERIFY2(waitFor([&] { return wizard->currentId() == NodeIdWizard::RunPageId; }, 3000),
                 qPrintable(wizard->blockingProblem() + QStringLiteral(" | ") + wizard->explanation()));
        QVERIFY(ready.count() > 0 || ready.wait(8000));
        QVERIFY2(ready.last().at(0).toBool(), qPrintable(wizard->planError() + wizard->blockingProblem()));
        click(wizard->runPage()->runButton());
        QVERIFY(finished.count() > 0 || finished.wait(30000));
        QVERIFY2(finished.last().at(0).toBool(), qPrintable(wizard->outcomeText()));

        // Then node 3's configuration: the Apply dialog opens by itself with the dry run.
        QVERIFY(waitFor([&] { return compare->applyDialog() != nullptr; }, 5000));
        auto* apply = qobject_cast<ApplyDialog*>(compare->applyDialog());
        QVERIFY(waitFor([&] { return apply->applyButton()->isEnabled(); }, 20000));
        QVERIFY2(apply->reportText().contains(QStringLiteral("write 1017:00")), qPrintable(apply->reportText()));
        {
            auto yes = answerBox(QMessageBox::Yes);
            click(apply->applyButton());
            QVERIFY(waitFor([&] { return apply->finished(); }, 20000));
        }
        QVERIFY(apply->lastReport().ok());
        uint64_t heartbeat = 0;
        net(w)->runOnNetworkThread(
            [&] { heartbeat = net(w)->device(3)->value(0x1017, 0).value_or(od::Value{}).toUInt64().value_or(0); });
        QCOMPARE(heartbeat, uint64_t(333));
        QCOMPARE(session->project().node(3)->identity.serial, std::optional<uint32_t>(0x51000042));
        QVERIFY(
            waitFor([&] { return compare->hasResult() && !compare->isRunning() && compare->model()->report().clean(); },
                    30000));

        auto discard = answerBox(QMessageBox::Discard);
        apply->close();
        compare->close();
        wizard->close();
        w.close();
        QVERIFY(waitFor([&] { return discard->answered(); }, 5000));
    }
};

QTEST_MAIN(TestProjectReplace)
#include "test_project_replace.moc"
