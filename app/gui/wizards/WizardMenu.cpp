// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/WizardMenu.h"

#include <QAction>
#include <QMenu>
#include <QWidget>

namespace coscope::gui {

const std::vector<WizardEntry>& wizardEntries() {
    // One line per wizard.
    static const std::vector<WizardEntry> entries = {
    };
    return entries;
}

QWidget* openWizard(const QString& id, Workspace* workspace, int node, QWidget* parent) {
    for (const WizardEntry& e : wizardEntries()) {
        if (e.id != id) continue;
        QWidget* w = e.create(workspace, node, parent);
        if (!w) return nullptr;
        w->setAttribute(Qt::WA_DeleteOnClose);
        w->show();
        w->raise();
        return w;
    }
    return nullptr;
}

void fillCommissionMenu(QMenu* menu, Workspace* workspace, QWidget* parent, std::function<int()> currentNode) {
    for (const WizardEntry& e : wizardEntries()) {
        const QString id = e.id;
        menu->addAction(e.title, parent, [=] { openWizard(id, workspace, currentNode ? currentNode() : -1, parent); });
    }
}

}  // namespace coscope::gui
