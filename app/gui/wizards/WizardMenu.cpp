// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/WizardMenu.h"

#include "app/gui/wizards/ds402/Ds402Wizard.h"
#include "app/gui/wizards/nodeid/NodeIdWizard.h"
#include "app/gui/wizards/pdo/PdoWizard.h"

#include <QAction>
#include <QCoreApplication>
#include <QMenu>
#include <QMetaObject>
#include <QWidget>

namespace coscope::gui {

const std::vector<WizardEntry>& wizardEntries() {
    // One line per wizard.
    static const std::vector<WizardEntry> entries = {
        {QStringLiteral("nodeid"), QT_TRANSLATE_NOOP("WizardMenu", "Baud rate and node-ID…"), [](Workspace* ws, int node, QWidget* parent) -> QWidget* { return new NodeIdWizard(ws, node, parent); }},
        {QStringLiteral("ds402"), QT_TRANSLATE_NOOP("WizardMenu", "CiA 402 enable step-through…"), [](Workspace* w, int node, QWidget* parent) -> QWidget* { return new Ds402Wizard(w, node, parent); },
         {QStringLiteral("homing"), QStringLiteral("position")}},
        {QStringLiteral("pdo"), QT_TRANSLATE_NOOP("WizardMenu", "PDO mapping…"), [](Workspace* ws, int node, QWidget* parent) -> QWidget* { return new PdoWizard(ws, node, parent); }},
    };
    return entries;
}

QString WizardEntry::titleText() const { return QCoreApplication::translate("WizardMenu", title); }

QWidget* openWizard(const QString& id, Workspace* workspace, int node, QWidget* parent) {
    for (const WizardEntry& e : wizardEntries()) {
        const QString page = id.startsWith(e.id + u'-') ? id.mid(e.id.size() + 1) : QString();
        if (e.id != id && !e.pages.contains(page)) continue;
        QWidget* w = e.create(workspace, node, parent);
        if (!w) return nullptr;
        if (!page.isEmpty()) QMetaObject::invokeMethod(w, "showPage", Q_ARG(QString, page));
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
        menu->addAction(e.titleText(), parent, [=] { openWizard(id, workspace, currentNode ? currentNode() : -1, parent); });
    }
}

}  // namespace coscope::gui
