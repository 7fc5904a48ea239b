// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/GuardedDrives.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <deque>

class QMessageBox;
class QWidget;

namespace coscope::gui {

class Workspace;

// The face of canopen::GuardedDrives: when CoScope enabled a drive, asks once per node and
// connection whether the drive may watch CoScope's heartbeat (1016h, 6007h) so that it stops by
// itself when CoScope or the cable dies, and says in the Events and the status bar what the
// guard did. The question is not modal: the wizard or panel that enabled the drive stays usable
// (Quick stop and Disable always at hand). "Remember my answer" keeps it in QSettings
// "master/heartbeatGuard" ("always" / "never"); the issue asks for it per project, and projects
// do not exist yet, so it is per user for now.
class HeartbeatGuardQuestion : public QObject {
    Q_OBJECT
public:
    static const QString kSettingsKey;

    HeartbeatGuardQuestion(Workspace* workspace, QWidget* window);
    ~HeartbeatGuardQuestion() override;

    // The window's refresh: binds to the open bus's guards (a new bus: the old question goes),
    // sets CoScope's heartbeat from the master settings, and polls them.
    void refresh();
    // The master settings changed: CoScope's heartbeat node-ID and period for the next guard.
    void applySettings();
    // The open question, if any (tests, the window).
    QMessageBox* question() const { return box_; }

signals:
    void message(const QString& text);
    void error(const QString& text);

private:
    void bind(canopen::GuardedDrives* guards);
    void consentNeeded(int node);
    void ask(int node);
    void answered(int node, bool yes, bool remember);
    void report(int node, int axis, canopen::GuardedDrives::State state, const QString& text);

    Workspace* workspace_;
    QWidget* window_;
    QPointer<canopen::GuardedDrives> guards_;
    QPointer<QMessageBox> box_;
    int asking_ = 0;           // the node the open question is about
    std::deque<int> waiting_;  // nodes to ask about next
};

}  // namespace coscope::gui
