// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstddef>

class QWidget;

namespace coscope::gui {

// A log that could not be opened at all: a message box (modal: the user just chose the file)
// naming the file and where it failed (`error`, possibly several lines), and saying that what
// was shown is kept.
void showOpenFailed(QWidget* parent, const QString& path, const QString& error);

// A log whose reading stopped part-way (a corrupt record): a box that does not block the window,
// saying how many frames before the error are shown.
void showReadFailed(QWidget* parent, const QString& path, const QString& error, size_t framesShown);

}  // namespace coscope::gui
