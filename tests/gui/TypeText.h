// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Types into a line edit as a user does: click it, select what is there (Ctrl+A), type, Enter.

#include <QLineEdit>
#include <QTest>

namespace coscope::testing {

inline void typeAndEnter(QLineEdit* edit, const QString& text) {
    QTest::mouseClick(edit, Qt::LeftButton);
    QTest::keyClick(edit, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(edit, text);
    QTest::keyClick(edit, Qt::Key_Return);
}

}  // namespace coscope::testing
