// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/od/ObjectDictionary.h"

#include <QString>

namespace coscope::gui {

// The drive's own units for the test move and its plot, from the dictionary's unit sidecar
// (resources/dictionaries/NAME.json "units", display = raw × factor): Delta ASDA-A2 60FFh and
// 606Ch are in 0.1 rpm, so the wizard asks for rpm and shows rpm, as the trace and the OD dock
// do. Without a dictionary or a unit for an object: the raw number in "units".
struct Ds402Units {
    od::Unit jogVelocity;          // 60FFh target velocity (profile velocity mode)
    od::Unit profileVelocity;      // 6081h profile velocity (profile position mode)
    od::Unit distance;             // 607Ah target position
    od::Unit position;             // 6064h position actual value
    od::Unit velocity;             // 606Ch velocity actual value
    od::Unit profileAcceleration;  // 6083h (6084h the same; Delta: ms from 0 to 3000 rpm)
    od::Unit homingSpeed;          // 6099h:01 and :02 (Delta: 0.1 rpm)
    od::Unit homingAcceleration;   // 609Ah
    od::Unit homeOffset;           // 607Ch

    static Ds402Units forDictionary(const QString& dictionaryName);
};

// "150 rpm" for raw 1500 in 0.1 rpm: the app's one number format (od::Value::format).
QString inUnit(double raw, const od::Unit& unit);
// A raw number's unit after an integer field: " inc/s", or " × 0.1 rpm" when one raw step is
// not one unit.
QString rawUnitSuffix(const od::Unit& unit);
// Decimals a display value needs to show one raw step (0.1 rpm: 1).
int unitDecimals(const od::Unit& unit);

}  // namespace coscope::gui
