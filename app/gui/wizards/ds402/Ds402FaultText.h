// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstdint>

namespace coscope::gui {

// A drive fault in words: the CiA error code from 603Fh with its CiA 301/402 meaning, and the
// vendor alarm (bundled table resources/alarms/NAME.json, the same one the EMCY decoder uses)
// found through the newest pre-defined error field 1003h:01, whose high word is the vendor's
// alarm number for Delta ("AL011") and AIMOTOR ("Er.201").
struct Ds402Fault {
    uint16_t errorCode = 0;  // 603Fh
    QString ciaText;         // "Current, device output side (2310h)"
    QString vendorAlarm;     // "AL011 Encoder error", empty when unknown
    QString text() const;    // one line for the wizard
};

// `history1003` 0 = not read. `dictionary` is the node's bundled dictionary name (may be empty).
Ds402Fault describeDs402Fault(const QString& dictionary, uint16_t errorCode, uint32_t history1003);

}  // namespace coscope::gui
