// SPDX-License-Identifier: GPL-3.0-or-later
// The program download dialog as a technician uses it, through input events only: the Nodes
// dock's context menu ▸ Download program… on node 1, the file typed in, what the node reports
// now, Download (confirmed in the question that says the node stops its application), Cancel
// half-way (nothing claimed), Download again from the start, and the result with the old and
// the new software version, which the virtual drive then reports in 100Ah. On a listen-only bus
// the menu entry is disabled with the reason.
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/program/ProgramDownloadDialog.h"
#include "core/sim/ProgramFlash.h"
#include "core/sim/ProgramImage.h"
#include "eds/SimulatorDictionaries.h"

#include <QAction>
#include <QCheckBox>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QProgressBar>
#include <QPushButton>
#include <QTableView>
#include <QTemporaryDir>
#include <QtTest>

#include "tests/gui/ContextMenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/SimDriveRig.h"

using namespace coscope;
using namespace coscope::gui;

namespace {
bool nodeMenu(NodesDock& dock, int node, const QString& text) {
    QTableView* view = dock.view();
    const QPoint pos = view->visualRect(view->model()->index(dock.model()->rowOfNode(node), 0)).center();
    QTest::mouseClick(view->viewport(), Qt::LeftButton, {}, pos);
    return coscope::testing::contextMenuClick(view, pos, text);
}

bool waitForNodes(NodesDock& dock, int n) {
    return QTest::qWaitFor(
        [&] {
            dock.refresh();
            return dock.model()->rowCount() >= n;
        },
        5000);
}
}  // namespace

class TestProgramDownload : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        eds::installSimulatorDictionaries();
        QVERIFY(dir_.isValid());
    }

    void cancelThenDownloadAgainShowsTheNewVersion() {
        coscope::testing::SimDriveRig rig;
        QVERIFY(rig.open(QStringLiteral("sim://?nodes=1:delta-asda-a2")));
        NodesDock dock(&rig.ws);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        QVERIFY(waitForNodes(dock, 1));

        QByteArray payload(256 * 1024, Qt::Uninitialized);
        for (qsizetype i = 0; i < payload.size(); ++i) payload[i] = static_cast<char>(i * 31 + (i >> 9));
        const QString path = dir_.filePath(QStringLiteral("drive-2.0.0.img"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(sim::makeProgramImage(payload, QStringLiteral("2.0.0")));
        f.close();

        QVERIFY(nodeMenu(dock, 1, QStringLiteral("Download program…")));
        ProgramDownloadDialog* dialog = nullptr;
        QVERIFY(QTest::qWaitFor(
            [&] { return (dialog = dock.findChild<ProgramDownloadDialog*>()) && dialog->isVisible(); }, 5000));
        auto* version = dialog->findChild<QLabel*>(QStringLiteral("programVersion"));
        auto* status = dialog->findChild<QLabel*>(QStringLiteral("programStatus"));
        auto* progress = dialog->findChild<QProgressBar*>(QStringLiteral("programProgress"));
        auto* download = dialog->findChild<QPushButton*>(QStringLiteral("downloadButton"));
        auto* cancel = dialog->findChild<QPushButton*>(QStringLiteral("cancelButton"));
        auto* block = dialog->findChild<QCheckBox*>();
        QVERIFY(version && status && progress && download && cancel && block);
        // What the node reports now: the Delta drive's first version (the simulator's "1.0").
        QVERIFY(QTest::qWaitFor([&] { return version->text() == QStringLiteral("1.0"); }, 5000));
        QVERIFY(!download->isEnabled());  // no file yet
        QTest::keyClicks(dialog->findChild<QLineEdit*>(QStringLiteral("programFile")), path);
        QVERIFY(download->isEnabled());

        // First try: segmented (slow enough to cancel half-way), confirmed, then cancelled.
        QTest::mouseClick(block, Qt::LeftButton, {}, QPoint(6, block->height() / 2));
        QVERIFY(!block->isChecked());
        QString asked;
        {
            auto yes = coscope::testing::answerBox(QMessageBox::Yes, &asked);
            QTest::mouseClick(download, Qt::LeftButton);
            QVERIFY(QTest::qWaitFor([&] { return progress->value() > 0; }, 10000));
        }
        QVERIFY2(asked.contains(QStringLiteral("into program 1 of node 1")), qPrintable(asked));
        QVERIFY(cancel->isEnabled());
        QVERIFY(!download->isEnabled());
        QTest::mouseClick(cancel, Qt::LeftButton);
        QVERIFY(QTest::qWaitFor([&] { return dialog->outcome().has_value(); }, 10000));
        QVERIFY(!dialog->outcome()->ok);
        QVERIFY(dialog->outcome()->cancelled);
        QVERIFY2(status->text().contains(QStringLiteral("Cancelled")), qPrintable(status->text()));
        QVERIFY2(status->text().contains(QStringLiteral("Nothing is claimed")), qPrintable(status->text()));
        QCOMPARE(download->text(), QStringLiteral("Download again (from the start)"));
        bool running = true;
        rig.net()->runOnNetworkThread([&] { running = rig.net()->device(1)->programFlash().running(); });
        QVERIFY(!running);

        // Again, by block transfer: done, with the old and the new version.
        QTest::mouseClick(block, Qt::LeftButton, {}, QPoint(6, block->height() / 2));
        QVERIFY(block->isChecked());
        {
            auto yes = coscope::testing::answerBox(QMessageBox::Yes);
            QTest::mouseClick(download, Qt::LeftButton);
            QVERIFY(QTest::qWaitFor([&] { return dialog->outcome().has_value(); }, 30000));
        }
        QVERIFY2(dialog->outcome()->ok, qPrintable(status->text()));
        QVERIFY2(status->text().contains(QStringLiteral("Software version 1.0 → 2.0.0")), qPrintable(status->text()));
        QCOMPARE(version->text(), QStringLiteral("2.0.0"));
        QCOMPARE(progress->value(), 1000);
        QString v;
        rig.net()->runOnNetworkThread([&] { v = rig.net()->device(1)->programFlash().version(); });
        QCOMPARE(v, QStringLiteral("2.0.0"));
        QPushButton* close = nullptr;
        for (QPushButton* b : dialog->findChildren<QPushButton*>())
            if (b->text().remove(u'&') == QStringLiteral("Close")) close = b;
        QVERIFY(close && close->isEnabled());
        QTest::mouseClick(close, Qt::LeftButton);
        QVERIFY(QTest::qWaitFor([&] { return !dock.findChild<ProgramDownloadDialog*>(); }, 5000));
    }

    void listenOnlyDisablesTheEntryWithTheReason() {
        coscope::testing::SimDriveRig rig;
        QVERIFY(rig.open(QStringLiteral("sim://?nodes=1:delta-asda-a2&listen-only=1")));
        NodesDock dock(&rig.ws);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        QVERIFY(waitForNodes(dock, 1));
        QVERIFY(!nodeMenu(dock, 1, QStringLiteral("Download program…")));  // there, but disabled
        QVERIFY(!dock.programDownloadAction()->isEnabled());
        QVERIFY2(dock.programDownloadAction()->toolTip().contains(QStringLiteral("Listen-only")),
                 qPrintable(dock.programDownloadAction()->toolTip()));
        QVERIFY(!dock.findChild<ProgramDownloadDialog*>());
    }
};

QTEST_MAIN(TestProgramDownload)
#include "test_program_download.moc"
