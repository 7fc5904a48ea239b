// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace coscope::gui {

class MainWindow;

// For `coscope --connect sim:// --view project-compare --screenshot FILE`: once the virtual drives
// answer, backs the machine up into a new project, changes two values of node 1 and puts another
// drive of the same type (another serial number) at node 3, then opens the comparison.
void startProjectCompareDemo(MainWindow* window);

}  // namespace coscope::gui
