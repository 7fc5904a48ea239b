// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/wizards/ds402/ owns the CiA 402 enable step-through: the wizard and its parts
// (state picture, statusword panel, step bar, mode box, test move with its plot, homing and profile
// position pages, frames and dry-run tabs), drive units, fault texts and vendor notes.
#pragma once

#include "core/canopen/CommandScript.h"
#include "core/canopen/Ds402.h"
#include "core/canopen/Ds402Controller.h"

#include <QDialog>
#include <QList>

#include <memory>
#include <optional>
#include <utility>

class QComboBox;
class QLabel;
class QPushButton;
class QTabWidget;
class QTimer;

namespace coscope::gui {

class Workspace;
class WizardFramesPane;
class ScriptPreview;
class Ds402StateDiagram;
class Ds402StatusPanel;
class Ds402MotionPlot;
class Ds402StepBar;
class Ds402ModeBox;
class Ds402TestMoveBox;
class Ds402HomingBox;
class Ds402PositionMoveBox;
class Ds402FramesTabs;

// The CiA 402 enable step-through (Commission ▸ CiA 402 enable step-through…): shows the
// drive's state from 6041h as the state machine picture with the statusword bits, one button per
// next step (fault reset → shutdown → switch on → enable operation) that writes 6040h and waits
// for the statusword it must lead to, explaining a missing bit in plain words; chooses and
// verifies the mode of operation (6060h/6061h) among those 6502h lists; an optional test move
// on a hold-to-run button with a live plot; homing with the drive's own methods and a profile
// position move on a hold-to-run button (Ds402WizardMotion.cpp). Quick stop and Disable are
// always there.
// Made of: the state picture (Ds402StateDiagram), the statusword panel (Ds402StatusPanel), the
// step bar (Ds402StepBar), the mode box (Ds402ModeBox), the pages Test move (Ds402TestMoveBox),
// Homing (Ds402HomingBox) and Position move (Ds402PositionMoveBox), and the frames and dry-run
// tabs (Ds402FramesTabs); this class runs the drive through them.
//
// Safety (DESIGN.md): asks before Enable operation, before homing and before arming a test or
// position move (and before either switches the mode of operation); any stop, fault, step or mode
// change ends the arming; a failed step
// sends Disable voltage; closing the wizard (Close, Esc, the window's ✕), losing the bus or
// quitting the app disables a drive the wizard left switched on. What it shows is what it last
// read from the drive: nothing once the connection is gone. The test move speaks the drive's
// units (Ds402Units) and the Mode box shows the drive's own mode (6061h). Sends nothing in listen-only mode. Never blocks the GUI thread:
// everything goes through Ds402Controller (core), whose CLI face is `coscope-cli ds402`.
class Ds402Wizard : public QDialog {
    Q_OBJECT
public:
    // `node` -1: the first node whose device type (1000h) says CiA 402, once nodes are known.
    Ds402Wizard(Workspace* workspace, int node, QWidget* parent = nullptr);
    ~Ds402Wizard() override;

    // Tests: answer every confirmation with yes (or no).
    void setAutoConfirm(bool yes) { autoConfirm_ = yes; }

    int node() const { return node_; }
    void selectNode(int node);
    // Why the wizard may not send now ("" = it may): no bus, listen-only, no drive chosen.
    QString sendRefusal() const;
    // Reads 6041h (and 6061h, 6502h once, 603Fh + 1003h:01 in fault). stateRead() when done.
    // Does nothing while a step runs: the step's own 6041h result is the state shown.
    void refresh();
    bool isBusy() const { return busy_; }

    // What the buttons do. False + *why when refused before anything is sent.
    bool runStep(canopen::ds402::Command command, QString* why = nullptr);
    bool chooseMode(int8_t mode, QString* why = nullptr);
    bool armTestMove(QString* why = nullptr);
    bool pressHoldToRun(QString* why = nullptr);  // the hold-to-run button goes down
    void releaseHoldToRun();                      // ... and comes up
    void setTestMove(const canopen::Ds402TestMove& move);
    canopen::Ds402TestMove testMove() const;
    void quickStop();
    void disableDrive();
    // Homing and the profile position move (Ds402WizardMotion.cpp). False + *why when refused
    // before anything is sent (or asked).
    bool startHoming(QString* why = nullptr);
    void stopHoming();
    bool armPositionMove(QString* why = nullptr);
    bool pressHoldToMove(QString* why = nullptr);
    void releaseHoldToMove();
    bool motionRunning() const;
    // Shows a page of the lower tabs by name: "test", "homing", "position".
    Q_INVOKABLE void showPage(const QString& name);
    // The dry run: the exact enable sequence from the current state (with the chosen mode),
    // shown in the preview; nothing is sent.
    canopen::CommandScript dryRun();

    // What the wizard shows.
    canopen::ds402::State shownState() const { return state_; }
    uint16_t statusword() const { return statusword_; }
    std::optional<uint32_t> supportedModes() const { return supported_; }
    int8_t modeDisplay() const;
    QString message() const;
    QString faultText() const { return faultText_; }
    bool isCia402() const { return cia402_; }
    bool testMoveArmed() const { return armed_; }
    bool testMoveRunning() const;
    QList<canopen::ds402::State> visitedStates() const { return visited_; }

    Ds402StateDiagram* diagram() const { return diagram_; }
    Ds402StatusPanel* statusPanel() const { return status_; }
    Ds402MotionPlot* motionPlot() const;
    WizardFramesPane* framesPane() const;
    ScriptPreview* preview() const;
    QPushButton* stepButton(canopen::ds402::Command command) const;
    QPushButton* holdToRunButton() const;
    QPushButton* quickStopButton() const { return quickStop_; }
    QPushButton* disableButton() const { return disable_; }
    QComboBox* modeCombo() const;
    QTabWidget* pages() const { return pages_; }
    Ds402HomingBox* homingBox() const { return homing_; }
    Ds402PositionMoveBox* positionBox() const { return position_; }

signals:
    void stateRead(bool ok);
    void stepFinished(bool ok);
    void modeFinished(bool ok);
    void testMoveFinished(bool ok);
    void homingFinished(bool ok);
    void positionMoveFinished(bool ok);

protected:
    void closeEvent(QCloseEvent* event) override;
    void showEvent(QShowEvent* event) override;
    void reject() override;

private:
    static constexpr int kSettleMs = 100;    // re-read while the drive initialises or reacts to a fault
    static constexpr int kSettleTries = 30;  // ... for at most 3 s

    void buildUi();
    void findFirstDrive(int attempt);
    void makeController();
    void startReading();  // after the drive (and its dictionary) is known
    void settleFaultReaction(const canopen::Ds402Result& r, int tries,
                             std::function<void(const canopen::Ds402Result&)> done);
    void dropController(const QString& why);
    void finishClosing();             // Close, Esc, ✕: disable, stop sending (once)
    void showDriveMode(int8_t mode);  // 6061h as read
    void readObject(uint16_t index, uint8_t sub, std::function<void(const canopen::SdoResult&)> done);
    void afterState(const canopen::Ds402Result& r, std::function<void()> then);
    void showState(canopen::ds402::State s, uint16_t sw);
    // After Quick stop or Disable: the state reached (`doneText` with %1 for its name) or why not.
    void showStopped(const canopen::Ds402Result& r, const QString& doneText, const QString& what);
    void setMessage(const QString& text, bool bad = false);
    void updateButtons();
    void fillModes();
    bool confirm(const QString& title, const QString& text);
    // Arming a test move ends with any stop, fault, mode change or step (DESIGN.md "Reliability
    // and safety"): a new hold-to-run needs a new confirmation. Says why when it was armed.
    void disarm(const QString& why);
    // Confirmed, with the drive in `driveMode` (6061h): the move switches to its own mode, as agreed.
    void arm(const canopen::Ds402TestMove& move, int8_t driveMode);
    // Asks before a motion that needs mode `needed` switches from the drive's mode (`question`
    // has %1 the drive's mode, %2 the needed one, %3 its number); *why says why not when refused
    // (6502h lacks it) or not confirmed (`notDone` with %1 the drive's mode).
    bool agreeMode(int8_t needed, const QString& question, const QString& notDone, QString* why);
    // The homing and position pages: the drive's methods, units and values (when first shown for
    // the node), the motion's progress and end.
    void setUpMotionPages();
    void readMotionSettings();
    void onMotionSample(const canopen::Ds402MotionSample& s);
    void homingDone(const canopen::Ds402Result& r);
    void positionDone(const canopen::Ds402Result& r);
    void armPosition(int32_t position);  // after the reads of arming
    // A failed motion: the state and the drive's fault text, then `show` with the whole text.
    void afterMotionFailure(const QString& text, std::function<void(const QString&)> show);
    QString limitsText() const;
    // Disables a drive the wizard may have left switched on, without waiting (close, quit,
    // bus lost). Returns whether something was sent.
    bool safeDisable(const QString& why);
    // The bus was lost (issue 16): stop, and say the drive's last known state and what to check.
    void stopOnBusLoss();
    QString checkAdvice() const;  // what to check for this vendor

    Workspace* workspace_;
    int node_ = -1;
    QString dictionary_;
    bool autoConfirm_ = false;
    bool busy_ = false;
    bool reading_ = false;
    bool cia402_ = true;
    bool armed_ = false;
    enum class Armed : uint8_t { TestMove, PositionMove };
    Armed armedKind_ = Armed::TestMove;  // what is armed
    enum class Motion : uint8_t { None, Homing, Position };
    Motion motion_ = Motion::None;                           // the home()/moveTo() running
    int motionSettingsFor_ = -1;                             // selection_ whose homing/position values were read
    std::optional<int32_t> position_6064_;                   // position actual, as last read
    std::optional<std::pair<int32_t, int32_t>> softLimits_;  // 607Dh:01/02 when the drive has them
    int32_t moveTarget_ = 0;                                 // where the running position move goes
    canopen::Ds402PositionMove armedMove_;                   // the position move the user agreed to
    int8_t armedMode_ = 0;      // the mode of operation (6061h) the armed test move runs in
    int8_t armedFromMode_ = 0;  // ... and the one the drive showed when it was armed (until it switched)
    bool holding_ = false;
    bool sentCommands_ = false;  // the wizard wrote 6040h since the node was chosen
    bool closing_ = false;
    bool stoppedByLoss_ = false;  // the bus was lost while a drive was shown: no automatic re-read on return
    int selection_ = 0;           // counts selectNode() calls: answers for an earlier choice are dropped
    int settleTries_ = 0;         // re-reads while the drive is Not ready to switch on
    canopen::ds402::State state_ = canopen::ds402::State::Unknown;
    uint16_t statusword_ = 0;
    std::optional<uint32_t> supported_;
    QString faultText_;
    QString controlWarning_;
    QList<canopen::ds402::State> visited_;
    std::unique_ptr<canopen::Ds402Controller> ctl_;
    canopen::SdoClient* ctlSdo_ = nullptr;

    Ds402StateDiagram* diagram_ = nullptr;
    Ds402StatusPanel* status_ = nullptr;
    Ds402StepBar* steps_ = nullptr;
    Ds402ModeBox* mode_ = nullptr;
    Ds402TestMoveBox* move_ = nullptr;
    Ds402HomingBox* homing_ = nullptr;
    Ds402PositionMoveBox* position_ = nullptr;
    QTabWidget* pages_ = nullptr;
    Ds402FramesTabs* tabs_ = nullptr;
    QComboBox* nodeCombo_ = nullptr;
    QLabel* banner_ = nullptr;
    QLabel* vendor_ = nullptr;
    QLabel* message_ = nullptr;
    QPushButton* quickStop_ = nullptr;
    QPushButton* disable_ = nullptr;
    QPushButton* dryRun_ = nullptr;
    QTimer* poll_ = nullptr;
    QTimer* feed_ = nullptr;
};

}  // namespace coscope::gui
