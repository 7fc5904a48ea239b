// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/CommandScript.h"
#include "core/canopen/ScriptRunner.h"

#include <QPointer>
#include <QWidget>

#include <memory>

class QLabel;
class QPushButton;

namespace coscope::gui {

class Workspace;
class ScriptPreview;
class WizardGuard;

// The last page most wizards need, in one widget: the guard banner, the dry run (ScriptPreview,
// with "Save as script…"), Run and Stop buttons and a one-line status. Run asks first (when a
// confirmation text is set), then sends the script through a ScriptRunner on the workspace's
// master services, marking each row as it goes; it stops at the first failure and the status
// names the step and what the device answered. Stop cancels at once. Run is disabled while the
// bus cannot transmit (listen-only, closed) - the dry run stays usable. A change of source
// (reconnect, log opened) cancels a run in progress.
//
//   auto* panel = new ScriptRunPanel(workspace, this);
//   panel->setConfirmation(tr("The drive may move. Run these steps?"));
//   panel->setScript(planFromTheEarlierPages());
//   connect(panel, &ScriptRunPanel::finished, this, [](const canopen::ScriptRunResult& r) { ... });
class ScriptRunPanel : public QWidget {
    Q_OBJECT
public:
    explicit ScriptRunPanel(Workspace* workspace, QWidget* parent = nullptr);
    ~ScriptRunPanel() override;

    void setScript(const canopen::CommandScript& script);
    const canopen::CommandScript& script() const;
    // Asked in a Yes/No box before anything is sent; empty = no question (default).
    void setConfirmation(const QString& question) { confirmation_ = question; }

    // Starts the run without asking (the Run button asks first). False + *why when refused.
    bool run(QString* why = nullptr);
    void stop();
    bool isRunning() const;
    QString statusText() const;

    ScriptPreview* preview() const { return preview_; }
    WizardGuard* guard() const { return guard_; }

signals:
    void started();
    void finished(const coscope::canopen::ScriptRunResult& result);

private:
    void onRunClicked();
    void setStatus(const QString& text);
    void updateButtons();

    QPointer<Workspace> workspace_;
    WizardGuard* guard_ = nullptr;
    ScriptPreview* preview_ = nullptr;
    QPushButton* run_ = nullptr;
    QPushButton* stop_ = nullptr;
    QLabel* status_ = nullptr;
    QString confirmation_;
    QString stopReason_;  // why the running script was stopped (a lost bus), shown instead of "Stopped at step"
    std::unique_ptr<canopen::ScriptRunner> runner_;
};

}  // namespace coscope::gui
