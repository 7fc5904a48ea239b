// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/CommandScript.h"

#include <QTabWidget>

namespace coscope::gui {

class Workspace;
class WizardFramesPane;
class ScriptPreview;

// The lower pane of the CiA 402 wizard: the frames the wizard sent and received (requests and
// responses of its drive), and the dry run, the exact enable sequence as a script to save.
class Ds402FramesTabs : public QTabWidget {
    Q_OBJECT
public:
    explicit Ds402FramesTabs(Workspace* workspace, QWidget* parent = nullptr);

    WizardFramesPane* frames() const { return frames_; }
    ScriptPreview* preview() const { return preview_; }
    // Shows `script` on the dry-run tab.
    void showDryRun(const canopen::CommandScript& script);

private:
    WizardFramesPane* frames_ = nullptr;
    ScriptPreview* preview_ = nullptr;
};

}  // namespace coscope::gui
