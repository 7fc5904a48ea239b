// SPDX-License-Identifier: GPL-3.0-or-later
// View ▸ Language and the switch itself: the window builds its menus, status bar and docks again
// in the new language over the unchanged Workspace. Rebuilding (rather than each widget
// retranslating itself) leaves no text of the old language anywhere, whoever wrote the widget.
#include "app/gui/MainWindow.h"

#include "app/gui/JournalOffer.h"

#include "app/gui/console/ConsoleDock.h"
#include "app/gui/events/EventsDock.h"
#include "app/gui/health/HealthDock.h"
#include "app/gui/language/Language.h"
#include "app/gui/master/ProcessDataDock.h"
#include "app/gui/master/TransmitDock.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/od/ObjectDictionaryDock.h"
#include "app/gui/plot/PlotDock.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/status/BusStatusBar.h"
#include "app/gui/trace/TraceDock.h"

#include <QActionGroup>
#include <QApplication>
#include <QMenu>
#include <QMenuBar>
#include <QStatusBar>

namespace coscope::gui {

namespace {
// Another window of ours is open (a wizard, a dialog): it was built in the old language and
// holds the user's work, so the language waits until it is closed.
bool otherWindowOpen(const QWidget* main) {
    for (QWidget* w : QApplication::topLevelWidgets())
        if (w != main && w->isVisible() && !qobject_cast<QMenu*>(w) && w->isWindow() &&
            w->windowType() != Qt::ToolTip && w->windowType() != Qt::Popup)
            return true;
    return false;
}
}  // namespace

void MainWindow::addLanguageMenu(QMenu* view) {
    QMenu* menu = view->addMenu(tr("&Language"));
    menu->setObjectName(QStringLiteral("languageMenu"));
    auto* group = new QActionGroup(menu);
    // The entry of the language in use is checked: the saved choice, unless `--lang` or a failed
    // load put another language in use (issue 37 item 9).
    const QString saved = language::saved();
    const QString chosen = language::resolve(saved) == language::current() ? saved : language::current();
    auto add = [&](const QString& code, const QString& text) {
        QAction* a = menu->addAction(text);
        a->setObjectName(QStringLiteral("language-") + (code.isEmpty() ? QStringLiteral("system") : code));
        a->setCheckable(true);
        a->setChecked(code == chosen);
        group->addAction(a);
        connect(a, &QAction::triggered, this, [this, code] { setLanguage(code, true); });
    };
    //: View ▸ Language: follow the operating system's language; %1 = that language's own name
    add(QString(), tr("System language (%1)").arg(language::nativeName(language::resolve(QString()))));
    menu->addSeparator();
    for (const QString& code : language::available()) add(code, language::nativeName(code));
    QAction* note = menu->addSection(tr("Close the other windows (wizards, dialogs) to change the language"));
    connect(menu, &QMenu::aboutToShow, menu, [this, group, note] {
        const bool blocked = otherWindowOpen(this);
        for (QAction* a : group->actions()) a->setEnabled(!blocked);
        note->setVisible(blocked);
    });
}

void MainWindow::setLanguage(const QString& code, bool remember) {
    if (remember) language::save(code);
    const QString before = language::current();
    language::apply(code);
    if (language::current() != before) rebuildInLanguage();
}

void MainWindow::rebuildInLanguage() {
    const QByteArray layout = saveState();
    // The node the OD dock shows (the Nodes dock's selection is not rebuilt: a second switch
    // would find none).
    const int node = od_->node() > 0 ? od_->node() : nodes_->selectedNode();
    // Menus first: they hold the docks' actions (View, Bus ▸ Scan).
    setMenuBar(new QMenuBar(this));
    for (QDockWidget* d : std::initializer_list<QDockWidget*>{trace_, nodes_, od_, plot_, events_, health_, console_,
                                                              transmit_, processData_}) {
        removeDockWidget(d);
        delete d;
    }
    setStatusBar(new QStatusBar(this));
    createDocks();
    status_ = new BusStatusBar(statusBar(), workspace_);
    buildMenus();
    journalOffer_->retranslate();
    restoreState(layout);
    if (node >= 0) od_->setNode(node);
    refresh();
}

}  // namespace coscope::gui
