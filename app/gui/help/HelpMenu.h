// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

class QMainWindow;
class QMenu;

namespace coscope::gui::help {

// Adds the Help menu to `window`'s menu bar: CoScope guide (F1: the section of the dock or wizard
// page that has the focus, anywhere in the app), Keyboard shortcuts, About CoScope, About Qt.
QMenu* addHelpMenu(QMainWindow* window);

// What F1 does: the guide at the section for the widget with the focus.
void openGuideForFocus(QMainWindow* window);

}  // namespace coscope::gui::help
