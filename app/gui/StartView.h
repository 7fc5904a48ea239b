// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

namespace coscope::gui {

class MainWindow;

// `coscope --view VIEW`: raises the dock VIEW at once; a commissioning wizard ("wizard-ID")
// opens as its own window once the nodes are known (so it can preselect one), at once when
// there is no live bus, and after 10 s without nodes anyway.
void showStartView(MainWindow* window, const QString& view);

}  // namespace coscope::gui
