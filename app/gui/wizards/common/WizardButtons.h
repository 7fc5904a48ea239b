// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

class QWizard;

namespace coscope::gui {

// Names a wizard's Back and Next buttons in our own words: Qt's zh_TW translation says 下一個
// ("next item"), where a Taiwanese wizard says 上一步 / 下一步 (issue 37 item 9).
void nameWizardButtons(QWizard* wizard);

}  // namespace coscope::gui
