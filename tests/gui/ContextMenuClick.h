// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Right-clicks a point of an item view's viewport and clicks the context menu's item `text` once
// the menu shows (Escape when it has none), as a user does.

#include <QAbstractItemView>
#include <QApplication>
#include <QContextMenuEvent>
#include <QMenu>
#include <QTest>
#include <QTimer>

namespace coscope::testing {

inline bool contextMenuClick(QAbstractItemView* view, QPoint pos, const QString& text) {
    bool clicked = false;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, [&] {
        auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
        if (!menu) return;
        poll.stop();
        for (QAction* a : menu->actions())
            if (a->text() == text && a->isEnabled()) {
                clicked = true;
                QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(a).center());
                return;
            }
        QTest::keyClick(menu, Qt::Key_Escape);
    });
    poll.start(20);
    QContextMenuEvent click(QContextMenuEvent::Mouse, pos, view->viewport()->mapToGlobal(pos));
    QCoreApplication::sendEvent(view->viewport(), &click);
    return clicked;
}

}  // namespace coscope::testing
