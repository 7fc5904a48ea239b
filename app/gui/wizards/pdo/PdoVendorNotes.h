// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/PdoMapping.h"

#include <QString>
#include <QStringList>

#include <cstdint>

namespace coscope::gui {

// What a technician should know about PDOs on a given drive, from the bundled dictionaries'
// manuals (shared/seeds/extract-*.md). Keyed by the dictionary name ("delta-asda-a2", ...).
QStringList pdoVendorNotes(const QString& dictionaryName, const canopen::PdoId& pdo);

// Plain-words advice for a failed PDO write: what the device's answer means and what to check.
// `abortCode` 0 = no abort (no answer, or the read-back differed).
QString pdoFailureAdvice(uint32_t abortCode, bool timedOut, const QString& dictionaryName);

// Plain explanation of a transmission type (CiA 301 §7.5.2.35 / 7.2.2.2), for TPDO or RPDO.
QString transmissionTypeText(uint8_t type, bool transmit);

}  // namespace coscope::gui
