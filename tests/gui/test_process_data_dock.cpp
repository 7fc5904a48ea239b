// SPDX-License-Identifier: GPL-3.0-or-later
// The Process data dock (issue 35) on the virtual AIMOTOR (node 2, default RPDO2 = 60FFh target
// velocity + 6071h at 302h, extract-aimotor §2): the user types a target velocity, chooses "With
// each SYNC", starts, arms and holds "Hold to run" — the drive's velocity actual turns while held
// and returns to 0 after release. Without a bus the dock says why it is disabled.
#include "ModalAnswer.h"
#include "SimDriveRig.h"
#include "TypeText.h"
#include "app/gui/master/ProcessDataDock.h"
#include "core/canopen/BusMaster.h"
#include "core/canopen/Ds402Controller.h"
#include "core/canopen/ServiceWait.h"
#include "eds/SimulatorDictionaries.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QtTest>

using namespace coscope;
using coscope::testing::answerBox;
using coscope::testing::typeAndEnter;

class TestProcessDataDock : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { eds::installSimulatorDictionaries(); }

    void disabledWithoutBus() {
        gui::Workspace ws;
        gui::ProcessDataDock dock(&ws);
        dock.show();
        auto* reason = dock.findChild<QLabel*>(QStringLiteral("processDataReason"));
        QVERIFY(reason);
        QVERIFY(QTest::qWaitFor([&] { return reason->text().contains(QStringLiteral("No bus")); }, 2000));
        QVERIFY(!dock.holdButton()->isEnabled());
        QVERIFY(!dock.findChild<QPushButton*>(QStringLiteral("processDataSend"))->isEnabled());
    }

    void holdToRunTurnsTheDrive() {
        testing::SimDriveRig rig;
        QVERIFY(rig.open(QStringLiteral("sim://?nodes=2:aimotor")));
        // Set-up as earlier steps would leave it: node 2 known with its dictionary, operational,
        // enabled in profile velocity (the CiA 402 wizard), SYNC running (the Bus menu).
        rig.ws.nodes().setDictionary(2, QStringLiteral("aimotor"));
        QString error;
        QVERIFY(rig.ws.master()->send(CanFrame::classic(0x000, {0x01, 0x02}), &error));
        canopen::Ds402Controller ctl(*rig.ws.sdo(), 2);
        auto mode =
            canopen::waitForResult<canopen::Ds402Result>([&](canopen::Ds402Callback cb) { ctl.setMode(3, cb); }, 5000);
        QVERIFY(mode && mode->ok);
        auto en =
            canopen::waitForResult<canopen::Ds402Result>([&](canopen::Ds402Callback cb) { ctl.enable(cb); }, 5000);
        QVERIFY(en && en->ok);
        canopen::BusMaster master(*rig.ws.master());
        master.sync().setPeriodUs(10000);
        QVERIFY(master.sync().start());

        gui::ProcessDataDock dock(&rig.ws);
        dock.setMaster(&master);
        dock.resize(700, 600);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        // The node appears; its values are read from the drive (controlword 000Fh, mode 3).
        QVERIFY(QTest::qWaitFor([&] { return dock.controlwordBit(3) && dock.controlwordBit(3)->isChecked(); }, 5000));
        QVERIFY(dock.controlwordBit(0)->isChecked());
        QLineEdit* velocity = dock.editor(0x60FF, 0);
        QVERIFY(velocity);
        typeAndEnter(velocity, QStringLiteral("20000"));
        QCOMPARE(dock.processData()->value(0x60FF, 0), std::optional<int64_t>(20000));

        auto* modeBox = dock.findChild<QComboBox*>(QStringLiteral("processDataMode"));
        modeBox->setFocus();
        QTest::keyClick(modeBox, Qt::Key_End);  // "With each SYNC"
        QCOMPARE(modeBox->currentIndex(), 3);
        QTest::mouseClick(dock.findChild<QPushButton*>(QStringLiteral("processDataStart")), Qt::LeftButton);
        QVERIFY(dock.processData()->isRunning());
        QTest::qWait(200);
        QVERIFY(std::abs(rig.onDrive(2, [](sim::Ds402Drive* d) { return d->velocity(); })) < 1);  // not held: no motion

        QString asked;
        {
            auto yes = answerBox(QMessageBox::Yes, &asked);
            QTest::mouseClick(dock.armButton(), Qt::LeftButton);
        }
        QVERIFY(asked.contains(QStringLiteral("Hold to run")));
        QVERIFY(dock.holdButton()->isEnabled());
        QTest::mousePress(dock.holdButton(), Qt::LeftButton);
        const bool moved = QTest::qWaitFor(
            [&] { return rig.onDrive(2, [](sim::Ds402Drive* d) { return d->velocity(); }) > 1000; }, 3000);
        QTest::qWait(600);  // held longer than the watchdog: still fed
        const double whileHeld = rig.onDrive(2, [](sim::Ds402Drive* d) { return d->velocity(); });
        QTest::mouseRelease(dock.holdButton(), Qt::LeftButton);
        QVERIFY(moved);
        QVERIFY2(whileHeld > 1000, qPrintable(QString::number(whileHeld)));
        QVERIFY(QTest::qWaitFor(
            [&] { return std::abs(rig.onDrive(2, [](sim::Ds402Drive* d) { return d->velocity(); })) < 1; }, 3000));
        dock.setMaster(nullptr);
        master.stopAll();
    }
};

QTEST_MAIN(TestProcessDataDock)
#include "test_process_data_dock.moc"
