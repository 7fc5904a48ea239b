// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/nodes/ owns the Nodes dock: its model over the node table, the network scan and
// the NMT commands.
#pragma once

#include <QDockWidget>
#include <QPointer>

#include <functional>
#include <map>

class QAction;
class QTableView;

namespace coscope::gui {

class NodeScanner;
class NodesModel;
class ProgramDownloadDialog;
class Workspace;

// The Nodes dock: nodes seen (boot-up, heartbeat, EMCY, SDO) or scanned, with a context menu
// for NMT commands, scan, identify and dictionary assignment. Everything that transmits is
// disabled when the bus is listen-only (or absent) and asks for confirmation first.
class NodesDock : public QDockWidget {
    Q_OBJECT
public:
    explicit NodesDock(Workspace* workspace, QWidget* parent = nullptr);

    void rebind();
    void refresh();

    NodesModel* model() const { return model_; }
    QTableView* view() const { return view_; }
    int selectedNode() const;  // -1 when none

    // The actions (for tests and menus); enabled only when the bus can transmit.
    QList<QAction*> commandActions() const { return commands_; }
    QAction* scanAction() const { return scan_; }
    // Context menu ▸ Heartbeat and guarding…: how CoScope watches the selected node.
    QAction* errorControlAction() const { return errorControl_; }
    // Context menu ▸ Download program…: the program download dialog (CiA 302-3) for the
    // selected node; disabled with the reason on a listen-only bus.
    QAction* programDownloadAction() const { return program_; }
    // Opens the dialog for `node` (window-modal, not blocking); the one open dialog is reused.
    ProgramDownloadDialog* openProgramDownload(int node);
    // An entry another part of the window adds to the node's context menu, after "Download
    // program…" (the project's program); it keeps its own enabled state.
    void addNodeAction(QAction* action) { extra_.append(action); }
    // Applies a choice of the dialog to `node` (canopen::HeartbeatMonitor); false with a message
    // when it cannot (node guarding on a listen-only bus).
    bool watchNode(int node, int consumerTimeMs, int guardTimeMs, int lifeTimeFactor);

    // Sends an NMT command (CiA 301 §7.2.8.3.1) after confirmation; `node` 0 = all nodes. A
    // command that stops a node's application first reads the drives' statusword 6041h, without
    // waiting on the GUI thread: the question shows when the answers (or their timeouts) are in.
    // False when refused at once (not connected, listen-only, another question open); true when
    // sent, or asked (nmtFinished() tells whether it went out).
    bool sendNmt(uint8_t command, int node, bool ask = true);
    // Scans node-IDs 1–127 and identifies who answers (NodeScanner); asks first unless `ask`
    // is false (the scan the window starts on connect). The one path behind every Scan button.
    void scan(bool ask = true);
    void assignDictionary(int node, const QString& name);
    // Test hook: answer confirmations without showing a dialog.
    void setAutoConfirm(bool on) { autoConfirm_ = on; }
    // Test hook: the text of the last confirmation asked (or auto-answered); "" while the
    // statusword reads before it are under way.
    QString lastConfirmation() const { return lastConfirmation_; }

signals:
    void nodeSelected(int node);
    void message(const QString& text);
    void nmtFinished(bool sent);

private:
    bool confirm(const QString& title, const QString& what);
    void updateEnabled();
    void editErrorControl();
    // Asks (the question box opens without blocking) and sends when the answer is yes.
    bool askNmt(uint8_t command, int node, const QString& warning);
    bool transmitNmt(uint8_t command, int node);
    // Before an NMT command that stops a node's application (stop, pre-operational, resets):
    // reads 6041h of the drives it reaches and calls `done` with one warning line per CiA 402
    // drive in Operation enabled ("" for none). False when nothing needs reading (`done` is not
    // called).
    bool readEnabledDrives(uint8_t command, int node, std::function<void(const QString&)> done);
    QString enabledDriveWarning(uint8_t command, const std::map<int, uint16_t>& statusword) const;

    Workspace* workspace_;
    NodesModel* model_ = nullptr;
    QTableView* view_ = nullptr;
    NodeScanner* scanner_ = nullptr;
    QList<QAction*> commands_;
    QAction* scan_ = nullptr;
    QAction* identify_ = nullptr;
    QAction* assign_ = nullptr;
    QAction* errorControl_ = nullptr;
    QAction* program_ = nullptr;
    QPointer<ProgramDownloadDialog> programDialog_;
    QList<QPointer<QAction>> extra_;
    bool autoConfirm_ = false;
    bool asking_ = false;  // an NMT question is being prepared or shown
    QString lastConfirmation_;
};

}  // namespace coscope::gui
