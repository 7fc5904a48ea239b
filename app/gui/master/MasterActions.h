// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QString>

class QAction;
class QWidget;

namespace coscope::gui {

class HeartbeatGuardQuestion;
class Workspace;

// The Bus menu's and the toolbar's master actions: SYNC on/off (checkable; the SYNC producer of
// the open bus with the MasterSettings), Master settings… and CoScope's heartbeat, which runs
// while the bus is open when the settings ask for it. Disabled, with the reason as tooltip,
// without an open bus and on a listen-only bus (README "Listen-only"). The status bar shows
// statusText(). Every send goes through core (SyncProducer, HeartbeatProducer: `coscope-cli sync`).
class MasterActions : public QObject {
    Q_OBJECT
public:
    MasterActions(Workspace* workspace, QWidget* window);

    QAction* syncAction() const { return sync_; }
    QAction* settingsAction() const { return settings_; }
    // Asks whether a drive CoScope enabled may watch CoScope's heartbeat (GuardedDrives).
    HeartbeatGuardQuestion* guardQuestion() const { return guardQuestion_; }

    // The window's refresh tick (≤ 30 Hz): enabled and checked states, the heartbeat started
    // once the bus can transmit.
    void refresh();
    // "SYNC 10 ms (1,234)" while SYNC runs, "Heartbeat 100 ms" while CoScope's heartbeat runs,
    // "guarding node 3" while node 3 watches it (GuardedDrives).
    QString statusText() const;

    // What the SYNC action does; false with *error when it cannot start.
    bool startSync(QString* error);
    void stopSync();

signals:
    void message(const QString& text);
    void error(const QString& text);

private:
    void showSettings();
    void applyHeartbeat();
    void writeCyclePeriod(uint32_t periodUs);

    Workspace* workspace_;
    QWidget* window_;
    QAction* sync_ = nullptr;
    QAction* settings_ = nullptr;
    HeartbeatGuardQuestion* guardQuestion_ = nullptr;
    bool heartbeatHeld_ = false;          // new heartbeat settings wait until no drive watches it
    const void* heartbeatFor_ = nullptr;  // the bus whose heartbeat was set up
};

}  // namespace coscope::gui
