// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Trace dock's Group SDO button as a user sees it in the dock's toolbar.

#include "app/gui/MainWindow.h"
#include "app/gui/trace/TraceDock.h"

#include <QToolBar>

namespace coscope::testing {

inline QWidget* groupSdoButton(coscope::gui::MainWindow& w) {
    for (auto* bar : w.traceDock()->findChildren<QToolBar*>())
        if (QWidget* b = bar->widgetForAction(w.traceDock()->groupSdoAction())) return b;
    return nullptr;
}

}  // namespace coscope::testing
