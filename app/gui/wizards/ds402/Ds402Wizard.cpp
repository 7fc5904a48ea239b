// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/ds402/Ds402Wizard.h"

#include "core/canopen/Sdo.h"

#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/common/ScriptPreview.h"
#include "app/gui/wizards/common/WizardFramesPane.h"
#include "app/gui/wizards/ds402/Ds402FaultText.h"
#include "app/gui/wizards/ds402/Ds402MotionPlot.h"
#include "app/gui/wizards/ds402/Ds402StateDiagram.h"
#include "app/gui/wizards/ds402/Ds402StatusPanel.h"
#include "app/gui/wizards/ds402/Ds402VendorNotes.h"
#include "core/canopen/SdoClient.h"
#include "eds/DictionaryLibrary.h"

#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QPointer>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QTabWidget>
#include <QTimer>
#include <QVBoxLayout>

#include <spdlog/spdlog.h>

namespace coscope::gui {

using canopen::Ds402Result;
using canopen::Ds402TestMove;
using canopen::SdoResult;
using canopen::ds402::Command;
using canopen::ds402::State;
namespace sw = canopen::ds402::sw;

namespace {
constexpr int kPollMs = 1000;      // idle refresh of the statusword
constexpr int kSettleMs = 100;     // re-read while the drive initialises or reacts to a fault
constexpr int kSettleTries = 30;   // ... for at most 3 s
constexpr int kFeedMs = 100;       // hold-to-run watchdog feed while the button is down
constexpr uint16_t kCia402 = 402;  // 1000h low word: device profile number (CiA 301 §7.5.2.1)

uint32_t le32(const QByteArray& b) {
    uint32_t v = 0;
    for (int i = 0; i < std::min<qsizetype>(4, b.size()); ++i) v |= uint32_t(uint8_t(b[i])) << (8 * i);
    return v;
}
QString hex4(uint32_t v) { return QStringLiteral("%1").arg(v, 4, 16, QChar(u'0')).toUpper(); }

// What each step does, in a technician's words with the CiA term beside it.
QString stepExplanation(Command c) {
    switch (c) {
    case Command::FaultReset:
        return QObject::tr("Fault reset (transition 15): clears the fault once its cause is removed. Sends controlword 6040h = 0000h, then "
                           "0080h (bit 7 rising). Expect Switch on disabled: fault bit 3 off, bit 6 on.");
    case Command::Shutdown:
        return QObject::tr("Shutdown (transition 2): gets the drive ready, the motor stays without power. Sends 6040h = 0006h. "
                           "Expect Ready to switch on: bits 0 and 5 on, bit 6 off.");
    case Command::SwitchOn:
        return QObject::tr("Switch on (transition 3): switches the power stage on, the motor is not yet energised; needs main power. "
                           "Sends 6040h = 0007h. Expect Switched on: bits 0, 1, 4 (voltage enabled) and 5 on.");
    case Command::EnableOperation:
        return QObject::tr("Enable operation (transition 4): energises the motor, which then holds its position and follows commands. "
                           "Sends 6040h = 000Fh. Expect Operation enabled: bits 0, 1, 2 and 5 on.");
    default: return canopen::ds402::commandName(c);
    }
}

// A test-move spin box in the drive's unit `u`, showing `raw` drive units.
void showInUnit(QDoubleSpinBox* box, const od::Unit& u, double maxRaw, double raw) {
    box->setDecimals(unitDecimals(u));
    box->setRange(-maxRaw * u.factor, maxRaw * u.factor);
    box->setSingleStep(std::max(1.0, 100.0 * u.factor));
    box->setSuffix(QStringLiteral(" ") + u.text);
    box->setValue(raw * u.factor);
}
}  // namespace

Ds402Wizard::Ds402Wizard(Workspace* workspace, int node, QWidget* parent) : QDialog(parent), workspace_(workspace) {
    setObjectName(QStringLiteral("ds402Wizard"));
    setWindowTitle(tr("CiA 402 enable step-through"));
    setProperty("screenshotReady", false);
    buildUi();
    poll_ = new QTimer(this);
    poll_->setInterval(kPollMs);
    connect(poll_, &QTimer::timeout, this, [this] {
        if (!busy_ && !reading_ && ctl_ && !ctl_->testMoveActive()) refresh();
    });
    feed_ = new QTimer(this);
    feed_->setInterval(kFeedMs);
    connect(feed_, &QTimer::timeout, this, [this] {
        if (ctl_ && holding_) ctl_->feedWatchdog();
    });
    connect(workspace_, &Workspace::busStateChanged, this, [this](CanBus::State s) {
        if (s == CanBus::State::Open) {
            if (!ctl_ && node_ > 0) selectNode(node_);
            return;
        }
        // The connection went away: tell the drive to disable if we still can, then forget it.
        safeDisable(tr("connection lost"));
        dropController(tr("Connection lost (bus %1). The drive was told to disable if the bus still accepted it; otherwise its own "
                          "communication-loss reaction (6007h) applies. Check the drive.").arg(s == CanBus::State::Error ? tr("error") : tr("closed")));
    });
    connect(workspace_, &Workspace::sourceChanged, this, [this] {
        if (ctlSdo_ != workspace_->sdo()) dropController(tr("The connection changed. Choose the drive again."));
    });
    connect(qApp, &QCoreApplication::aboutToQuit, this, [this] { safeDisable(tr("application quits")); });
    // Disconnecting (or switching source) closes the bus and the SDO client right after this
    // signal, before the client's queue would run: one expedited SDO download of 6040h goes out
    // at once on the bus (CanBus::send, which still refuses in listen-only) — Quick stop while
    // moving (605Ah: stop, then Switch on disabled), else Disable voltage.
    connect(workspace_, &Workspace::aboutToDisconnect, this, [this] {
        if (!workspace_->bus() || !workspace_->canTransmit() || node_ <= 0 || !cia402_) return;
        const bool moving = ctl_ && ctl_->testMoveActive();
        spdlog::info("ds402 wizard: bus closing, disabling node {}", node_);
        const CanFrame f = canopen::sdo::initiateDownload(static_cast<uint8_t>(node_), 0x6040, 0, QByteArray::fromHex(moving ? "0200" : "0000"));
        QString error;
        if (!workspace_->bus()->send(f, &error)) spdlog::warn("ds402 wizard: could not disable node {}: {}", node_, error.toStdString());
    });
    if (const QString why = sendRefusal(); !why.isEmpty() && workspace_->bus() && workspace_->bus()->isListenOnly()) {
        banner_->setText(tr("Listen-only connection: this wizard is disabled because it would have to send (SDO to 6040h/6041h)."));
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

    auto* stepsBox = new QGroupBox(tr("Step through — one button per transition"), this);
    auto* stl = new QVBoxLayout(stepsBox);
    auto* row = new QHBoxLayout;
    const std::pair<Command, QString> steps[] = {{Command::FaultReset, tr("1  Fault reset")},
                                                 {Command::Shutdown, tr("2  Shutdown")},
                                                 {Command::SwitchOn, tr("3  Switch on")},
                                                 {Command::EnableOperation, tr("4  Enable operation…")}};
    for (const auto& [cmd, text] : steps) {
        auto* b = new QPushButton(text, stepsBox);
        b->setObjectName(QStringLiteral("step_%1").arg(canopen::ds402::commandName(cmd).toLower().replace(u' ', u'_')));
        b->setToolTip(stepExplanation(cmd));
        const Command c = cmd;
        connect(b, &QPushButton::clicked, this, [this, c] {
            QString why;
            if (!runStep(c, &why) && !why.isEmpty()) setMessage(why, true);
        });
        steps_[cmd] = b;
        row->addWidget(b);
    }
    stl->addLayout(row);
    next_ = new QLabel(stepsBox);
    next_->setObjectName(QStringLiteral("nextStep"));
    next_->setWordWrap(true);
    next_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
    next_->setFixedHeight(next_->fontMetrics().lineSpacing() * 3 + 4);  // the steps do not move as it changes
    stl->addWidget(next_);
    root->addWidget(stepsBox);

    auto* lower = new QHBoxLayout;
    auto* modeBox = new QGroupBox(tr("Mode of operation (6060h / 6061h)"), this);
    auto* ml = new QFormLayout(modeBox);
    mode_ = new QComboBox(modeBox);
    mode_->setObjectName(QStringLiteral("modeCombo"));
    mode_->setPlaceholderText(tr("not read"));  // no item selected: the drive's mode is not among those offered
    connect(mode_, &QComboBox::currentIndexChanged, this, [this] { updateButtons(); });
    setMode_ = new QPushButton(tr("Set and verify"), modeBox);
    connect(setMode_, &QPushButton::clicked, this, [this] {
        QString why;
        if (!chooseMode(static_cast<int8_t>(mode_->currentData().toInt()), &why)) setMessage(why, true);
    });
    auto* mr = new QHBoxLayout;
    mr->addWidget(mode_, 1);
    mr->addWidget(setMode_);
    ml->addRow(tr("Mode:"), mr);
    modeShown_ = new QLabel(tr("Shown by the drive (6061h): not read"), modeBox);
    modeShown_->setWordWrap(true);
    ml->addRow(modeShown_);
    lower->addWidget(modeBox, 2);

    auto* moveBox = new QGroupBox(tr("Test move (optional, small limits)"), this);
    auto* mvl = new QHBoxLayout(moveBox);
    auto* form = new QFormLayout;
    moveKind_ = new QComboBox(moveBox);
    moveKind_->addItem(tr("Jog (profile velocity, 60FFh)"), 0);
    moveKind_->addItem(tr("Short move (profile position, 607Ah relative)"), 1);
    connect(moveKind_, &QComboBox::currentIndexChanged, this, [this] { applyUnits(); });
    form->addRow(tr("Kind:"), moveKind_);
    // In the drive's units (applyUnits): 2000 and 5000 drive units to begin with.
    velocity_ = new QDoubleSpinBox(moveBox);
    velocity_->setObjectName(QStringLiteral("testVelocity"));
    form->addRow(tr("Velocity:"), velocity_);
    distance_ = new QDoubleSpinBox(moveBox);
    distance_->setObjectName(QStringLiteral("testDistance"));
    form->addRow(tr("Distance:"), distance_);
    velocityShownIn_ = units_.jogVelocity;
    distanceShownIn_ = units_.distance;
    showInUnit(velocity_, velocityShownIn_, Ds402TestMove::kMaxVelocity, 2000);
    showInUnit(distance_, distanceShownIn_, Ds402TestMove::kMaxDistance, 5000);
    duration_ = new QSpinBox(moveBox);
    duration_->setRange(100, Ds402TestMove::kMaxDurationMs);
    duration_->setValue(3000);
    duration_->setSuffix(tr(" ms max"));
    form->addRow(tr("Time limit:"), duration_);
    arm_ = new QPushButton(tr("Arm test move…"), moveBox);
    arm_->setObjectName(QStringLiteral("armTestMove"));
    connect(arm_, &QPushButton::clicked, this, [this] {
        QString why;
        if (!armTestMove(&why) && !why.isEmpty()) setMessage(why, true);
    });
    hold_ = new QPushButton(tr("Hold to run"), moveBox);
    hold_->setObjectName(QStringLiteral("holdToRun"));
    hold_->setMinimumHeight(40);
    hold_->setToolTip(tr("The motor moves only while this button is held down; releasing it stops the motor."));
    connect(hold_, &QPushButton::pressed, this, [this] {
        QString why;
        if (!pressHoldToRun(&why) && !why.isEmpty()) setMessage(why, true);
    });
    connect(hold_, &QPushButton::released, this, &Ds402Wizard::releaseHoldToRun);
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(arm_);
    buttons->addWidget(hold_);
    form->addRow(buttons);
    mvl->addLayout(form, 1);
    plot_ = new Ds402MotionPlot(moveBox);
    mvl->addWidget(plot_, 1);
    lower->addWidget(moveBox, 3);
    root->addLayout(lower);

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

    tabs_ = new QTabWidget(this);
    frames_ = new WizardFramesPane(workspace_, tabs_);
    tabs_->addTab(frames_, tr("Frames (requests and responses)"));
    auto* dry = new QWidget(tabs_);
    auto* dryl = new QVBoxLayout(dry);
    preview_ = new ScriptPreview(dry);
    dryl->addWidget(preview_);
    // The preview's own "Save as script…" is the tab's only one; say where the file went.
    connect(preview_, &ScriptPreview::saved, this, [this](const QString& path) {
        setMessage(tr("Saved %1; replay it with: coscope-cli script run BUS %1").arg(path));
    });
    tabs_->addTab(dry, tr("Dry run (what will be sent)"));
    tabs_->setMinimumHeight(150);
    root->addWidget(tabs_, 2);

    auto* bar = new QHBoxLayout;
    quickStop_ = new QPushButton(tr("Quick stop"), this);
    quickStop_->setObjectName(QStringLiteral("quickStop"));
    quickStop_->setStyleSheet(QStringLiteral("QPushButton { background: #c62828; color: white; font-weight: bold; padding: 6px 18px; }"
                                             "QPushButton:disabled { background: #d9a0a0; }"));
    quickStop_->setToolTip(tr("Brakes on the drive's quick stop ramp (6040h = 0002h)."));
    connect(quickStop_, &QPushButton::clicked, this, &Ds402Wizard::quickStop);
    disable_ = new QPushButton(tr("Disable"), this);
    disable_->setObjectName(QStringLiteral("disable"));
    disable_->setStyleSheet(QStringLiteral("QPushButton { font-weight: bold; padding: 6px 18px; }"));
    disable_->setToolTip(tr("Removes power from the motor: Shutdown then Disable voltage (6040h = 0006h, 0000h)."));
    connect(disable_, &QPushButton::clicked, this, &Ds402Wizard::disableDrive);
    dryRun_ = new QPushButton(tr("Dry run"), this);
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
    resize(1080, 880);
}

// --- choosing the drive

QString Ds402Wizard::sendRefusal() const {
    if (!workspace_->bus()) return tr("Not connected to a bus.");
    if (workspace_->bus()->isListenOnly()) return tr("Listen-only connection: the wizard does not send.");
    if (!workspace_->canTransmit() || !workspace_->sdo()) return tr("The bus is not open.");
    if (node_ <= 0) return tr("No drive chosen.");
    if (!ctl_) return tr("Node %1 is not being read: press “Read state” to read it again.").arg(node_);
    if (!cia402_) return tr("Node %1 is not a CiA 402 drive.").arg(node_);
    return {};
}

void Ds402Wizard::findFirstDrive(int attempt) {
    if (node_ > 0 || attempt > 60) return;
    if (!workspace_->canTransmit() || !workspace_->sdo()) {
        if (workspace_->bus() && workspace_->bus()->isListenOnly()) return;
        QTimer::singleShot(500, this, [this, attempt] { findFirstDrive(attempt + 1); });
        return;
    }
    std::vector<int> ids;
    for (const canopen::NodeInfo& n : workspace_->nodes().snapshot()) ids.push_back(n.node);
    std::sort(ids.begin(), ids.end());
    if (ids.empty()) {
        QTimer::singleShot(500, this, [this, attempt] { findFirstDrive(attempt + 1); });
        return;
    }
    setMessage(tr("Looking for a CiA 402 drive (device type 1000h = …0192h)…"));
    // Ask the nodes one after the other for their device type.
    auto ask = std::make_shared<std::function<void(size_t)>>();
    QPointer<Ds402Wizard> self(this);
    *ask = [self, ids, ask, attempt](size_t i) {
        if (!self || self->node_ > 0) return;
        if (i >= ids.size() || !self->workspace_->sdo()) {
            *ask = nullptr;
            self->setMessage(tr("No CiA 402 drive answered yet; trying again."));
            QTimer::singleShot(1000, self, [self, attempt] {
                if (self) self->findFirstDrive(attempt + 1);
            });
            return;
        }
        self->workspace_->sdo()->upload(static_cast<uint8_t>(ids[i]), 0x1000, 0, [self, ids, ask, i](const SdoResult& r) {
            if (!self || self->node_ > 0 || !*ask) return;
            if (r.ok && (le32(r.data) & 0xFFFF) == kCia402) {
                *ask = nullptr;
                return self->selectNode(ids[i]);
            }
            (*ask)(i + 1);
        });
    };
    (*ask)(0);
}

void Ds402Wizard::selectNode(int node) {
    if (ctl_ && ctl_->testMoveActive()) ctl_->stopTestMove(tr("another drive was chosen"));
    if (node != node_) safeDisable(tr("another drive was chosen"));
    node_ = node;
    sentCommands_ = false;
    armed_ = false;
    supported_.reset();
    modeRead_ = false;
    mode_->setPlaceholderText(tr("not read"));  // not the previous drive's mode
    mode_->setCurrentIndex(-1);
    state_ = State::Unknown;
    visited_.clear();
    faultText_.clear();
    controlWarning_.clear();
    cia402_ = true;
    diagram_->setState(State::Unknown);
    status_->clear();
    const auto info = workspace_->nodes().node(node);
    dictionary_ = info ? info->dictionary : QString();
    ++selection_;
    reading_ = false;  // answers to reads for the earlier choice are dropped
    settleTries_ = 0;
    // The node list of the combo: every node seen, this one selected.
    nodeCombo_->clear();
    for (const canopen::NodeInfo& n : workspace_->nodes().snapshot())
        nodeCombo_->addItem(n.dictionary.isEmpty() ? tr("Node %1").arg(n.node) : tr("Node %1 — %2").arg(n.node).arg(n.dictionary), n.node);
    if (nodeCombo_->findData(node) < 0) nodeCombo_->addItem(tr("Node %1").arg(node), node);
    nodeCombo_->setCurrentIndex(nodeCombo_->findData(node));
    frames_->setNode(node);
    frames_->markStart();
    makeController();
    if (dictionary_.isEmpty() && ctl_) {
        // The node table has no dictionary yet (the network was not scanned): match one as the
        // node scan does, by the identity object 1018h sub 1 vendor-ID, sub 2 product code
        // (CiA 301 §7.5.2.21), or without one by 1000h and 1008h, so the vendor notes and alarm
        // texts are known.
        setMessage(tr("Reading the identity of node %1 (1018h)…").arg(node));
        auto device = std::make_shared<eds::DeviceIdentity>();
        QPointer<Ds402Wizard> self(this);
        const int selection = selection_;
        readObject(0x1000, 0, [device](const SdoResult& r) {
            if (r.ok) device->deviceType = le32(r.data);
        });
        readObject(0x1008, 0, [device](const SdoResult& r) {
            if (r.ok) device->deviceName = QString::fromLatin1(r.data).section(QChar(0), 0, 0);
        });
        readObject(0x1018, 1, [device](const SdoResult& r) {
            if (r.ok) device->vendorId = le32(r.data);
        });
        readObject(0x1018, 2, [self, device, selection](const SdoResult& r) {
            if (!self || selection != self->selection_) return;
            if (r.ok) device->productCode = le32(r.data);
            if (const auto* e = eds::DictionaryLibrary::shared().match(*device)) self->dictionary_ = e->name;
            self->setMessage({});
            self->startReading();
        });
        return;
    }
    startReading();
}

void Ds402Wizard::startReading() {
    units_ = Ds402Units::forDictionary(dictionary_);
    applyUnits();
    const auto notes = ds402VendorNotes(dictionary_);
    vendor_->setText(notes ? QStringLiteral("<b>%1:</b> %2").arg(notes->vendor, notes->before.toHtmlEscaped()) : QString());
    if (notes && notes->notCia402) {
        cia402_ = false;
        setMessage(tr("Node %1 is a %2: %3").arg(node_).arg(notes->vendor, notes->before), true);
        setProperty("screenshotReady", true);
        updateButtons();
        emit stateRead(false);
        return;
    }
    setMessage({});  // e.g. "Looking for a CiA 402 drive…" is over
    refresh();
    poll_->start();
}

void Ds402Wizard::makeController() {
    ctl_.reset();
    ctlSdo_ = nullptr;
    if (node_ <= 0 || !workspace_->sdo() || !workspace_->canTransmit()) return;
    ctlSdo_ = workspace_->sdo();
    ctl_ = std::make_unique<canopen::Ds402Controller>(*ctlSdo_, static_cast<uint8_t>(node_));
    ctl_->setTimeout(1000);
    ctl_->setSendObserver([](const QString& line) { spdlog::info("ds402 wizard: {}", line.toStdString()); });
}

void Ds402Wizard::dropController(const QString& why) {
    poll_->stop();
    feed_->stop();
    holding_ = false;
    busy_ = reading_ = false;
    ctl_.reset();
    ctlSdo_ = nullptr;
    // Nothing read any more: show no state rather than the last one (it may be long gone).
    ++selection_;  // answers still under way are dropped
    state_ = State::Unknown;
    statusword_ = 0;
    armed_ = false;
    diagram_->setState(State::Unknown);
    diagram_->setNextTransition(std::nullopt);
    status_->clear();
    modeRead_ = false;
    modeShown_->setText(tr("Shown by the drive (6061h): not read"));
    mode_->setPlaceholderText(tr("not read"));
    mode_->setCurrentIndex(-1);
    next_->setText(node_ > 0 ? tr("The state of node %1 is not known: not connected.").arg(node_) : QString());
    if (!why.isEmpty()) setMessage(why, true);
    updateButtons();
}

void Ds402Wizard::readObject(uint16_t index, uint8_t sub, std::function<void(const SdoResult&)> done) {
    if (!ctlSdo_ || ctlSdo_ != workspace_->sdo()) {
        SdoResult r;
        r.error = tr("not connected");
        return done(r);
    }
    QPointer<Ds402Wizard> self(this);
    ctlSdo_->upload(static_cast<uint8_t>(node_), index, sub, [self, done](const SdoResult& r) {
        if (self) done(r);
    });
}

// --- reading the state

void Ds402Wizard::refresh() {
    // No controller (the connection changed or the window was closed and shown again): choose
    // the same drive again, which reads it afresh.
    if (!ctl_ && node_ > 0 && workspace_->canTransmit() && workspace_->sdo()) return selectNode(node_);
    // Never while a step runs: the step reads 6041h itself and its result is the state shown.
    if (!ctl_ || reading_ || busy_ || !cia402_) return;
    reading_ = true;
    QPointer<Ds402Wizard> self(this);
    const int selection = selection_;
    ctl_->readState([self, selection](const Ds402Result& r) {
        if (!self || selection != self->selection_) return;
        if (r.ok && r.state == State::NotReadyToSwitchOn && self->settleTries_ < kSettleTries) {
            // Still initialising: it goes to Switch on disabled by itself (CiA 402-2 §6.2,
            // transition 1). Read again soon instead of showing a state without a next step.
            ++self->settleTries_;
            self->showState(r.state, r.statusword);
            self->setMessage(tr("The drive is initialising (Not ready to switch on); waiting for Switch on disabled…"));
            QTimer::singleShot(kSettleMs, self, [self] {
                if (!self) return;
                self->reading_ = false;
                self->refresh();
            });
            return;
        }
        if (self->settleTries_ > 0 && r.ok) self->setMessage(tr("The drive finished initialising."));
        self->settleTries_ = 0;
        self->afterState(r, [self, ok = r.ok, selection] {
            if (!self || selection != self->selection_) return;
            self->reading_ = false;
            self->updateButtons();
            emit self->stateRead(ok);
        });
    });
}

void Ds402Wizard::afterState(const Ds402Result& r, std::function<void()> then) {
    if (!r.ok) {
        if (r.error.contains(QStringLiteral("06020000")) || r.error.contains(QStringLiteral("does not exist"), Qt::CaseInsensitive)) {
            cia402_ = false;
            poll_->stop();
            setMessage(tr("Node %1 has no statusword 6041h: it is not a CiA 402 drive (%2).").arg(node_).arg(r.error), true);
            setProperty("screenshotReady", true);
        } else {
            setMessage(tr("Cannot read the drive's state: %1. Check that the drive is powered and connected, and its node-ID.").arg(r.error), true);
        }
        return then();
    }
    showState(r.state, r.statusword);
    QPointer<Ds402Wizard> self(this);
    // 6061h: the mode the drive runs in; 6502h once: the modes it supports.
    readObject(0x6061, 0, [self, then](const SdoResult& m) {
        if (m.ok && !m.data.isEmpty()) self->showDriveMode(static_cast<int8_t>(m.data[0]));
        auto afterModes = [self, then] {
            if (!self) return;
            const bool fault = self->statusword_ & sw::Fault;
            if (!fault) {
                self->faultText_.clear();
                self->status_->setFaultText({});
                self->setProperty("screenshotReady", true);
                return then();
            }
            // In fault: 603Fh error code and the newest 1003h entry for the vendor alarm.
            self->readObject(0x603F, 0, [self, then](const SdoResult& e) {
                const uint16_t code = e.ok ? static_cast<uint16_t>(le32(e.data)) : 0;
                self->readObject(0x1003, 1, [self, then, code, e](const SdoResult& h) {
                    const Ds402Fault f = describeDs402Fault(self->dictionary_, code, h.ok ? le32(h.data) : 0);
                    self->faultText_ = e.ok ? f.text() : tr("Error code 603Fh could not be read: %1").arg(e.error);
                    self->status_->setFaultText(self->faultText_);
                    self->setProperty("screenshotReady", true);
                    then();
                });
            });
        };
        if (self->supported_) return afterModes();
        self->readObject(0x6502, 0, [self, afterModes](const SdoResult& s) {
            self->supported_ = s.ok ? le32(s.data) : 0x3EDu;  // unknown: offer the standard modes
            self->fillModes();
            // Vendor pre-condition: the control-mode parameter (Delta P1-01, AIMOTOR H02-00).
            const auto notes = ds402VendorNotes(self->dictionary_);
            if (!notes || !notes->controlIndex) return afterModes();
            self->readObject(notes->controlIndex, notes->controlSub, [self, afterModes, n = *notes](const SdoResult& c) {
                if (c.ok && static_cast<int64_t>(le32(c.data)) != n.controlValue)
                    self->controlWarning_ = tr("%1 is %2, not %3: the drive is not in CANopen control and will ignore the controlword. Set %1 = %3 first.")
                                                .arg(n.controlName)
                                                .arg(le32(c.data))
                                                .arg(n.controlValue);
                if (!self->controlWarning_.isEmpty()) self->setMessage(self->controlWarning_, true);
                afterModes();
            });
        });
    });
}

void Ds402Wizard::showState(State s, uint16_t swd) {
    statusword_ = swd;
    if (s != state_ || visited_.isEmpty()) visited_ << s;
    state_ = s;
    diagram_->setState(s);
    status_->setStatusword(swd);
    const auto next = canopen::ds402::nextEnableCommand(s);
    diagram_->setNextTransition(next ? ds402TransitionNumber(s, *next) : std::nullopt);
    if (!cia402_) next_->clear();
    else if (s == State::OperationEnabled) next_->setText(tr("The drive is enabled (Operation enabled). Choose a mode and try a test move, or press Disable."));
    else if (s == State::QuickStopActive) next_->setText(tr("Quick stop is active: press Disable to leave it (Disable voltage, transition 12)."));
    else if (next) next_->setText(tr("Next: %1").arg(stepExplanation(*next)));
    else next_->setText(tr("The drive is in %1; wait for it to settle, then read the state again.").arg(canopen::ds402::stateName(s)));
    updateButtons();
}

void Ds402Wizard::fillModes() {
    mode_->clear();
    for (int8_t m : {1, 3, 4, 6, 7, 8, 9, 10})
        if (supported_ && canopen::ds402::modeSupported(*supported_, m)) mode_->addItem(canopen::ds402::modeName(m), int(m));
    // The jog needs profile velocity; otherwise the short profile-position move.
    const bool pv = supported_ && canopen::ds402::modeSupported(*supported_, 3);
    moveKind_->setCurrentIndex(pv ? 0 : 1);
    if (modeRead_) {
        modeRead_ = false;  // as read anew: the box shows the drive's mode
        showDriveMode(modeDisplay_);
    }
}

void Ds402Wizard::showDriveMode(int8_t mode) {
    const bool changed = !modeRead_ || mode != modeDisplay_;
    modeDisplay_ = mode;
    modeRead_ = true;
    const QString name = canopen::ds402::modeName(mode);
    modeShown_->setText(tr("Shown by the drive (6061h): %1").arg(name));
    status_->setModeText(tr("Mode of operation (6061h): %1").arg(name));
    if (!changed) return;  // a choice not yet applied stays until the drive's mode changes
    // The Mode box shows the drive's own mode (its name as placeholder when it is not offered),
    // and the test move the kind that mode runs (PV: jog, PP: short move).
    mode_->setPlaceholderText(name);
    mode_->setCurrentIndex(mode_->findData(int(mode)));
    if (mode == 3) moveKind_->setCurrentIndex(0);
    if (mode == 1) moveKind_->setCurrentIndex(1);
}

// --- steps

bool Ds402Wizard::confirm(const QString& title, const QString& text) {
    if (autoConfirm_) return true;
    return QMessageBox::question(this, title, text, QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel) == QMessageBox::Yes;
}

QString Ds402Wizard::checkAdvice() const {
    QStringList out;
    if (const auto notes = ds402VendorNotes(dictionary_)) out << notes->before;
    out << tr("Check main power, the enable and safe torque off (STO) inputs, and the drive's own display.");
    return out.join(u' ');
}

bool Ds402Wizard::runStep(Command command, QString* why) {
    if (const QString r = sendRefusal(); !r.isEmpty()) {
        if (why) *why = r;
        return false;
    }
    if (busy_) {
        if (why) *why = tr("Wait for the current step to finish.");
        return false;
    }
    if (command == Command::EnableOperation &&
        !confirm(tr("Enable operation"), tr("Enable operation energises the motor of node %1: it will hold its position and follow commands.\n\n"
                                            "Make sure the machine is safe to move and people are clear.\n\nSend 6040h = 000Fh now?").arg(node_))) {
        if (why) *why = tr("Enable operation was not confirmed; nothing was sent.");
        return false;
    }
    busy_ = true;
    sentCommands_ = true;
    const QString name = canopen::ds402::commandName(command);
    setMessage(tr("%1: sending… (%2)").arg(name, stepExplanation(command)));
    updateButtons();
    QPointer<Ds402Wizard> self(this);
    ctl_->transition(command, [self, command, name](const Ds402Result& r) {
        if (!self) return;
        if (r.ok) {
            self->busy_ = false;
            self->showState(r.state, r.statusword);
            self->setMessage(tr("%1 done: the drive is now in %2 (statusword %3h).").arg(name, canopen::ds402::stateName(r.state), hex4(r.statusword)));
            self->poll_->start();  // the next idle read one full interval from now
            emit self->stepFinished(true);
            return;
        }
        // Failed: say which step and what the drive answered, then leave it disabled.
        if (r.statusword || r.state != State::Unknown) self->showState(r.state, r.statusword);
        QString text = tr("Step “%1” failed: %2.").arg(name, r.error);
        if (!r.advice.isEmpty()) text += QStringLiteral("\n") + r.advice + QStringLiteral(".");
        self->setMessage(text, true);
        if (!self->ctl_) return;
        self->ctl_->disableVoltage([self, text, command](const Ds402Result& d0) {
            if (!self) return;
            self->settleFaultReaction(d0, 0, [self, text, command](const Ds402Result& d) {
                if (!self) return;
                self->busy_ = false;
                QString t = text + (d.ok ? tr("\nThe drive was sent Disable voltage (6040h = 0000h) and is now in %1.").arg(canopen::ds402::stateName(d.state))
                                         : tr("\nDISABLING FAILED: %1").arg(d.error));
                if (d.ok) self->showState(d.state, d.statusword);
                self->reading_ = true;
                self->afterState(d, [self, t] {
                    if (!self) return;
                    self->reading_ = false;
                    QString full = t;
                    if (!self->faultText_.isEmpty()) full += QStringLiteral("\n") + self->faultText_;
                    full += QStringLiteral("\n") + tr("What to check: ") + self->checkAdvice();
                    self->setMessage(full, true);
                    self->updateButtons();
                    emit self->stepFinished(false);
                });
                (void)command;
            });
        });
    });
    return true;
}

void Ds402Wizard::settleFaultReaction(const Ds402Result& r, int tries, std::function<void(const Ds402Result&)> done) {
    // Fault reaction active ends in Fault by itself once the drive has braked (CiA 402-2 §6.2,
    // transition 14): show where it ends, not the passing state.
    if (!r.ok || r.state != State::FaultReactionActive || tries >= kSettleTries || !ctl_) return done(r);
    QPointer<Ds402Wizard> self(this);
    QTimer::singleShot(kSettleMs, this, [self, tries, done] {
        if (!self || !self->ctl_) return;
        self->ctl_->readState([self, tries, done](const Ds402Result& again) {
            if (self) self->settleFaultReaction(again, tries + 1, done);
        });
    });
}

bool Ds402Wizard::chooseMode(int8_t mode, QString* why) {
    if (const QString r = sendRefusal(); !r.isEmpty()) {
        if (why) *why = r;
        return false;
    }
    if (busy_ || ctl_->testMoveActive()) {
        if (why) *why = tr("Wait for the current step to finish.");
        return false;
    }
    if (supported_ && !canopen::ds402::modeSupported(*supported_, mode)) {
        if (why) *why = tr("The drive does not list %1 as supported (6502h = %2h).").arg(canopen::ds402::modeName(mode)).arg(QStringLiteral("%1").arg(*supported_, 8, 16, QChar(u'0')).toUpper());
        return false;
    }
    busy_ = true;
    updateButtons();
    setMessage(tr("Setting the mode of operation: 6060h = %1 (%2), then checking 6061h…").arg(mode).arg(canopen::ds402::modeName(mode)));
    QPointer<Ds402Wizard> self(this);
    ctl_->setMode(mode, [self, mode](const Ds402Result& r) {
        if (!self) return;
        self->busy_ = false;
        if (r.ok) {
            self->showDriveMode(r.mode);
            self->modeShown_->setText(tr("Shown by the drive (6061h): %1 ✓").arg(canopen::ds402::modeName(r.mode)));
            self->setMessage(tr("Mode set and verified: the drive shows %1 in 6061h.").arg(canopen::ds402::modeName(r.mode)));
        } else {
            self->setMessage(tr("Could not set %1: %2").arg(canopen::ds402::modeName(mode), r.error), true);
        }
        self->updateButtons();
        emit self->modeFinished(r.ok);
    });
    return true;
}

// --- test move

void Ds402Wizard::setTestMove(const Ds402TestMove& m) {
    moveKind_->setCurrentIndex(m.kind == Ds402TestMove::Kind::Jog ? 0 : 1);
    velocity_->setValue(m.velocity * velocityShownIn_.factor);
    distance_->setValue(m.distance * distanceShownIn_.factor);
    duration_->setValue(m.maxDurationMs);
}

Ds402TestMove Ds402Wizard::testMove() const {
    // The spin boxes show the drive's units; the drive gets raw numbers (display = raw × factor).
    const auto velocity = static_cast<int32_t>(std::llround(velocity_->value() / velocityShownIn_.factor));
    Ds402TestMove m;
    m.kind = moveKind_->currentIndex() == 0 ? Ds402TestMove::Kind::Jog : Ds402TestMove::Kind::Relative;
    m.velocity = m.kind == Ds402TestMove::Kind::Jog ? velocity : std::abs(velocity);
    m.distance = static_cast<int32_t>(std::llround(distance_->value() / distanceShownIn_.factor));
    m.maxDurationMs = duration_->value();
    m.acceleration = m.deceleration = static_cast<uint32_t>(std::max(1000, std::abs(velocity) * 5));
    return m;
}

void Ds402Wizard::applyUnits() {
    // The same speed and distance, shown in the unit of the object the move kind writes.
    const double velocity = velocity_->value() / velocityShownIn_.factor, distance = distance_->value() / distanceShownIn_.factor;
    velocityShownIn_ = moveKind_->currentIndex() == 0 ? units_.jogVelocity : units_.profileVelocity;
    distanceShownIn_ = units_.distance;
    showInUnit(velocity_, velocityShownIn_, Ds402TestMove::kMaxVelocity, velocity);
    showInUnit(distance_, distanceShownIn_, Ds402TestMove::kMaxDistance, distance);
    plot_->setUnits(units_.position, units_.velocity);
}

bool Ds402Wizard::testMoveRunning() const { return ctl_ && ctl_->testMoveActive(); }

bool Ds402Wizard::armTestMove(QString* why) {
    if (const QString r = sendRefusal(); !r.isEmpty()) {
        if (why) *why = r;
        return false;
    }
    if (state_ != State::OperationEnabled) {
        if (why) *why = tr("Enable the drive first (Operation enabled), then arm the test move.");
        return false;
    }
    const Ds402TestMove m = testMove();
    if (const QString bad = m.check(); !bad.isEmpty()) {
        if (why) *why = bad;
        return false;
    }
    const QString what = m.kind == Ds402TestMove::Kind::Jog
                             ? tr("turn at %1 (profile velocity, 60FFh = %2)").arg(inUnit(m.velocity, velocityShownIn_)).arg(m.velocity)
                             : tr("move %1 at up to %2 (profile position, relative: 607Ah = %3, 6081h = %4)")
                                   .arg(inUnit(m.distance, distanceShownIn_), inUnit(m.velocity, velocityShownIn_))
                                   .arg(m.distance)
                                   .arg(m.velocity);
    if (!confirm(tr("Test move"), tr("While you hold “Hold to run”, the motor of node %1 will %2, for at most %3 ms.\n"
                                     "Releasing the button stops it. Make sure the axis is free to move.\n\nArm the test move?")
                                      .arg(node_).arg(what).arg(m.maxDurationMs))) {
        if (why) *why = tr("Test move not armed.");
        return false;
    }
    armed_ = true;
    setMessage(tr("Test move armed: hold the “Hold to run” button to move, release it to stop."));
    updateButtons();
    return true;
}

bool Ds402Wizard::pressHoldToRun(QString* why) {
    if (const QString r = sendRefusal(); !r.isEmpty()) {
        if (why) *why = r;
        return false;
    }
    if (!armed_) {
        if (why) *why = tr("Arm the test move first.");
        return false;
    }
    if (busy_ || ctl_->testMoveActive()) {
        if (why) *why = tr("Wait for the current step to finish.");
        return false;
    }
    holding_ = true;
    plot_->clear();
    const Ds402TestMove m = testMove();
    QPointer<Ds402Wizard> self(this);
    QString error;
    const bool started = ctl_->startTestMove(
        m,
        [self](const canopen::Ds402MotionSample& s) {
            if (!self) return;
            self->plot_->addSample(double(s.ms), double(s.position), double(s.velocity));
            self->status_->setStatusword(s.statusword ? s.statusword : self->statusword_);
        },
        [self](const Ds402Result& r) {
            if (!self) return;
            self->feed_->stop();
            self->holding_ = false;
            if (r.ok) self->setMessage(tr("Test move stopped: %1. The drive stays enabled; press Disable when done.").arg(r.stopReason));
            else self->setMessage(tr("Test move failed: %1").arg(r.error), true);
            self->refresh();
            self->updateButtons();
            emit self->testMoveFinished(r.ok);
        },
        &error);
    if (!started) {
        holding_ = false;
        if (why) *why = error;
        return false;
    }
    feed_->start();
    setMessage(tr("Moving while the button is held…"));
    updateButtons();
    return true;
}

void Ds402Wizard::releaseHoldToRun() {
    holding_ = false;
    feed_->stop();
    if (ctl_ && ctl_->testMoveActive()) ctl_->stopTestMove(tr("hold-to-run button released"));
}

// --- always there

void Ds402Wizard::quickStop() {
    if (!ctl_ && !closing_) makeController();  // the window shows a drive: Quick stop works whatever came before
    if (!ctl_) return setMessage(tr("Quick stop: %1").arg(sendRefusal()), true);
    holding_ = false;
    sentCommands_ = true;
    setMessage(tr("Quick stop: sending 6040h = 0002h…"));
    QPointer<Ds402Wizard> self(this);
    ctl_->quickStop([self](const Ds402Result& r) {
        if (!self) return;
        if (r.ok) {
            self->showState(r.state, r.statusword);
            self->setMessage(tr("Quick stop done: the drive is in %1.").arg(canopen::ds402::stateName(r.state)));
        } else {
            self->setMessage(tr("Quick stop: %1").arg(r.error), true);
        }
        self->refresh();
    });
}

void Ds402Wizard::disableDrive() {
    if (!ctl_ && !closing_) makeController();
    if (!ctl_) return setMessage(tr("Disable: %1").arg(sendRefusal()), true);
    holding_ = false;
    armed_ = false;
    setMessage(tr("Disabling: Shutdown, then Disable voltage…"));
    QPointer<Ds402Wizard> self(this);
    auto done = [self](const Ds402Result& r) {
        if (!self) return;
        if (r.ok) {
            self->showState(r.state, r.statusword);
            self->setMessage(tr("The drive is disabled (%1): the motor has no power.").arg(canopen::ds402::stateName(r.state)));
        } else {
            self->setMessage(tr("Disable: %1").arg(r.error), true);
        }
        self->refresh();
    };
    // During a test move: no power at once (the move's monitor sees it and stops too).
    if (ctl_->testMoveActive()) ctl_->disableVoltage(done);
    else ctl_->disable(done);
}

canopen::CommandScript Ds402Wizard::dryRun() {
    std::optional<int8_t> mode;
    if (mode_->currentIndex() >= 0 && mode_->currentData().toInt() != modeDisplay_) mode = static_cast<int8_t>(mode_->currentData().toInt());
    canopen::CommandScript script = canopen::Ds402Controller::enableScript(static_cast<uint8_t>(std::max(node_, 1)), 0, state_, mode);
    preview_->setScript(script);
    tabs_->setCurrentIndex(1);
    setMessage(tr("Dry run: %n step(s) the enable would send from %1 — nothing was sent. “Save as script…” keeps them for coscope-cli script run.", nullptr,
                  int(script.steps.size()))
                   .arg(canopen::ds402::stateName(state_)));
    return script;
}

bool Ds402Wizard::safeDisable(const QString& why) {
    if (!ctlSdo_ || ctlSdo_ != workspace_->sdo() || !workspace_->canTransmit() || node_ <= 0 || !cia402_) return false;
    const bool moving = ctl_ && ctl_->testMoveActive();
    const bool powered = state_ == State::OperationEnabled || state_ == State::SwitchedOn || state_ == State::QuickStopActive ||
                         (sentCommands_ && state_ == State::ReadyToSwitchOn);
    if (!moving && !powered) return false;
    spdlog::info("ds402 wizard: disabling node {} ({})", node_, why.toStdString());
    const auto n = static_cast<uint8_t>(node_);
    // Fire and forget (the wizard may be gone when the answers come): the SDO client sends in order.
    if (moving) ctlSdo_->download(n, 0x6040, 0, QByteArray::fromHex("0200"), [](const SdoResult&) {});  // quick stop
    ctlSdo_->download(n, 0x6040, 0, QByteArray::fromHex("0000"), [](const SdoResult&) {});              // disable voltage
    return true;
}

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

QPushButton* Ds402Wizard::stepButton(Command c) const {
    auto it = steps_.find(c);
    return it == steps_.end() ? nullptr : it->second;
}

void Ds402Wizard::updateButtons() {
    const bool canSend = sendRefusal().isEmpty();
    const bool moving = ctl_ && ctl_->testMoveActive();
    const auto next = canopen::ds402::nextEnableCommand(state_);
    for (auto& [cmd, b] : steps_) {
        b->setEnabled(canSend && !busy_ && !moving && next && *next == cmd);
        QFont f = b->font();
        f.setBold(b->isEnabled());
        b->setFont(f);
    }
    mode_->setEnabled(canSend && !busy_ && !moving);
    setMode_->setEnabled(canSend && !busy_ && !moving && mode_->currentIndex() >= 0);
    arm_->setEnabled(canSend && !busy_ && !moving && state_ == State::OperationEnabled);
    hold_->setEnabled(canSend && (moving || (armed_ && !busy_ && state_ == State::OperationEnabled)));
    // Always there while connected (DESIGN.md "quick stop / disable always visible").
    const bool connected = workspace_->canTransmit() && workspace_->sdo() && node_ > 0 && cia402_ && !closing_;
    quickStop_->setEnabled(connected);
    disable_->setEnabled(connected);
    dryRun_->setEnabled(node_ > 0 && cia402_);
}

}  // namespace coscope::gui
