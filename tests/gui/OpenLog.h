// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Opens a log as a user does: File ▸ Open log…, its file dialog answered with `path`; waits
// until the log is read and shown.

#include "app/gui/MainWindow.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/LogLoadJob.h"

#include <QFileInfo>
#include <QTest>

#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/WaitFor.h"

namespace coscope::testing {

inline bool openLogByMenu(coscope::gui::MainWindow& w, const QString& path) {
    auto name = answerFileDialog(path);
    if (!clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Open log")) ||
        !waitFor([&] { return name->answered(); }))
        return false;
    // The window manager gives the focus back to the window when the dialog closes; offscreen
    // there is none, so do its part.
    w.activateWindow();
    if (!QTest::qWaitForWindowActive(&w)) return false;
    return waitFor([&] {
        return w.workspace()->loadJob() && w.workspace()->loadJob()->isDone() &&
               w.workspace()->sourceName() == QFileInfo(path).fileName();
    });
}

}  // namespace coscope::testing
