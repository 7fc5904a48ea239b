// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/help/ owns the Help menu: the technician's guide (docs/guide/LANG.md, compiled
// in) in a help window, F1 on a dock or wizard page opening its section, the keyboard shortcuts
// read from the window's actions, and About.
#pragma once

#include <QString>

class QWidget;

namespace coscope::gui::help {

// The guide's section for the part of the window `w` is in: the first of `w` and its parents
// with a "helpSection" property, a dock known by its objectName, or a wizard (its page) known
// by its class; empty (the guide's start) when none is.
QString sectionFor(const QWidget* w);

}  // namespace coscope::gui::help
