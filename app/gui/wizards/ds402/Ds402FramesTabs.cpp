// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/ds402/Ds402FramesTabs.h"

#include "app/gui/wizards/common/ScriptPreview.h"
#include "app/gui/wizards/common/WizardFramesPane.h"

#include <QVBoxLayout>

namespace coscope::gui {

Ds402FramesTabs::Ds402FramesTabs(Workspace* workspace, QWidget* parent) : QTabWidget(parent) {
    frames_ = new WizardFramesPane(workspace, this);
    addTab(frames_, tr("Frames (requests and responses)"));
    auto* dry = new QWidget(this);
    auto* layout = new QVBoxLayout(dry);
    preview_ = new ScriptPreview(dry);
    layout->addWidget(preview_);
    addTab(dry, tr("Dry run (what will be sent)"));
    setMinimumHeight(150);
}

void Ds402FramesTabs::showDryRun(const canopen::CommandScript& script) {
    preview_->setScript(script);
    setCurrentIndex(1);
}

}  // namespace coscope::gui
