// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/wizards/common/ owns what every wizard shows and does alike: the frames pane, the
// script preview (dry run, save), the script run panel and the guard that refuses to send when it
// must not.
#pragma once

#include <QList>
#include <QPointer>
#include <QWidget>

class QLabel;

namespace coscope::gui {

class Workspace;

// "May this wizard send?" in one place, as a banner every wizard puts at its top.
// Sending needs an open bus that is not listen-only (Workspace::canTransmit(); the bus itself
// refuses in listen-only mode - this only explains it early). While sending is impossible the
// banner shows why in plain words and every widget given to addSender() is disabled; it follows
// the workspace's source and bus state changes. The dry run and "Save as script…" stay usable.
//
//   auto* guard = new WizardGuard(workspace, this);
//   layout->addWidget(guard);
//   guard->addSender(applyButton);
//   if (!guard->canSend()) ... guard->reason()
class WizardGuard : public QWidget {
    Q_OBJECT
public:
    explicit WizardGuard(Workspace* workspace, QWidget* parent = nullptr);

    bool canSend() const;
    // Why nothing can be sent ("" when sending is possible).
    QString reason() const;
    // `widget` is enabled only while sending is possible (kept in step from now on).
    void addSender(QWidget* widget);

    // Re-reads the workspace's state (called on its signals; public for tests and callers that
    // change the bus themselves).
    void refresh();

signals:
    void canSendChanged(bool canSend);

private:
    QPointer<Workspace> workspace_;
    QLabel* text_ = nullptr;
    QList<QPointer<QWidget>> senders_;
    int last_ = -1;  // -1 unknown, 0 cannot send, 1 can send
};

}  // namespace coscope::gui
