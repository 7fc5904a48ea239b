// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/pdo/PdoWizardState.h"

#include "dissectors/ObjectNames.h"
#include "dissectors/VendorTable.h"

namespace coscope::gui {

QString PdoWizardState::objectName(uint16_t index, uint8_t sub) const {
    QString ref = QStringLiteral("%1h:%2")
                      .arg(index, 4, 16, QChar(u'0'))
                      .arg(sub, 2, 16, QChar(u'0'))
                      .toUpper()
                      .replace(QStringLiteral("H:"), QStringLiteral("h:"));
    if (index >= 1 && index <= 7) return ref + QStringLiteral(" (gap: dummy)");
    if (dictionary && dictionary->entry(index, sub))
        return ref + QLatin1Char(' ') +
               dissect::localDisplayName(*dictionary, index, sub, dissect::vendorTextLanguage());
    return ref;
}

}  // namespace coscope::gui
