// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/nodes/NodesDock.h"

#include "app/gui/language/CoreText.h"

#include "app/gui/MenuTitle.h"
#include "app/gui/nodes/ErrorControlDialog.h"
#include "app/gui/nodes/NodeScanner.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/program/ProgramDownloadDialog.h"
#include "app/gui/session/Workspace.h"
#include "core/canopen/HeartbeatMonitor.h"
#include "core/canopen/MasterContext.h"
#include "core/canopen/Nmt.h"
#include "eds/DictionaryLibrary.h"

#include "core/canopen/SdoClient.h"

#include <QAction>
#include <QHeaderView>
#include <QInputDialog>
#include <QMenu>
#include <QMessageBox>
#include <QPointer>
#include <QTableView>
#include <QTimer>

namespace coscope::gui {

using canopen::NmtCommand;

NodesDock::NodesDock(Workspace* workspace, QWidget* parent) : QDockWidget(tr("Nodes"), parent), workspace_(workspace) {
    setObjectName(QStringLiteral("NodesDock"));
    model_ = new NodesModel(this);
    view_ = new QTableView(this);
    view_->setObjectName(QStringLiteral("nodesView"));
    view_->setModel(model_);
    view_->verticalHeader()->hide();
    view_->setSelectionBehavior(QAbstractItemView::SelectRows);
    view_->setSelectionMode(QAbstractItemView::SingleSelection);
    view_->setAlternatingRowColors(true);
    view_->horizontalHeader()->setStretchLastSection(true);
    view_->setContextMenuPolicy(Qt::CustomContextMenu);
    view_->setShowGrid(false);
    view_->setWordWrap(false);
    view_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    setWidget(view_);

    struct Cmd {
        NmtCommand cs;
        const char* text;
    };
    for (const Cmd& c :
         {Cmd{NmtCommand::Start, "Start (Operational)"}, Cmd{NmtCommand::Stop, "Stop"},
          Cmd{NmtCommand::EnterPreOperational, "Enter Pre-operational"}, Cmd{NmtCommand::ResetNode, "Reset node"},
          Cmd{NmtCommand::ResetCommunication, "Reset communication"}}) {
        auto* a = new QAction(tr(c.text), this);
        a->setData(static_cast<int>(c.cs));
        a->setObjectName(QStringLiteral("nmt_%1").arg(static_cast<int>(c.cs)));
        connect(a, &QAction::triggered, this,
                [this, a] { sendNmt(static_cast<uint8_t>(a->data().toInt()), std::max(0, selectedNode())); });
        commands_ << a;
    }
    // One action for the Nodes dock's context menu, Bus ▸ Scan network and the toolbar.
    scan_ = new QAction(tr("Scan network (SDO 1000h on nodes 1–127)"), this);
    scan_->setObjectName(QStringLiteral("scanAction"));
    scan_->setIconText(tr("Scan network"));
    connect(scan_, &QAction::triggered, this, [this] { scan(); });
    identify_ = new QAction(tr("Read identity"), this);
    connect(identify_, &QAction::triggered, this, [this] {
        if (selectedNode() > 0 && scanner_) scanner_->identify(selectedNode());
    });
    commands_ << scan_ << identify_;
    assign_ = new QAction(tr("Assign dictionary…"), this);
    connect(assign_, &QAction::triggered, this, [this] {
        const int node = selectedNode();
        if (node <= 0) return;
        const eds::DictionaryLibrary library;
        bool ok = false;
        const QString name = QInputDialog::getItem(
            this, tr("Assign dictionary"), tr("Dictionary for node %1:").arg(node), library.names(), 0, false, &ok);
        if (ok) assignDictionary(node, name);
    });

    errorControl_ = new QAction(tr("Heartbeat and guarding…"), this);
    errorControl_->setObjectName(QStringLiteral("errorControlAction"));
    connect(errorControl_, &QAction::triggered, this, &NodesDock::editErrorControl);
    program_ = new QAction(tr("Download program…"), this);
    program_->setObjectName(QStringLiteral("programDownloadAction"));
    connect(program_, &QAction::triggered, this, [this] {
        if (selectedNode() > 0) openProgramDownload(selectedNode());
    });

    connect(view_, &QWidget::customContextMenuRequested, this, [this](const QPoint& pos) {
        updateEnabled();
        QMenu menu(this);
        menu.setToolTipsVisible(true);  // why an entry is disabled
        const int node = selectedNode();
        addMenuTitle(menu, node > 0 ? tr("Node %1").arg(node) : tr("All nodes"));
        for (QAction* a : commands_)
            if (a != scan_ && a != identify_) menu.addAction(a);
        menu.addSeparator();
        menu.addAction(identify_);
        menu.addAction(assign_);
        menu.addAction(errorControl_);
        menu.addAction(program_);
        for (const QPointer<QAction>& a : extra_)
            if (a) menu.addAction(a);
        menu.addSeparator();
        menu.addAction(scan_);
        if (!workspace_->canTransmit())
            menu.addSection(workspace_->bus() && workspace_->bus()->isListenOnly()
                                ? tr("Listen-only: commands disabled")
                                : tr("Not connected"));
        menu.exec(view_->viewport()->mapToGlobal(pos));
    });
    connect(view_->selectionModel(), &QItemSelectionModel::currentRowChanged, this, [this] {
        if (selectedNode() > 0) emit nodeSelected(selectedNode());
    });
    rebind();
}

void NodesDock::rebind() {
    model_->setTable(&workspace_->nodes());
    model_->setClock([this]() -> int64_t {
        if (workspace_->isLive()) return nowNs();
        const auto& s = workspace_->store();
        return s && !s->empty() ? s->record(static_cast<FrameNo>(s->size() - 1)).timestampNs : 0;
    });
    delete scanner_;
    scanner_ = workspace_->sdo() ? new NodeScanner(workspace_->sdo(), this) : nullptr;
    if (scanner_)
        connect(scanner_, &NodeScanner::finished, this,
                [this](int n) { emit message(tr("Scan finished: %1 node(s) answered").arg(n)); });
    updateEnabled();
}

void NodesDock::refresh() {
    const int node = selectedNode();
    model_->refresh();
    if (node > 0 && selectedNode() != node) {
        const int row = model_->rowOfNode(node);
        if (row >= 0) view_->selectRow(row);
    }
    updateEnabled();
}

void NodesDock::updateEnabled() {
    const bool can = workspace_->canTransmit();
    for (QAction* a : commands_) a->setEnabled(can && (a != identify_ || selectedNode() > 0));
    scan_->setEnabled(can && scanner_ && !scanner_->isRunning());
    const QString why =
        scanner_ && scanner_->isRunning()                        ? tr("A scan is running")
        : workspace_->bus() && workspace_->bus()->isListenOnly() ? tr("Listen-only bus: a scan would transmit")
        : !can                                                   ? tr("Connect to a bus first")
               : tr("Read the device type 1000h of every node-ID 1–127, then each answering node's identity");
    if (scan_->statusTip() != why) {
        scan_->setStatusTip(why);
        scan_->setToolTip(why);
    }
    assign_->setEnabled(selectedNode() > 0);
    errorControl_->setEnabled(selectedNode() > 0 && workspace_->heartbeatMonitor());
    program_->setEnabled(can && selectedNode() > 0);
    const QString programWhy = workspace_->bus() && workspace_->bus()->isListenOnly()
                                   ? tr("Listen-only bus: a program download would transmit")
                               : !can ? tr("Connect to a bus first")
                               : selectedNode() <= 0
                                   ? tr("Select a node first")
                                   : tr("Load a new program (firmware) into the node: CiA 302-3 program download");
    program_->setStatusTip(programWhy);
    program_->setToolTip(programWhy);
}

ProgramDownloadDialog* NodesDock::openProgramDownload(int node) {
    if (node <= 0 || !workspace_->canTransmit()) return nullptr;
    if (programDialog_ && (programDialog_->node() == node || programDialog_->isDownloading())) {
        programDialog_->raise();
        programDialog_->activateWindow();
        return programDialog_;
    }
    delete programDialog_;
    programDialog_ = new ProgramDownloadDialog(workspace_, node, this);
    programDialog_->setAttribute(Qt::WA_DeleteOnClose);
    programDialog_->open();
    return programDialog_;
}

void NodesDock::editErrorControl() {
    const int node = selectedNode();
    canopen::HeartbeatMonitor* monitor = workspace_->heartbeatMonitor();
    if (node <= 0 || !monitor) return;
    canopen::NodeInfo info = workspace_->nodes().node(node).value_or(canopen::NodeInfo{});
    info.node = node;
    // Node guarding sends an RTR each guard time; listen-only never transmits.
    const QString off = workspace_->canTransmit() ? QString()
                        : workspace_->bus() && workspace_->bus()->isListenOnly()
                            ? tr("Listen-only bus: node guarding would transmit (an RTR each guard time); "
                                 "a heartbeat can still be watched.")
                            : tr("The bus is not open: node guarding cannot send its requests.");
    ErrorControlDialog dialog(info, off, this);
    if (dialog.exec() != QDialog::Accepted) return;
    const ErrorControlDialog::Choice c = dialog.choice();
    watchNode(node, c.kind == ErrorControlDialog::Kind::Heartbeat ? c.consumerTimeMs : 0,
              c.kind == ErrorControlDialog::Kind::Guarding ? c.guardTimeMs : 0, c.lifeTimeFactor);
}

bool NodesDock::watchNode(int node, int consumerTimeMs, int guardTimeMs, int lifeTimeFactor) {
    canopen::HeartbeatMonitor* monitor = workspace_->heartbeatMonitor();
    if (!monitor) return false;
    const auto id = static_cast<uint8_t>(node);
    if (guardTimeMs > 0) {
        QString error;
        if (!monitor->setGuarding(id, guardTimeMs, lifeTimeFactor, &error)) {
            emit message(tr("Node guarding of node %1 not started: %2").arg(node).arg(coreText(error)));
            QMessageBox::warning(this, tr("Node guarding"),
                                 tr("Node guarding of node %1 not started: %2").arg(node).arg(coreText(error)));
            return false;
        }
        emit message(tr("Node %1: node guarding every %2 ms, lost after %3 ms without an answer")
                         .arg(node)
                         .arg(guardTimeMs)
                         .arg(guardTimeMs * lifeTimeFactor));
    } else if (consumerTimeMs > 0) {
        monitor->setConsumerTime(id, consumerTimeMs);
        emit message(tr("Node %1: heartbeat expected within %2 ms").arg(node).arg(consumerTimeMs));
    } else {
        monitor->unwatch(id);
        emit message(tr("Node %1 is no longer watched").arg(node));
    }
    return true;
}

int NodesDock::selectedNode() const {
    const QModelIndex idx = view_->currentIndex();
    return idx.isValid() ? model_->nodeAt(idx.row()) : -1;
}

bool NodesDock::confirm(const QString& title, const QString& what) {
    lastConfirmation_ = what;
    if (autoConfirm_) return true;
    return QMessageBox::question(this, title, what, QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel) ==
           QMessageBox::Yes;
}

bool NodesDock::sendNmt(uint8_t command, int node, bool ask) {
    if (!workspace_->canTransmit() || !workspace_->master()) {
        emit message(workspace_->bus() && workspace_->bus()->isListenOnly()
                         ? tr("Listen-only: NMT commands are disabled")
                         : tr("Not connected to a bus"));
        return false;
    }
    if (!ask) return transmitNmt(command, node);
    if (asking_) {
        emit message(tr("An NMT command is waiting for your answer"));
        return false;
    }
    lastConfirmation_.clear();
    asking_ = true;  // until the question (after the reads, if any) is answered
    QPointer<NodesDock> self(this);
    if (readEnabledDrives(command, node, [self, command, node](const QString& warning) {
            if (self) self->askNmt(command, node, warning);
        }))
        return true;
    return askNmt(command, node, {});
}

bool NodesDock::askNmt(uint8_t command, int node, const QString& warning) {
    const auto frame = canopen::nmtFrame(static_cast<NmtCommand>(command), static_cast<uint8_t>(node));
    const QString target = node == 0 ? tr("all nodes") : tr("node %1").arg(node);
    const QString text = warning + tr("Send NMT “%1” to %2?\n\nFrame: %3")
                                       .arg(coreText(canopen::nmtCommandName(command)), target, formatCansend(frame));
    lastConfirmation_ = text;
    if (autoConfirm_) {
        asking_ = false;
        const bool sent = transmitNmt(command, node);
        emit nmtFinished(sent);
        return sent;
    }
    // Window-modal and answered through finished(): no event loop of its own on the GUI thread.
    asking_ = true;
    auto* box = new QMessageBox(QMessageBox::Question, tr("Send NMT command"), text,
                                QMessageBox::Yes | QMessageBox::Cancel, this);
    box->setDefaultButton(QMessageBox::Cancel);
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(box, &QMessageBox::finished, this, [this, box, command, node] {
        asking_ = false;
        const bool sent = box->clickedButton() == box->button(QMessageBox::Yes) && transmitNmt(command, node);
        emit nmtFinished(sent);
    });
    box->open();
    return true;
}

bool NodesDock::transmitNmt(uint8_t command, int node) {
    const QString target = node == 0 ? tr("all nodes") : tr("node %1").arg(node);
    QString error;
    if (!workspace_->master() ||
        !workspace_->master()->send(canopen::nmtFrame(static_cast<NmtCommand>(command), static_cast<uint8_t>(node)),
                                    &error)) {
        if (error.isEmpty()) error = tr("Not connected to a bus");
        emit message(tr("NMT %1 to %2 failed: %3").arg(coreText(canopen::nmtCommandName(command)), target, error));
        QMessageBox::warning(this, tr("NMT command failed"), error);
        return false;
    }
    emit message(tr("Sent NMT %1 to %2").arg(coreText(canopen::nmtCommandName(command)), target));
    return true;
}

bool NodesDock::readEnabledDrives(uint8_t command, int node, std::function<void(const QString&)> done) {
    // Stop (02h), enter pre-operational (80h), reset node (81h) and reset communication (82h)
    // end PDO/SDO control of the drive (CiA 301 §7.2.8.3.1); a drive in Operation enabled then
    // stops abruptly or trips its communication-loss reaction (6007h, CiA 402-2).
    if (command != 0x02 && command != 0x80 && command != 0x81 && command != 0x82) return false;
    canopen::SdoClient* sdo = workspace_->sdo();
    if (!sdo || !workspace_->canTransmit()) return false;
    std::vector<int> ids;
    if (node > 0) ids.push_back(node);
    else
        for (const canopen::NodeInfo& n : workspace_->nodes().snapshot()) ids.push_back(n.node);
    if (ids.empty()) return false;
    // Read the statusword 6041h of each node (short timeout; transfers to different nodes run
    // side by side). A node without 6041h simply aborts: not a drive. The answers come back
    // through the event loop; `done` runs once, when all are in or after a second at most.
    struct Reads {
        int pending = 0;
        bool finished = false;
        std::map<int, uint16_t> statusword;
    };
    auto reads = std::make_shared<Reads>();
    reads->pending = int(ids.size());
    QPointer<NodesDock> self(this);
    auto finish = [self, reads, command, done] {
        if (reads->finished) return;
        reads->finished = true;
        if (self) done(self->enabledDriveWarning(command, reads->statusword));
    };
    canopen::SdoOptions options;
    options.timeoutMs = 300;
    for (int id : ids)
        sdo->upload(
            static_cast<uint8_t>(id), 0x6041, 0,
            [reads, id, finish](const canopen::SdoResult& r) {
                if (r.ok && r.data.size() >= 2)
                    reads->statusword[id] = static_cast<uint16_t>(uint8_t(r.data[0]) | (uint8_t(r.data[1]) << 8));
                if (--reads->pending == 0) finish();
            },
            options);
    QTimer::singleShot(1000, this, finish);  // never wait long, whatever happens
    return true;
}

QString NodesDock::enabledDriveWarning(uint8_t command, const std::map<int, uint16_t>& statusword) const {
    QString out;
    for (const auto& [id, sw] : statusword) {
        // Operation enabled: bits 0-3, 5, 6 = x01x 0111 (CiA 402-2 Table 30).
        if ((sw & 0x6F) != 0x27) continue;
        const auto info = workspace_->nodes().node(id);
        const bool delta = info && info->dictionary.contains(QStringLiteral("delta"), Qt::CaseInsensitive);
        out += tr("Drive %1 is enabled (Operation enabled, statusword 0x%2): %3 stops it abruptly; the motor loses "
                  "torque or trips its "
                  "communication-loss reaction (6007h). %4Disable it first (CiA 402 wizard: Disable).\n\n")
                   .arg(id)
                   .arg(sw, 4, 16, QChar(u'0'))
                   .arg(command == 0x81 || command == 0x82 ? tr("a reset") : tr("this command"))
                   .arg(delta || !info || info->dictionary.isEmpty()
                            ? tr("Delta drives raise AL401 (CANopen communication lost). ")
                            : QString());
    }
    return out;
}

void NodesDock::scan(bool ask) {
    if (!workspace_->canTransmit() || !scanner_) {
        emit message(tr("Scan needs a connected bus that is not listen-only"));
        return;
    }
    if (scanner_->isRunning()) {
        emit message(tr("A scan is already running"));
        return;
    }
    if (ask && !confirm(tr("Scan network"),
                        tr("Read object 1000h from every node-ID 1–127 (SDO upload requests on 601h–67Fh)?")))
        return;
    emit message(tr("Scanning nodes 1–127…"));
    scanner_->scan();
    updateEnabled();
}

void NodesDock::assignDictionary(int node, const QString& name) {
    workspace_->nodes().setDictionary(node, name);
    if (workspace_->master()) workspace_->master()->setNodeDictionary(static_cast<uint8_t>(node), name);
    emit message(tr("Node %1 uses dictionary %2").arg(node).arg(name));
}

}  // namespace coscope::gui
