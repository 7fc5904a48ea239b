// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/PdoMapping.h"
#include "core/od/ObjectDictionary.h"

#include <QString>

#include <memory>

namespace coscope::gui {

// What the PDO wizard's pages share (no widgets): the target, the device's current
// configuration as read, and the configuration being edited.
struct PdoWizardState {
    int node = -1;
    canopen::PdoId pdo{true, 1};
    QString dictionaryName;  // as matched or assigned in the node table ("" = none)
    std::shared_ptr<const od::ObjectDictionary> dictionary;
    bool haveCurrent = false;     // `current` was read from the device (or taken from the dictionary)
    bool fromDictionary = false;  // listen-only dry run: `current` = the dictionary's defaults
    canopen::PdoConfig current;   // as read
    canopen::PdoConfig wanted;    // as edited (starts as a copy of `current`)

    // "6041h:00 Statusword" (the dictionary's name when known).
    QString objectName(uint16_t index, uint8_t sub) const;
};

}  // namespace coscope::gui
