// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Chooses an entry of a combo box as a user does: a click opens its list, a click on the entry.

#include <QAbstractItemView>
#include <QApplication>
#include <QComboBox>
#include <QTest>

#include "tests/gui/WaitFor.h"

namespace coscope::testing {

inline bool pickInCombo(QComboBox* combo, const QString& text) {
    const int at = combo->findText(text);
    if (at < 0) return false;
    QTest::mouseClick(combo, Qt::LeftButton);
    QAbstractItemView* list = combo->view();
    if (!waitFor([&] { return list->isVisible(); }, 3000)) return false;
    // The open list ignores a click within a double-click's time of opening (QComboBox takes it
    // for the second half of the click that opened it); a user's hand is slower.
    QTest::qWait(QApplication::doubleClickInterval() + 50);
    const QModelIndex item = list->model()->index(at, combo->modelColumn(), combo->rootModelIndex());
    list->scrollTo(item);
    QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, list->visualRect(item).center());
    return waitFor([&] { return !list->isVisible() && combo->currentIndex() == at; }, 3000);
}

}  // namespace coscope::testing
