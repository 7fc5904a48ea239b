// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/wizards/ owns the Commission menu's wizards, one folder each (pdo/, ds402/,
// nodeid/), and their shared parts (common/: frames pane, script preview and run panel, guard).
#pragma once

#include <QString>
#include <QStringList>

#include <functional>
#include <vector>

class QMenu;
class QWidget;

namespace coscope::gui {

class Workspace;

// The commissioning wizards, listed once: the Commission menu and `--view wizard-ID`
// (screenshots) both come from this table.
struct WizardEntry {
    QString id;                 // "pdo", "nodeid", "ds402": `--view wizard-pdo`
    const char* title;          // menu text, English source (QT_TRANSLATE_NOOP "WizardMenu"); see titleText()
    QString titleText() const;  // the title in the UI language
    // Creates the wizard window (top-level, not shown); `node` preselects a node (-1 = none).
    std::function<QWidget*(Workspace* workspace, int node, QWidget* parent)> create;
    // The node the wizard window is on (0 or -1: none), remembered when it closes.
    std::function<int(QWidget* wizard)> nodeOf = {};
    // Pages a view may open the wizard on (`--view wizard-ds402-homing`); the window shows one by
    // its Q_INVOKABLE showPage(QString).
    QStringList pages = {};
};

const std::vector<WizardEntry>& wizardEntries();

// Fills `menu` with one action per wizard; each opens its wizard (non-modal) for the node
// `currentNode()` returns (the Nodes dock's selection), or on the node the wizard was last
// closed on while that selection is the one it was opened with (QSettings, issue 35).
void fillCommissionMenu(QMenu* menu, Workspace* workspace, QWidget* parent, std::function<int()> currentNode);

// The node the wizard `id` opens on when `selected` is chosen in the Nodes dock (see above).
int wizardStartNode(const QString& id, Workspace* workspace, int selected);

// Creates and shows the wizard `id` ("ds402", or "ds402-homing" for one of its pages); nullptr
// when there is no such wizard. The node it is closed on is remembered for wizardStartNode().
QWidget* openWizard(const QString& id, Workspace* workspace, int node, QWidget* parent);

}  // namespace coscope::gui
