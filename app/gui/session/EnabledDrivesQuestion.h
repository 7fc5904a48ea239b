// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QString>

class QWidget;

namespace coscope::gui {

class Workspace;

// DESIGN.md "Reliability and safety": before a user action closes the bus while drives CoScope
// enabled are on it (canopen::EnabledDrives), the user is asked "Node 3 is enabled by CoScope:
// disable it and quit?" (Disable and quit / Cancel). True: go on — the workspace then sends
// Disable voltage and sees it go out before the bus closes. False (Cancel, Esc): nothing was
// sent and nothing changes. Nothing enabled: true without a question. `quiet` (tests,
// --screenshot): logs it and goes on.
class EnabledDrivesQuestion {
    Q_DECLARE_TR_FUNCTIONS(EnabledDrivesQuestion)
public:
    enum class Closing { Quit, Disconnect, Connect, OpenLog };
    static bool confirm(QWidget* parent, Workspace* workspace, Closing closing, bool quiet);
    // What the question says for these drives (for the box and the tests).
    static QString text(const QString& nodes, int count, Closing closing);
};

}  // namespace coscope::gui
