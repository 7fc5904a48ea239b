// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/help/HelpMenu.h"

#include "app/gui/help/AboutBox.h"
#include "app/gui/help/HelpSections.h"
#include "app/gui/help/HelpWindow.h"
#include "app/gui/help/ShortcutsDialog.h"

#include <QApplication>
#include <QCoreApplication>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>

namespace coscope::gui::help {

namespace {
struct HelpMenu {
    Q_DECLARE_TR_FUNCTIONS(HelpMenu)
};
}  // namespace

void openGuideForFocus(QMainWindow* window) {
    // Where the key went: the focus of the active window (a wizard is a window of its own), or
    // that window when nothing in it has the focus.
    const QWidget* where = QApplication::activeWindow();
    if (where && where->focusWidget()) where = where->focusWidget();
    if (!where) where = QApplication::focusWidget();
    HelpWindow::open(window, where && where != HelpWindow::of(window) ? sectionFor(where) : QString());
}

QMenu* addHelpMenu(QMainWindow* window) {
    QMenu* menu = window->menuBar()->addMenu(HelpMenu::tr("&Help"));
    menu->setObjectName(QStringLiteral("helpMenu"));
    QAction* guide = menu->addAction(HelpMenu::tr("CoScope &guide"), window, [window] { openGuideForFocus(window); });
    guide->setObjectName(QStringLiteral("helpGuide"));
    guide->setShortcut(QKeySequence(Qt::Key_F1));
    // F1 in every window of the app (wizards are windows of their own), not only the main one.
    guide->setShortcutContext(Qt::ApplicationShortcut);
    menu->addAction(HelpMenu::tr("&Keyboard shortcuts"), window, [window] {
        auto* dialog = new ShortcutsDialog(window);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->open();
    });
    menu->addSeparator();
    menu->addAction(HelpMenu::tr("&About CoScope"), window, [window] { showAbout(window); });
    menu->addAction(HelpMenu::tr("About &Qt"), window, [window] { QMessageBox::aboutQt(window); });
    return menu;
}

}  // namespace coscope::gui::help
