// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

class QWidget;

namespace coscope::gui::help {

// Help ▸ About CoScope: version, source revision and the licenses of CoScope and of the libraries
// in it. The text alone for tests and the box that shows it.
QString aboutText();
void showAbout(QWidget* parent);

}  // namespace coscope::gui::help
