// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDockWidget>

class QAction;
class QTableView;

namespace coscope::gui {

class NodeScanner;
class NodesModel;
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

    // Sends an NMT command (CiA 301 §7.2.8.3.1) after confirmation; `node` 0 = all nodes.
    bool sendNmt(uint8_t command, int node, bool confirm = true);
    // Scans node-IDs 1–127 and identifies who answers (NodeScanner); asks first unless `ask`
    // is false (the scan the window starts on connect). The one path behind every Scan button.
    void scan(bool ask = true);
    void assignDictionary(int node, const QString& name);
    // Test hook: answer confirmations without showing a dialog.
    void setAutoConfirm(bool on) { autoConfirm_ = on; }
    // Test hook: the text of the last confirmation asked (or auto-answered).
    QString lastConfirmation() const { return lastConfirmation_; }

signals:
    void nodeSelected(int node);
    void message(const QString& text);

private:
    bool confirm(const QString& title, const QString& what);
    void updateEnabled();
    // Before an NMT command that stops a node's application (stop, pre-operational, resets):
    // one warning line per CiA 402 drive that reads back Operation enabled, else "".
    QString enabledDriveWarning(uint8_t command, int node);

    Workspace* workspace_;
    NodesModel* model_ = nullptr;
    QTableView* view_ = nullptr;
    NodeScanner* scanner_ = nullptr;
    QList<QAction*> commands_;
    QAction* scan_ = nullptr;
    QAction* identify_ = nullptr;
    QAction* assign_ = nullptr;
    bool autoConfirm_ = false;
    QString lastConfirmation_;
};

}  // namespace coscope::gui
