// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

namespace coscope::gui {

class MainWindow;

// --screenshot: waits until `view` has content (trace rows flowing, nodes found, events
// logged, a log fully loaded), lets it settle, renders the window to `file` (PNG) and exits
// the application (0 written, 1 not). Gives up waiting after 20 s and shoots what there is.
void takeScreenshotWhenReady(MainWindow* window, const QString& file, const QString& view);

// True when `view` shows enough to be worth a picture.
bool viewHasContent(MainWindow* window, const QString& view);

}  // namespace coscope::gui
