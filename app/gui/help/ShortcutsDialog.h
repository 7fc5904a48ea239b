// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

class QAction;
class QTreeWidget;

namespace coscope::gui::help {

// Help ▸ Keyboard shortcuts: every shortcut the window's actions have now (menus, toolbars,
// docks), read from the actions themselves, so the list is never out of date.
class ShortcutsDialog : public QDialog {
    Q_OBJECT
public:
    explicit ShortcutsDialog(QWidget* window);
    QTreeWidget* list() const { return list_; }

    struct Entry {
        QString keys;    // as the platform writes them: "Ctrl+Q"
        QString action;  // the action's text without '&'
        QString where;   // the menu or dock it belongs to
    };
    static QList<Entry> collect(const QWidget* window);

private:
    QTreeWidget* list_;
};

}  // namespace coscope::gui::help
