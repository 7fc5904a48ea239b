// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Opens a menu of a window's menu bar by a click on its title and clicks one of its items, as a
// user does: titles are compared without '&', items by how their text starts.

#include <QAction>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QTest>

#include "tests/gui/WaitFor.h"

namespace coscope::testing {

inline QString withoutAccelerator(QString text) { return text.remove(QLatin1Char('&')); }

// Opens the menu `title` by a click on it in the menu bar; the menu, shown, or null.
inline QMenu* openMenu(QMainWindow& window, const QString& title) {
    QMenuBar* bar = window.menuBar();
    for (QAction* a : bar->actions())
        if (a->menu() && withoutAccelerator(a->text()) == title) {
            QTest::mouseClick(bar, Qt::LeftButton, {}, bar->actionGeometry(a).center());
            return waitFor([&] { return a->menu()->isVisible(); }) ? a->menu() : nullptr;
        }
    return nullptr;
}

// The item of `menu` whose text starts with `text`, or null.
inline QAction* menuItem(QMenu* menu, const QString& text) {
    for (QAction* a : menu->actions())
        if (!a->isSeparator() && withoutAccelerator(a->text()).startsWith(text)) return a;
    return nullptr;
}

// Opens `title` and clicks its item starting with `item`; false (the menu closed by Esc) when
// either is missing.
inline bool clickMenuItem(QMainWindow& window, const QString& title, const QString& item) {
    QMenu* menu = openMenu(window, title);
    if (!menu) return false;
    QAction* a = menuItem(menu, item);
    if (!a) {
        QTest::keyClick(menu, Qt::Key_Escape);
        return false;
    }
    QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(a).center());
    // A triggered item closes its menu. On a loaded machine the first click can land while the
    // menu is still settling and be lost (seen in CI); a user whose click did nothing clicks again.
    if (a->isEnabled() && !a->menu() && !waitFor([&] { return !menu->isVisible(); }, 2000) && menu->isVisible())
        QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(a).center());
    return true;
}

}  // namespace coscope::testing
