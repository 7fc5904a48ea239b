// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 35 "Safety edges": the CiA 402 wizard's test move, through clicks and keys only. Its
// arming ends with Quick stop, Disable, a fault, a mode change and the steps that re-enable the
// drive: after any of them "Hold to run" moves nothing until the move is armed (and confirmed)
// again. And it never changes the mode of operation silently: from Homing it asks first
// ("the test move needs Profile velocity: switch?"); Cancel leaves the drive in Homing.
#include "app/gui/wizards/ds402/Ds402Wizard.h"
#include "eds/SimulatorDictionaries.h"

#include <QComboBox>
#include <QMessageBox>
#include <QPushButton>
#include <QtTest>

#include "tests/gui/ModalAnswer.h"
#include "tests/gui/SimDriveRig.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using canopen::ds402::Command;
using canopen::ds402::State;
using coscope::testing::answerBoxSaying;
using coscope::testing::waitFor;

namespace {
constexpr int kNode = 3;
const QString kUrl = QStringLiteral("sim://?nodes=3:generic-cia402");

QPushButton* buttonNamed(QWidget* w, const QString& text) {
    for (QPushButton* b : w->findChildren<QPushButton*>())
        if (b->text() == text) return b;
    return nullptr;
}
}  // namespace

class TestWizardDs402Arming : public QObject {
    Q_OBJECT
    std::unique_ptr<testing::SimDriveRig> rig_;
    std::unique_ptr<Ds402Wizard> w_;

    double velocity() {
        return rig_->onDrive(kNode, [](sim::Ds402Drive* d) { return d->velocity(); });
    }
    int8_t driveMode() {
        return rig_->onDrive(kNode, [](sim::Ds402Drive* d) { return d->modeDisplay(); });
    }

    void openWizard() {
        rig_ = std::make_unique<testing::SimDriveRig>();
        QVERIFY(rig_->open(kUrl));
        w_ = std::make_unique<Ds402Wizard>(&rig_->ws, kNode);
        w_->show();
        QVERIFY(QTest::qWaitForWindowExposed(w_.get()));
        QVERIFY(waitFor([&] { return w_->shownState() == State::SwitchOnDisabled; }, 8000));
    }
    // From whatever state: the next step's button, clicked until Operation enabled (Yes to
    // "Enable operation energises…").
    void enableByClicks() {
        QString asked;
        auto yes = answerBoxSaying(QStringLiteral("energises"), QMessageBox::Yes, &asked);
        for (int i = 0; i < 6 && rig_->driveState(kNode) != State::OperationEnabled; ++i) {
            QPushButton* next = nullptr;
            QVERIFY(waitFor(
                [&] {
                    for (Command c : {Command::FaultReset, Command::Shutdown, Command::SwitchOn,
                                      Command::EnableOperation, Command::DisableVoltage})
                        if (QPushButton* b = w_->stepButton(c); b && b->isEnabled() && !w_->isBusy()) next = b;
                    return next != nullptr;
                },
                6000));
            QTest::mouseClick(next, Qt::LeftButton);
            QVERIFY(waitFor([&] { return !w_->isBusy(); }, 6000));
        }
        QVERIFY(waitFor(
            [&] {
                return rig_->driveState(kNode) == State::OperationEnabled &&
                       w_->shownState() == State::OperationEnabled;
            },
            6000));
    }
    // Arm… with Yes to the questions; `modeAsked` gets the mode question (empty: none came).
    void armByClicks(QString* modeAsked = nullptr) {
        QString mode, arm;
        auto yesMode = answerBoxSaying(QStringLiteral("the test move needs"), QMessageBox::Yes, &mode);
        auto yesArm = answerBoxSaying(QStringLiteral("Arm the test move?"), QMessageBox::Yes, &arm);
        QTest::mouseClick(buttonNamed(w_.get(), QStringLiteral("Arm test move…")), Qt::LeftButton);
        QVERIFY(waitFor([&] { return !arm.isEmpty(); }, 5000));
        QVERIFY(waitFor([&] { return w_->holdToRunButton()->isEnabled(); }, 5000));
        if (modeAsked) *modeAsked = mode;
    }
    // Holding "Hold to run" for a while: whether the motor turned.
    bool holdMoves() {
        QTest::mousePress(w_->holdToRunButton(), Qt::LeftButton);
        const bool moved = waitFor([&] { return std::abs(velocity()) > 500; }, 1500);
        QTest::mouseRelease(w_->holdToRunButton(), Qt::LeftButton);
        waitFor([&] { return !w_->testMoveRunning() && std::abs(velocity()) < 1; }, 5000);
        return moved;
    }
    // Picks `mode` in the Mode box by keys and clicks Set and verify.
    void setModeByClicks(const QString& mode, int8_t value) {
        QComboBox* box = w_->modeCombo();
        box->setFocus();
        QTest::keyClick(box, Qt::Key_Home);
        for (int i = 0; i < box->count() && !box->currentText().startsWith(mode); ++i)
            QTest::keyClick(box, Qt::Key_Down);
        QVERIFY(box->currentText().startsWith(mode));
        QTest::mouseClick(buttonNamed(w_.get(), QStringLiteral("Set and verify")), Qt::LeftButton);
        QVERIFY(waitFor([&] { return driveMode() == value && !w_->isBusy(); }, 5000));
    }

private slots:
    void initTestCase() { eds::installSimulatorDictionaries(); }
    void cleanup() {
        w_.reset();
        rig_.reset();
    }

    // Armed and moved once; Quick stop; enabled again by the steps: Hold to run is off and a
    // press moves nothing; armed again (a new Yes), it moves.
    void quickStopAndReEnableEndTheArming() {
        openWizard();
        enableByClicks();
        armByClicks();
        QVERIFY(holdMoves());
        QVERIFY(w_->holdToRunButton()->isEnabled());  // released: still armed for the next hold
        QTest::mouseClick(w_->quickStopButton(), Qt::LeftButton);
        QVERIFY(waitFor(
            [&] {
                return rig_->driveState(kNode) != State::OperationEnabled &&
                       w_->shownState() != State::OperationEnabled;
            },
            5000));
        QVERIFY(!w_->testMoveArmed());
        enableByClicks();
        QTest::qWait(300);
        QVERIFY2(!w_->holdToRunButton()->isEnabled(), "Hold to run is live again after Quick stop and re-enable");
        QVERIFY(!holdMoves());
        QCOMPARE(velocity(), 0.0);
        armByClicks();
        QVERIFY(holdMoves());
    }

    // Disable, a fault (raised by the drive itself) and a mode set in the Mode box each end it.
    void disableFaultAndModeChangeEndTheArming() {
        openWizard();
        enableByClicks();
        armByClicks();
        QTest::mouseClick(w_->disableButton(), Qt::LeftButton);
        QVERIFY(waitFor([&] { return rig_->driveState(kNode) == State::SwitchOnDisabled; }, 5000));
        enableByClicks();
        QVERIFY(!w_->holdToRunButton()->isEnabled());

        armByClicks();
        rig_->onDrive(kNode, [](sim::Ds402Drive* d) {
            d->raiseFault(0x2310);
            return 0;
        });
        QVERIFY2(waitFor([&] { return !w_->holdToRunButton()->isEnabled(); }, 5000),
                 "still armed after the drive faulted");
        enableByClicks();  // fault reset and the steps
        QTest::qWait(300);
        QVERIFY(!w_->holdToRunButton()->isEnabled());
        QVERIFY(!holdMoves());

        armByClicks();
        setModeByClicks(QStringLiteral("Profile position"), 1);
        QVERIFY2(!w_->holdToRunButton()->isEnabled(), "still armed after the mode of operation changed");
        QVERIFY(!holdMoves());
    }

    // In Homing, Arm asks before the move switches to Profile velocity; Cancel: not armed, the
    // drive stays in Homing. Yes: armed, and holding switches the mode and moves.
    void testMoveAsksBeforeSwitchingTheMode() {
        openWizard();
        enableByClicks();
        setModeByClicks(QStringLiteral("Homing"), 6);
        QString asked, armAsked;
        {
            auto cancel = answerBoxSaying(QStringLiteral("the test move needs"), QMessageBox::Cancel, &asked);
            auto arm = answerBoxSaying(QStringLiteral("Arm the test move?"), QMessageBox::Yes, &armAsked);
            QTest::mouseClick(buttonNamed(w_.get(), QStringLiteral("Arm test move…")), Qt::LeftButton);
            QVERIFY2(waitFor([&] { return !asked.isEmpty(); }, 3000), "no question before switching from Homing");
            QTest::qWait(300);
        }
        QVERIFY2(asked.contains(QStringLiteral("The drive is in Homing")) &&
                     asked.contains(QStringLiteral("Profile velocity")),
                 qPrintable(asked));
        QVERIFY(armAsked.isEmpty());
        QVERIFY(!w_->testMoveArmed());
        QVERIFY(!w_->holdToRunButton()->isEnabled());
        QCOMPARE(driveMode(), int8_t(6));

        QString modeAsked;
        armByClicks(&modeAsked);
        QVERIFY(modeAsked.contains(QStringLiteral("Homing")));
        QCOMPARE(driveMode(), int8_t(6));  // nothing switched before the hold
        QVERIFY(holdMoves());
        QCOMPARE(driveMode(), int8_t(3));
    }
};

QTEST_MAIN(TestWizardDs402Arming)
#include "test_wizard_ds402_arming.moc"
