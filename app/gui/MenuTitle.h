// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QAction>
#include <QMenu>

namespace coscope::gui {

// A context menu's title line ("1017:00 Producer heartbeat time"). QMenu::addSection() sizes the
// menu without the section's text, so Fusion elides a long title; a disabled bold item is sized
// by its text like every other item.
inline QAction* addMenuTitle(QMenu& menu, const QString& text) {
    QAction* title = menu.addAction(text);
    QFont bold = title->font();
    bold.setBold(true);
    title->setFont(bold);
    title->setEnabled(false);
    title->setObjectName(QStringLiteral("menuTitle"));
    menu.addSeparator();
    return title;
}

}  // namespace coscope::gui
