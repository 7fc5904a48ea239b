// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 35 item 4: the CiA 402 wizard's Homing and Position move pages on the virtual drives,
// through clicks and keys only. The generic drive (node 3) homes with method 35 and a home offset
// typed in: the wizard shows "homing attained" and the drive's 6064h is the offset (CiA 402-2
// §13.2). The AIMOTOR (node 2) has no method 3 (extract-aimotor §4.7): the wizard refuses it
// with the drive's own list and sends nothing. Then node 3 makes a relative profile position move
// of 1000 while "Hold to move" is held, with the set-point handshake shown, and a second one
// released early halts short of its target.
#include "app/gui/od/IntegerSpinBox.h"
#include "app/gui/wizards/ds402/Ds402BitLamps.h"
#include "app/gui/wizards/ds402/Ds402HomingBox.h"
#include "app/gui/wizards/ds402/Ds402PositionMoveBox.h"
#include "app/gui/wizards/ds402/Ds402StatusPanel.h"
#include "app/gui/wizards/ds402/Ds402Wizard.h"
#include "eds/SimulatorDictionaries.h"

#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QTabBar>
#include <QTabWidget>
#include <QtTest>

#include "tests/gui/ModalAnswer.h"
#include "tests/gui/SimDriveRig.h"
#include "tests/gui/TypeText.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using canopen::ds402::State;
using coscope::testing::answerBoxSaying;
using coscope::testing::typeAndEnter;
using coscope::testing::waitFor;

namespace {
constexpr int kGeneric = 3, kAimotor = 2;
constexpr int32_t kOffset = 250;

// Clicks the tab titled `title` of `tabs`.
void clickTab(QTabWidget* tabs, const QString& title) {
    QTabBar* bar = tabs->tabBar();
    for (int i = 0; i < bar->count(); ++i)
        if (bar->tabText(i) == title) return QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(i).center());
    QFAIL(qPrintable(QStringLiteral("no tab %1").arg(title)));
}

QLineEdit* editOf(QWidget* field) { return field->findChild<QLineEdit*>(); }
}  // namespace

class TestWizardDs402Homing : public QObject {
    Q_OBJECT
    std::unique_ptr<testing::SimDriveRig> rig_;
    std::unique_ptr<Ds402Wizard> w_;

    double position(int node) {
        return rig_->onDrive(node, [](sim::Ds402Drive* d) { return d->position(); });
    }
    int64_t homingMethod(int node) {
        int64_t out = -1;
        rig_->net()->runOnNetworkThread([&] {
            out = rig_->net()->device(uint8_t(node))->value(0x6098, 0).value_or(od::Value{}).toInt64().value_or(-1);
        });
        return out;
    }

    void chooseNode(int node) {
        auto* combo = w_->findChild<QComboBox*>(QStringLiteral("nodeCombo"));
        QVERIFY(combo);
        combo->setFocus();
        QTest::keyClick(combo, Qt::Key_Home);
        for (int i = 0; i < combo->count() && combo->currentData().toInt() != node; ++i)
            QTest::keyClick(combo, Qt::Key_Down);
        QCOMPARE(combo->currentData().toInt(), node);
        QVERIFY(waitFor([&] { return w_->node() == node && w_->shownState() != State::Unknown; }, 8000));
    }

private slots:
    void initTestCase() {
        eds::installSimulatorDictionaries();
        rig_ = std::make_unique<testing::SimDriveRig>();
        QVERIFY(rig_->open(QStringLiteral("sim://")));
        w_ = std::make_unique<Ds402Wizard>(&rig_->ws, kGeneric);
        w_->show();
        QVERIFY(QTest::qWaitForWindowExposed(w_.get()));
        QVERIFY(waitFor([&] { return w_->shownState() == State::SwitchOnDisabled; }, 8000));
    }
    void cleanupTestCase() {
        w_.reset();
        rig_.reset();
    }

    // Method 35 and home offset 250 typed in; Start asks to switch to Homing and to start.
    void homesTheGenericDrive() {
        clickTab(w_->pages(), QStringLiteral("Homing"));
        Ds402HomingBox* page = w_->homingBox();
        QVERIFY(page->isVisible());
        typeAndEnter(page->methodCombo()->lineEdit(), QStringLiteral("35"));
        QVERIFY2(page->findChild<QLabel*>(QStringLiteral("homingMethodText"))
                     ->text()
                     .contains(QStringLiteral("Current position is home")),
                 qPrintable(page->findChild<QLabel*>(QStringLiteral("homingMethodText"))->text()));
        typeAndEnter(editOf(page->offsetField()), QStringLiteral("250"));
        QString modeAsked, startAsked;
        auto yesMode = answerBoxSaying(QStringLiteral("homing needs"), QMessageBox::Yes, &modeAsked);
        auto yesStart = answerBoxSaying(QStringLiteral("Start homing?"), QMessageBox::Yes, &startAsked);
        QSignalSpy finished(w_.get(), &Ds402Wizard::homingFinished);
        QTest::mouseClick(page->startButton(), Qt::LeftButton);
        QVERIFY2(waitFor([&] { return !finished.isEmpty(); }, 10000), qPrintable(w_->message()));
        QVERIFY2(finished.first().first().toBool(), qPrintable(page->resultText()));
        QVERIFY2(
            startAsked.contains(QStringLiteral("method 35")) && startAsked.contains(QStringLiteral("enabled first")),
            qPrintable(startAsked));
        QVERIFY2(modeAsked.contains(QStringLiteral("Homing")), qPrintable(modeAsked));
        // The page and the statusword panel name bits 10/12 for homing mode.
        QVERIFY2(page->resultText().contains(QStringLiteral("Homing attained")) &&
                     page->resultText().contains(QStringLiteral("= 250")),
                 qPrintable(page->resultText()));
        QCOMPARE(page->lamps()->name(1), QStringLiteral("12  homing attained"));
        QVERIFY(page->lamps()->isOn(0) && page->lamps()->isOn(1) && !page->lamps()->isOn(2));
        QVERIFY(
            waitFor([&] { return w_->statusPanel()->bitText(12) == QStringLiteral("12 homing attained: on"); }, 3000));
        QVERIFY(std::abs(position(kGeneric) - kOffset) < 1.0);
        QCOMPARE(rig_->driveState(kGeneric), State::OperationEnabled);
    }

    // Relative 1000 at 1000 inc/s, held to the end: target reached, the handshake shown. Held
    // again and released early: halted short of the next target, the drive still enabled.
    void movesWhileHeld() {
        clickTab(w_->pages(), QStringLiteral("Position move"));
        Ds402PositionMoveBox* page = w_->positionBox();
        QVERIFY(page->isVisible());
        QVERIFY(page->relativeBox()->isChecked());
        typeAndEnter(editOf(page->targetField()), QStringLiteral("1000"));
        typeAndEnter(editOf(page->velocityField()), QStringLiteral("0x3E8"));  // 1000, as a user may type it
        QVERIFY(waitFor([&] { return w_->shownState() == State::OperationEnabled && !w_->isBusy(); }, 5000));
        QString modeAsked, armAsked;
        {
            auto yesMode = answerBoxSaying(QStringLiteral("position move needs"), QMessageBox::Yes, &modeAsked);
            auto yesArm = answerBoxSaying(QStringLiteral("Arm the position move?"), QMessageBox::Yes, &armAsked);
            QTest::mouseClick(page->armButton(), Qt::LeftButton);
            QVERIFY2(waitFor([&] { return page->holdButton()->isEnabled(); }, 5000), qPrintable(w_->message()));
        }
        QVERIFY2(armAsked.contains(QStringLiteral("1000")) && armAsked.contains(QStringLiteral("relative")),
                 qPrintable(armAsked));
        QVERIFY(modeAsked.contains(QStringLiteral("Profile position")));

        const double start = position(kGeneric);
        QSignalSpy finished(w_.get(), &Ds402Wizard::positionMoveFinished);
        QTest::mousePress(page->holdButton(), Qt::LeftButton);
        QVERIFY2(waitFor([&] { return !finished.isEmpty(); }, 8000), qPrintable(w_->message()));
        QTest::mouseRelease(page->holdButton(), Qt::LeftButton);
        QVERIFY2(finished.first().first().toBool(), qPrintable(page->resultText()));
        QVERIFY2(std::abs(position(kGeneric) - (start + 1000)) <= 2, qPrintable(QString::number(position(kGeneric))));
        QVERIFY2(page->resultText().contains(QStringLiteral("Target reached")), qPrintable(page->resultText()));
        QVERIFY2(page->handshakeText().count(QStringLiteral("✔")) == 3, qPrintable(page->handshakeText()));

        finished.clear();
        const double second = position(kGeneric);
        QVERIFY(waitFor([&] { return page->holdButton()->isEnabled(); }, 3000));  // still armed
        QTest::mousePress(page->holdButton(), Qt::LeftButton);
        QVERIFY(waitFor([&] { return position(kGeneric) > second + 100; }, 5000));
        QTest::mouseRelease(page->holdButton(), Qt::LeftButton);
        QVERIFY2(waitFor([&] { return !finished.isEmpty(); }, 5000), qPrintable(w_->message()));
        const double halted = position(kGeneric);
        QVERIFY2(halted < second + 900, qPrintable(QString::number(halted)));
        QVERIFY2(page->resultText().contains(QStringLiteral("Halted before the target")),
                 qPrintable(page->resultText()));
        QTest::qWait(200);
        QCOMPARE(position(kGeneric), halted);  // stands still
        QCOMPARE(rig_->driveState(kGeneric), State::OperationEnabled);
    }

    // The AIMOTOR lacks method 3: refused with its own list before anything is asked or sent.
    void refusesAMethodTheDriveLacks() {
        chooseNode(kAimotor);
        clickTab(w_->pages(), QStringLiteral("Homing"));
        Ds402HomingBox* page = w_->homingBox();
        QVERIFY(page->methodCombo()->findData(37) >= 0);  // its own list: the hard-stop methods
        QCOMPARE(page->methodCombo()->findData(3), -1);
        typeAndEnter(page->methodCombo()->lineEdit(), QStringLiteral("3"));
        QVERIFY2(page->findChild<QLabel*>(QStringLiteral("homingMethodText"))
                     ->text()
                     .contains(QStringLiteral("Not a homing method of the AIMOTOR")),
                 qPrintable(page->findChild<QLabel*>(QStringLiteral("homingMethodText"))->text()));
        QString asked;
        auto cancel = testing::answerBox(QMessageBox::Cancel, &asked);
        QTest::mouseClick(page->startButton(), Qt::LeftButton);
        QTest::qWait(300);
        QVERIFY2(asked.isEmpty(), qPrintable(asked));
        QVERIFY2(w_->message().contains(QStringLiteral("has no homing method 3")) &&
                     w_->message().contains(QStringLiteral("1, 2, 4, 6, 17, 18, 24, 28, 33, 34, 35, 37, 38")),
                 qPrintable(w_->message()));
        QCOMPARE(homingMethod(kAimotor), int64_t(35));
        QVERIFY(rig_->driveState(kAimotor) != State::Fault);
        QVERIFY(!w_->motionRunning());
    }
};

QTEST_MAIN(TestWizardDs402Homing)
#include "test_wizard_ds402_homing.moc"
