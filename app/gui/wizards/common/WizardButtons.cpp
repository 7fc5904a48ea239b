// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/common/WizardButtons.h"

#include <QCoreApplication>
#include <QWizard>

namespace coscope::gui {

void nameWizardButtons(QWizard* wizard) {
    //: A wizard's button to the previous step
    wizard->setButtonText(QWizard::BackButton, QCoreApplication::translate("WizardButtons", "< &Back"));
    //: A wizard's button to the next step
    wizard->setButtonText(QWizard::NextButton, QCoreApplication::translate("WizardButtons", "&Next >"));
}

}  // namespace coscope::gui
