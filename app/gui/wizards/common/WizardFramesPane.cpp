// SPDX-License-Identifier: GPL-3.0-or-later
// Placeholder: being implemented.
#include "app/gui/wizards/common/WizardFramesPane.h"

namespace coscope::gui {

WizardFramesPane::WizardFramesPane(Workspace*, QWidget* parent) : QWidget(parent) {}
void WizardFramesPane::setNode(int) {}
void WizardFramesPane::markStart() {}
int WizardFramesPane::rowCount() const { return 0; }
QString WizardFramesPane::rowText(int) const { return {}; }

}  // namespace coscope::gui
