// SPDX-License-Identifier: GPL-3.0-or-later
// The CiA 402 wizard's window: its parts, what may be sent, closing and the message line. Choosing
// and reading the drive: Ds402WizardReading.cpp; what the buttons do: Ds402WizardCommands.cpp.
#include "app/gui/wizards/ds402/Ds402Wizard.h"

#include "core/canopen/SdoClient.h"

#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/common/ScriptPreview.h"
#include "app/gui/wizards/ds402/Ds402FramesTabs.h"
#include "app/gui/wizards/ds402/Ds402HomingBox.h"
#include "app/gui/wizards/ds402/Ds402ModeBox.h"
#include "app/gui/wizards/ds402/Ds402PositionMoveBox.h"
#include "app/gui/wizards/ds402/Ds402StateDiagram.h"
#include "app/gui/wizards/ds402/Ds402StatusPanel.h"
#include "app/gui/wizards/ds402/Ds402StepBar.h"
#include "app/gui/wizards/ds402/Ds402TestMoveBox.h"

#include <QCloseEvent>
#include <QComboBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QTabWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <spdlog/spdlog.h>

namespace coscope::gui {

using canopen::ds402::Command;
using canopen::ds402::State;

namespace {
constexpr int kPollMs = 1000;  // idle refresh of the statusword
constexpr int kFeedMs = 100;   // hold-to-run watchdog feed while the button is down
}  // namespace

Ds402Wizard::Ds402Wizard(Workspace* workspace, int node, QWidget* parent) : QDialog(parent), workspace_(workspace) {
    setObjectName(QStringLiteral("ds402Wizard"));
    setWindowTitle(tr("CiA 402 enable step-through"));
    setProperty("screenshotReady", false);
    buildUi();
    poll_ = new QTimer(this);
    poll_->setInterval(kPollMs);
    connect(poll_, &QTimer::timeout, this, [this] {
        if (!busy_ && !reading_ && ctl_ && !ctl_->testMoveActive() && !ctl_->motionActive()) refresh();
    });
    feed_ = new QTimer(this);
    feed_->setInterval(kFeedMs);
    connect(feed_, &QTimer::timeout, this, [this] {
        if (ctl_ && holding_) ctl_->feedWatchdog();
    });
    connect(workspace_, &Workspace::busStateChanged, this, [this](CanBus::State s) {
        if (s == CanBus::State::Open) {
            // Back after a loss: the loss message stays until the user reads the drive again.
            if (!ctl_ && node_ > 0 && !stoppedByLoss_) selectNode(node_);
            stoppedByLoss_ = false;
            return;
        }
        if (s == CanBus::State::Lost) {  // issue 16: nothing can be sent; say what the drive may be left in
            stopOnBusLoss();
            return;
        }
        // The connection went away: tell the drive to disable if we still can, then forget it.
        safeDisable(tr("connection lost"));
        dropController(tr("Connection lost (bus %1). The drive was told to disable if the bus still accepted it; "
                          "otherwise its own "
                          "communication-loss reaction (6007h) applies. Check the drive.")
                           .arg(s == CanBus::State::Error ? tr("error") : tr("closed")));
    });
    connect(workspace_, &Workspace::sourceChanged, this, [this] {
        if (ctlSdo_ != workspace_->sdo()) dropController(tr("The connection changed. Choose the drive again."));
    });
    // Disconnecting, another connection, a log opened or the app quitting: the workspace sends
    // Disable voltage to every drive CoScope enabled and sees it go out before the bus closes
    // (canopen::disableEnabledDrives); the window asked first. Nothing more to send from here.
    if (const QString why = sendRefusal(); !why.isEmpty() && workspace_->bus() && workspace_->bus()->isListenOnly()) {
        banner_->setText(
            tr("Listen-only connection: this wizard is disabled because it would have to send (SDO to 6040h/6041h)."));
        banner_->show();
    }
    if (node > 0) selectNode(node);
    else QTimer::singleShot(0, this, [this] { findFirstDrive(0); });
    updateButtons();
}

Ds402Wizard::~Ds402Wizard() {
    if (!closing_) safeDisable(tr("wizard destroyed"));
}

void Ds402Wizard::buildUi() {
    auto* root = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Drive (node):"), this));
    nodeCombo_ = new QComboBox(this);
    nodeCombo_->setObjectName(QStringLiteral("nodeCombo"));
    nodeCombo_->setMinimumWidth(220);
    connect(nodeCombo_, &QComboBox::activated, this, [this](int i) { selectNode(nodeCombo_->itemData(i).toInt()); });
    top->addWidget(nodeCombo_);
    auto* refreshButton = new QPushButton(tr("Read state"), this);
    connect(refreshButton, &QPushButton::clicked, this, &Ds402Wizard::refresh);
    top->addWidget(refreshButton);
    vendor_ = new QLabel(this);
    vendor_->setWordWrap(true);
    vendor_->setObjectName(QStringLiteral("vendorNotes"));
    top->addWidget(vendor_, 1);
    root->addLayout(top);
    banner_ = new QLabel(this);
    banner_->setObjectName(QStringLiteral("banner"));
    banner_->setWordWrap(true);
    banner_->setStyleSheet(QStringLiteral("background: #fff3c4; padding: 4px; border: 1px solid #d8b000;"));
    banner_->hide();
    root->addWidget(banner_);

    auto* middle = new QHBoxLayout;
    auto* diagramBox = new QGroupBox(tr("Drive state (CiA 402 state machine)"), this);
    auto* dl = new QVBoxLayout(diagramBox);
    diagram_ = new Ds402StateDiagram(diagramBox);
    dl->addWidget(diagram_);
    middle->addWidget(diagramBox, 3);
    auto* statusBox = new QGroupBox(tr("Statusword bits"), this);
    auto* sl = new QVBoxLayout(statusBox);
    status_ = new Ds402StatusPanel(statusBox);
    sl->addWidget(status_);
    middle->addWidget(statusBox, 2);
    root->addLayout(middle, 3);

    steps_ = new Ds402StepBar(this);
    connect(steps_, &Ds402StepBar::stepClicked, this, [this](Command c) {
        QString why;
        if (!runStep(c, &why) && !why.isEmpty()) setMessage(why, true);
    });
    root->addWidget(steps_);

    auto* lower = new QHBoxLayout;
    mode_ = new Ds402ModeBox(this);
    connect(mode_, &Ds402ModeBox::setRequested, this, [this](int8_t mode) {
        QString why;
        if (!chooseMode(mode, &why)) setMessage(why, true);
    });
    lower->addWidget(mode_, 1, Qt::AlignTop);
    // The motions, one page each: the test move, homing, a profile position move.
    pages_ = new QTabWidget(this);
    pages_->setObjectName(QStringLiteral("motionPages"));
    move_ = new Ds402TestMoveBox(this);
    connect(move_, &Ds402TestMoveBox::armClicked, this, [this] {
        QString why;
        if (!armTestMove(&why) && !why.isEmpty()) setMessage(why, true);
    });
    connect(move_, &Ds402TestMoveBox::holdPressed, this, [this] {
        QString why;
        if (!pressHoldToRun(&why) && !why.isEmpty()) setMessage(why, true);
    });
    connect(move_, &Ds402TestMoveBox::holdReleased, this, &Ds402Wizard::releaseHoldToRun);
    pages_->addTab(move_, tr("Test move"));
    homing_ = new Ds402HomingBox(this);
    connect(homing_, &Ds402HomingBox::startClicked, this, [this] {
        QString why;
        if (!startHoming(&why) && !why.isEmpty()) setMessage(why, true);
    });
    connect(homing_, &Ds402HomingBox::stopClicked, this, &Ds402Wizard::stopHoming);
    pages_->addTab(homing_, tr("Homing"));
    position_ = new Ds402PositionMoveBox(this);
    connect(position_, &Ds402PositionMoveBox::armClicked, this, [this] {
        QString why;
        if (!armPositionMove(&why) && !why.isEmpty()) setMessage(why, true);
    });
    connect(position_, &Ds402PositionMoveBox::holdPressed, this, [this] {
        QString why;
        if (!pressHoldToMove(&why) && !why.isEmpty()) setMessage(why, true);
    });
    connect(position_, &Ds402PositionMoveBox::holdReleased, this, &Ds402Wizard::releaseHoldToMove);
    pages_->addTab(position_, tr("Position move"));
    // Homing and position values are read from the drive when their page is first shown.
    connect(pages_, &QTabWidget::currentChanged, this, [this] { readMotionSettings(); });
    lower->addWidget(pages_, 3);
    root->addLayout(lower, 2);

    message_ = new QLabel(this);
    message_->setObjectName(QStringLiteral("message"));
    message_->setWordWrap(true);
    message_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    message_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    // A reserved area of four lines (it scrolls when a message is longer): the layout above
    // and below does not jump as messages come and go.
    auto* messageArea = new QScrollArea(this);
    messageArea->setObjectName(QStringLiteral("messageArea"));
    messageArea->setFrameShape(QFrame::NoFrame);
    messageArea->setWidgetResizable(true);
    messageArea->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    messageArea->setWidget(message_);
    messageArea->setFixedHeight(message_->fontMetrics().lineSpacing() * 4 + 6);
    root->addWidget(messageArea);

    tabs_ = new Ds402FramesTabs(workspace_, this);
    // The preview's own "Save as script…" is the tab's only one; say where the file went.
    connect(tabs_->preview(), &ScriptPreview::saved, this, [this](const QString& path) {
        setMessage(tr("Saved %1; replay it with: coscope-cli script run BUS %1").arg(path));
    });
    root->addWidget(tabs_, 2);

    auto* bar = new QHBoxLayout;
    quickStop_ = new QPushButton(tr("Quick stop"), this);
    quickStop_->setObjectName(QStringLiteral("quickStop"));
    quickStop_->setStyleSheet(
        QStringLiteral("QPushButton { background: #c62828; color: white; font-weight: bold; padding: 6px 18px; }"
                       "QPushButton:disabled { background: #d9a0a0; }"));
    quickStop_->setToolTip(tr("Brakes on the drive's quick stop ramp (6040h = 0002h)."));
    connect(quickStop_, &QPushButton::clicked, this, &Ds402Wizard::quickStop);
    disable_ = new QPushButton(tr("Disable"), this);
    disable_->setObjectName(QStringLiteral("disable"));
    disable_->setStyleSheet(QStringLiteral("QPushButton { font-weight: bold; padding: 6px 18px; }"));
    disable_->setToolTip(tr("Removes power from the motor: Shutdown then Disable voltage (6040h = 0006h, 0000h)."));
    connect(disable_, &QPushButton::clicked, this, &Ds402Wizard::disableDrive);
    dryRun_ = new QPushButton(tr("Dry run"), this);
    dryRun_->setObjectName(QStringLiteral("dryRun"));
    dryRun_->setToolTip(tr("Show the exact SDO sequence of the enable, without sending anything."));
    connect(dryRun_, &QPushButton::clicked, this, [this] { dryRun(); });
    auto* close = new QPushButton(tr("Close"), this);
    close->setObjectName(QStringLiteral("close"));
    connect(close, &QPushButton::clicked, this, &QDialog::close);
    bar->addWidget(quickStop_);
    bar->addWidget(disable_);
    bar->addStretch(1);
    bar->addWidget(dryRun_);
    bar->addWidget(close);
    root->addLayout(bar);
    resize(1120, 960);
}

QString Ds402Wizard::sendRefusal() const {
    if (!workspace_->bus()) return tr("Not connected to a bus.");
    if (workspace_->bus()->isListenOnly()) return tr("Listen-only connection: the wizard does not send.");
    if (!workspace_->canTransmit() || !workspace_->sdo()) return tr("The bus is not open.");
    if (node_ <= 0) return tr("No drive chosen.");
    if (!ctl_) return tr("Node %1 is not being read: press “Read state” to read it again.").arg(node_);
    if (!cia402_) return tr("Node %1 is not a CiA 402 drive.").arg(node_);
    return {};
}

Ds402MotionPlot* Ds402Wizard::motionPlot() const { return move_->plot(); }
QPushButton* Ds402Wizard::holdToRunButton() const { return move_->holdButton(); }
QComboBox* Ds402Wizard::modeCombo() const { return mode_->combo(); }
WizardFramesPane* Ds402Wizard::framesPane() const { return tabs_->frames(); }
ScriptPreview* Ds402Wizard::preview() const { return tabs_->preview(); }
int8_t Ds402Wizard::modeDisplay() const { return mode_->driveMode(); }

// Close and the window's ✕ come through closeEvent, Esc through reject(); QDialog::closeEvent
// calls reject() again, and QDialog::reject() hides the window (and deletes it on close).
void Ds402Wizard::finishClosing() {
    if (closing_) return;
    closing_ = true;
    safeDisable(tr("wizard closed"));
    dropController({});  // nothing more goes out from this wizard
}

void Ds402Wizard::closeEvent(QCloseEvent* event) {
    finishClosing();
    QDialog::closeEvent(event);
}

void Ds402Wizard::reject() {
    finishClosing();
    QDialog::reject();
}

void Ds402Wizard::showEvent(QShowEvent* event) {
    QDialog::showEvent(event);
    if (!closing_) return;
    closing_ = false;  // shown again after a close: read the drive afresh
    if (node_ > 0) selectNode(node_);
}

// --- view

QString Ds402Wizard::message() const { return message_->text(); }

void Ds402Wizard::setMessage(const QString& text, bool bad) {
    message_->setText(text);
    message_->setStyleSheet(bad ? QStringLiteral("color: #a00000;") : QString());
}

QPushButton* Ds402Wizard::stepButton(Command c) const { return steps_->button(c); }

void Ds402Wizard::updateButtons() {
    const bool canSend = sendRefusal().isEmpty();
    const bool testing = ctl_ && ctl_->testMoveActive();
    const bool moving = testing || (ctl_ && ctl_->motionActive());
    const auto next = canopen::ds402::nextEnableCommand(state_);
    steps_->enableNext(next, canSend && !busy_ && !moving);
    mode_->setChoosable(canSend && !busy_ && !moving);
    const bool enabled = canSend && !busy_ && state_ == State::OperationEnabled;
    move_->setButtons(enabled && !moving,
                      canSend && (testing || (enabled && !moving && armed_ && armedKind_ == Armed::TestMove)));
    homing_->setButtons(canSend && !busy_ && !moving, canSend && motion_ == Motion::Homing);
    position_->setButtons(enabled && !moving,
                          canSend && (motion_ == Motion::Position ||
                                      (enabled && !moving && armed_ && armedKind_ == Armed::PositionMove)));
    // Always there while connected (DESIGN.md "quick stop / disable always visible").
    const bool connected = workspace_->canTransmit() && workspace_->sdo() && node_ > 0 && cia402_ && !closing_;
    quickStop_->setEnabled(connected);
    disable_->setEnabled(connected);
    dryRun_->setEnabled(node_ > 0 && cia402_);
}

}  // namespace coscope::gui
