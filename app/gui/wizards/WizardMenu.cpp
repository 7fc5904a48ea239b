// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/WizardMenu.h"

#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/ds402/Ds402Wizard.h"
#include "app/gui/wizards/nodeid/NodeIdWizard.h"
#include "app/gui/wizards/pdo/PdoWizard.h"

#include <QAction>
#include <QCoreApplication>
#include <QEvent>
#include <QMenu>
#include <QMetaObject>
#include <QSettings>
#include <QWidget>

namespace coscope::gui {

const std::vector<WizardEntry>& wizardEntries() {
    // One line per wizard.
    static const std::vector<WizardEntry> entries = {
        {QStringLiteral("nodeid"), QT_TRANSLATE_NOOP("WizardMenu", "Baud rate and node-ID…"),
         [](Workspace* ws, int node, QWidget* parent) -> QWidget* { return new NodeIdWizard(ws, node, parent); },
         [](QWidget* w) {
             auto* x = qobject_cast<NodeIdWizard*>(w);
             return x ? x->node() : -1;
         }},
        {QStringLiteral("ds402"),
         QT_TRANSLATE_NOOP("WizardMenu", "CiA 402 enable step-through…"),
         [](Workspace* w, int node, QWidget* parent) -> QWidget* { return new Ds402Wizard(w, node, parent); },
         [](QWidget* w) {
             auto* x = qobject_cast<Ds402Wizard*>(w);
             return x ? x->node() : -1;
         },
         {QStringLiteral("homing"), QStringLiteral("position")}},
        {QStringLiteral("pdo"), QT_TRANSLATE_NOOP("WizardMenu", "PDO mapping…"),
         [](Workspace* ws, int node, QWidget* parent) -> QWidget* { return new PdoWizard(ws, node, parent); },
         [](QWidget* w) {
             auto* x = qobject_cast<PdoWizard*>(w);
             return x ? x->state().node : -1;
         }},
    };
    return entries;
}

QString WizardEntry::titleText() const { return QCoreApplication::translate("WizardMenu", title); }

namespace {
// QSettings keys: the node a wizard was closed on, and the Nodes dock's selection it was opened with.
QString lastNodeKey(const QString& id) { return QStringLiteral("wizards/%1/lastNode").arg(id); }
QString openedWithKey(const QString& id) { return QStringLiteral("wizards/%1/openedWith").arg(id); }
// Remembers the node a wizard window is on when it is hidden (closed, whichever way).
class RememberNode : public QObject {
public:
    RememberNode(QString id, std::function<int(QWidget*)> nodeOf, QWidget* wizard)
        : QObject(wizard), id_(std::move(id)), nodeOf_(std::move(nodeOf)), wizard_(wizard) {}
    bool eventFilter(QObject* watched, QEvent* event) override {
        // Hidden while being destroyed, the window is no longer a wizard (nodeOf gives -1): the
        // Hide of close() came first and was kept.
        if (watched == wizard_ && event->type() == QEvent::Hide)
            if (const int node = nodeOf_(wizard_); node >= 0) QSettings().setValue(lastNodeKey(id_), node);
        return false;
    }

private:
    QString id_;
    std::function<int(QWidget*)> nodeOf_;
    QWidget* wizard_;
};
}  // namespace

int wizardStartNode(const QString& id, Workspace* workspace, int selected) {
    QSettings s;
    const int last = s.value(lastNodeKey(id), -1).toInt();
    const bool sameChoice = s.value(openedWithKey(id), -1).toInt() == selected;
    // A node the table knows now (1..127; not the unconfigured device of an LSS Fastscan).
    if (sameChoice && last >= 1 && last <= 127 && workspace && workspace->nodes().node(last)) return last;
    return selected;
}

QWidget* openWizard(const QString& id, Workspace* workspace, int node, QWidget* parent) {
    for (const WizardEntry& e : wizardEntries()) {
        const QString page = id.startsWith(e.id + u'-') ? id.mid(e.id.size() + 1) : QString();
        if (e.id != id && !e.pages.contains(page)) continue;
        QWidget* w = e.create(workspace, node, parent);
        if (!w) return nullptr;
        if (e.nodeOf) w->installEventFilter(new RememberNode(e.id, e.nodeOf, w));
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
        menu->addAction(e.titleText(), parent, [=] {
            const int selected = currentNode ? currentNode() : -1;
            const int start = wizardStartNode(id, workspace, selected);
            QSettings().setValue(openedWithKey(id), selected);
            openWizard(id, workspace, start, parent);
        });
    }
}

}  // namespace coscope::gui
