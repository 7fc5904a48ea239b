// SPDX-License-Identifier: GPL-3.0-or-later
// The wizard kit against the virtual drives: the frames pane shows the node's SDO request and
// response decoded after markStart (and not other nodes' traffic or older frames); the script
// preview lists the steps, marks them, and saves a file CommandScript::load reads back
// identically; the guard explains listen-only and disables what sends.
#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/common/ScriptPreview.h"
#include "app/gui/wizards/common/ScriptRunPanel.h"
#include "app/gui/wizards/common/WizardFramesPane.h"
#include "app/gui/wizards/common/WizardGuard.h"
#include "app/gui/wizards/ds402/Ds402Wizard.h"
#include "core/canopen/SdoClient.h"
#include "eds/SimulatorDictionaries.h"

#include <QPushButton>
#include <QTabBar>
#include <QTabWidget>
#include <QTableView>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace coscope;
using namespace coscope::gui;
using namespace coscope::canopen;

namespace {

bool connectSim(Workspace& w, const QString& url) {
    QString error;
    if (!w.connectBus(url, &error)) {
        qWarning() << error;
        return false;
    }
    return QTest::qWaitFor([&] { return w.bus() && w.bus()->state() == CanBus::State::Open; }, 5000);
}

CommandScript sample() {
    CommandScript s;
    s.title = QStringLiteral("Kit sample");
    s.steps.push_back(
        ScriptStep::nmtCommand(NmtCommand::EnterPreOperational, 3, QStringLiteral("Stop process data (NMT)")));
    s.steps.push_back(ScriptStep::sdoWrite(3, 0x1017, 0, 750, 2, QStringLiteral("Heartbeat every 750 ms")));
    s.steps.push_back(ScriptStep::sdoExpect(3, 0x6041, 0, 0x27, 2, 0x6F, QStringLiteral("Operation enabled?")));
    s.steps.push_back(ScriptStep::waitForNode(3, 2000, QStringLiteral("Back after reset")));
    return s;
}

}  // namespace

class TestWizardKit : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { eds::installSimulatorDictionaries(); }

    void framesPaneShowsDecodedSdoAfterMark() {
        Workspace w;
        QVERIFY(connectSim(w, QStringLiteral("sim://?nodes=1:generic-cia402,3:generic-cia402")));
        WizardFramesPane pane(&w);
        pane.resize(900, 300);
        pane.show();
        // Older traffic (boot-ups, an SDO read) must not show after the mark.
        auto first = std::make_shared<std::optional<SdoResult>>();
        w.sdo()->upload(3, 0x1000, 0, [first](const SdoResult& r) { *first = r; });
        QTRY_VERIFY_WITH_TIMEOUT(first->has_value(), 5000);
        QTest::qWait(100);
        pane.setNode(3);
        pane.markStart();
        QCOMPARE(pane.rowCount(), 0);
        // Node 1 traffic is not for this pane; node 3's is.
        auto other = std::make_shared<std::optional<SdoResult>>();
        w.sdo()->upload(1, 0x1018, 1, [other](const SdoResult& r) { *other = r; });
        auto read = std::make_shared<std::optional<SdoResult>>();
        w.sdo()->upload(3, 0x1018, 1, [read](const SdoResult& r) { *read = r; });
        QTRY_VERIFY_WITH_TIMEOUT(read->has_value() && other->has_value(), 5000);
        QVERIFY((*read)->ok);
        QTRY_VERIFY_WITH_TIMEOUT(pane.rowCount() >= 2, 3000);
        QStringList rows;
        for (int i = 0; i < pane.rowCount(); ++i) rows << pane.rowText(i);
        const QString all = rows.join(u'\n');
        QVERIFY2(rows[0].startsWith(QStringLiteral("Tx 603 40 18 10 01 00 00 00 00  ")), qPrintable(all));
        QVERIFY2(rows[0].contains(QStringLiteral("1018")), qPrintable(all));
        QVERIFY2(rows[1].startsWith(QStringLiteral("Rx 583 43 18 10 01 ")), qPrintable(all));
        QVERIFY2(rows[1].size() > QStringLiteral("Rx 583 43 18 10 01 00 00 00 00  ").size(),
                 qPrintable(all));  // a decoded summary follows
        QVERIFY2(!all.contains(QStringLiteral(" 601 ")) && !all.contains(QStringLiteral(" 581 ")), qPrintable(all));
        QVERIFY2(!all.contains(QStringLiteral("40 00 10 00")), qPrintable(all));  // the 1000h read before the mark

        // Appends without reset: a further request adds rows after the existing ones.
        const QString firstRow = pane.rowText(0);
        const int before = pane.rowCount();
        auto again = std::make_shared<std::optional<SdoResult>>();
        w.sdo()->upload(3, 0x1018, 2, [again](const SdoResult& r) { *again = r; });
        QTRY_VERIFY_WITH_TIMEOUT(pane.rowCount() >= before + 2, 5000);
        QCOMPARE(pane.rowText(0), firstRow);

        QPixmap shot = pane.grab();
        QVERIFY(!shot.isNull());
        shot.save(QStringLiteral(COSCOPE_TEST_BINARY_DIR) + QStringLiteral("/wizard_frames_pane.png"));
    }

    // Issue 12: step rows one text line high, so a 19-step plan shows at least 10 steps.
    void previewRowsAreOneLineHigh() {
        CommandScript s;
        for (int i = 0; i < 19; ++i) {
            ScriptStep st = ScriptStep::sdoWrite(3, 0x1A00, static_cast<uint8_t>(1 + i % 8), 0x60410010u, 4, {});
            st.why = QStringLiteral(
                         "Mapping entry %1: the statusword (6041h, 16 bits) goes into the message at this place, "
                         "after the objects mapped before it, so the controller reads it there")
                         .arg(i + 1);
            s.steps.push_back(st);
        }
        ScriptPreview preview;
        preview.resize(1000, 420);
        preview.show();
        QVERIFY(QTest::qWaitForWindowExposed(&preview));
        preview.setScript(s);
        auto* table = preview.findChild<QTableWidget*>(QStringLiteral("scriptSteps"));
        QVERIFY(table);
        QTest::qWait(50);
        int visible = 0;
        for (int r = 0; r < table->rowCount(); ++r) {
            const QRect rect = table->visualRect(table->model()->index(r, 1));
            if (rect.isValid() && table->viewport()->rect().contains(rect)) ++visible;
        }
        QVERIFY2(visible >= 10, qPrintable(QStringLiteral("%1 of 19 steps visible").arg(visible)));
        QCOMPARE(table->item(0, 1)->text(), QStringLiteral("Write 1A00h:01 = 60410010h on node 3"));
    }

    // Issue 12: one "Save as script…" on the CiA 402 wizard's dry-run tab, not two.
    void oneSaveButtonPerTab() {
        Workspace w;
        QVERIFY(connectSim(w, QStringLiteral("sim://?nodes=3:generic-cia402")));
        Ds402Wizard wiz(&w, 3);
        wiz.show();
        QVERIFY(QTest::qWaitForWindowExposed(&wiz));
        // The wizard has two tab sets (frames / dry run, and its pages): the one with Dry run.
        QTabWidget* tabs = nullptr;
        int dry = -1;
        for (QTabWidget* t : wiz.findChildren<QTabWidget*>())
            for (int i = 0; i < t->count(); ++i)
                if (t->tabText(i).startsWith(QStringLiteral("Dry run"))) {
                    tabs = t;
                    dry = i;
                }
        QVERIFY(tabs && dry >= 0);
        QTest::mouseClick(tabs->tabBar(), Qt::LeftButton, {}, tabs->tabBar()->tabRect(dry).center());
        QTRY_COMPARE(tabs->currentIndex(), dry);
        int visible = 0;
        for (QPushButton* b : wiz.findChildren<QPushButton*>())
            if (b->isVisible() && b->text() == QStringLiteral("Save as script…")) ++visible;
        QCOMPARE(visible, 1);
    }

    void previewListsMarksAndSaves() {
        ScriptPreview preview;
        preview.resize(1100, 300);
        preview.show();
        const CommandScript s = sample();
        preview.setScript(s);
        QCOMPARE(preview.rowCount(), 4);
        auto* table = preview.findChild<QTableWidget*>(QStringLiteral("scriptSteps"));
        QVERIFY(table);
        QCOMPARE(table->item(1, 1)->text(), QStringLiteral("Write 1017h:00 = 750 on node 3"));
        QCOMPARE(table->item(1, 2)->text(), QStringLiteral("sdo write 3 0x1017:00 0x02ee"));
        QCOMPARE(table->item(1, 3)->text(), QStringLiteral("Heartbeat every 750 ms"));

        preview.markRunning(0);
        QCOMPARE(preview.stepState(0), QStringLiteral("running"));
        preview.markStep(0, true);
        preview.markStep(1, true, QStringLiteral("written"));
        preview.markStep(2, false, QStringLiteral("node 3 6041:00 reads 0x0250, expected 0x0027"));
        QCOMPARE(preview.stepState(1), QStringLiteral("done"));
        QVERIFY(preview.stepState(2).startsWith(QStringLiteral("failed: node 3 6041:00 reads")));
        QCOMPARE(table->item(2, 4)->text(), QStringLiteral("node 3 6041:00 reads 0x0250, expected 0x0027"));
        QVERIFY(table->item(2, 0)->background().color() != table->item(1, 0)->background().color());
        QCOMPARE(preview.stepState(3), QString());
        preview.grab().save(QStringLiteral(COSCOPE_TEST_BINARY_DIR) + QStringLiteral("/wizard_script_preview.png"));
        preview.clearMarks();
        QCOMPARE(preview.stepState(2), QString());

        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("kit.txt"));
        QString error;
        QVERIFY2(preview.saveTo(path, &error), qPrintable(error));
        const auto back = CommandScript::load(path, &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->title, s.title);
        QCOMPARE(back->steps.size(), s.steps.size());
        for (size_t i = 0; i < s.steps.size(); ++i)
            QVERIFY2(back->steps[i].sameAs(s.steps[i]), qPrintable(back->steps[i].toLine()));
        QVERIFY(!preview.saveTo(dir.filePath(QStringLiteral("no/such/dir/x.txt")), &error));
        QVERIFY(!error.isEmpty());

        preview.setScript({});
        QCOMPARE(preview.rowCount(), 0);
        auto* save = preview.findChild<QPushButton*>(QStringLiteral("saveScript"));
        QVERIFY(save && !save->isEnabled());
    }

    void guardExplainsListenOnly() {
        Workspace none;
        WizardGuard noBus(&none);
        QPushButton send(QStringLiteral("Apply"));
        noBus.addSender(&send);
        QVERIFY(!noBus.canSend());
        QVERIFY(!send.isEnabled());
        QVERIFY(noBus.reason().contains(QStringLiteral("No bus")));

        Workspace w;
        WizardGuard guard(&w);
        QPushButton apply(QStringLiteral("Apply"));
        guard.addSender(&apply);
        QSignalSpy changed(&guard, &WizardGuard::canSendChanged);
        QVERIFY(connectSim(w, QStringLiteral("sim://?nodes=3:generic-cia402&listen-only=1")));
        guard.refresh();
        QVERIFY(!guard.canSend());
        QVERIFY2(guard.reason().contains(QStringLiteral("listen-only")), qPrintable(guard.reason()));
        QVERIFY(!apply.isEnabled());

        Workspace live;
        WizardGuard ok(&live);
        QPushButton go(QStringLiteral("Apply"));
        ok.addSender(&go);
        QVERIFY(!go.isEnabled());
        QVERIFY(connectSim(live, QStringLiteral("sim://?nodes=3:generic-cia402")));
        QTRY_VERIFY_WITH_TIMEOUT(go.isEnabled(), 3000);  // follows the bus state by itself
        QVERIFY(ok.canSend());
        QVERIFY(ok.reason().isEmpty());
    }

    void runPanelRunsAndMarks() {
        Workspace w;
        ScriptRunPanel panel(&w);
        CommandScript s;
        s.steps.push_back(ScriptStep::sdoWrite(3, 0x1017, 0, 750, 2, QStringLiteral("Heartbeat every 750 ms")));
        s.steps.push_back(ScriptStep::sdoExpect(3, 0x1017, 0, 750, 2, 0, QStringLiteral("Reads back")));
        s.steps.push_back(ScriptStep::sdoExpect(3, 0x1017, 0, 1, 2, 0, QStringLiteral("Fails on purpose")));
        s.steps.push_back(ScriptStep::sdoWrite(3, 0x1017, 0, 900, 2, QStringLiteral("Never sent")));
        panel.setScript(s);
        QString why;
        QVERIFY(!panel.run(&why));  // no bus
        QVERIFY(why.contains(QStringLiteral("No bus")));
        auto* runButton = panel.findChild<QPushButton*>(QStringLiteral("runScript"));
        QVERIFY(runButton && !runButton->isEnabled());
        QVERIFY(connectSim(w, QStringLiteral("sim://?nodes=3:generic-cia402")));
        QTRY_VERIFY_WITH_TIMEOUT(runButton->isEnabled(), 3000);
        std::vector<canopen::ScriptRunResult> done;
        connect(&panel, &ScriptRunPanel::finished, &panel,
                [&](const canopen::ScriptRunResult& r) { done.push_back(r); });
        QVERIFY2(panel.run(&why), qPrintable(why));
        QTRY_COMPARE_WITH_TIMEOUT(done.size(), size_t(1), 10000);
        const auto r = done.front();
        QVERIFY(!r.ok);
        QCOMPARE(r.failedStep, 2);
        QCOMPARE(panel.preview()->stepState(0), QStringLiteral("done"));
        QCOMPARE(panel.preview()->stepState(1), QStringLiteral("done"));
        QVERIFY2(panel.preview()->stepState(2).contains(QStringLiteral("reads 0x02ee, expected 0x0001")),
                 qPrintable(panel.preview()->stepState(2)));
        QCOMPARE(panel.preview()->stepState(3), QString());
        QVERIFY2(panel.statusText().contains(QStringLiteral("step 3")), qPrintable(panel.statusText()));
        QVERIFY(runButton->isEnabled());
    }
};

QTEST_MAIN(TestWizardKit)
#include "test_wizard_kit.moc"
