// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstdint>
#include <optional>

namespace coscope::gui {

// What a technician must know about a vendor's drive before stepping it through the CiA 402
// state machine (facts from shared/seeds/extract-*.md), keyed by the bundled dictionary name.
struct Ds402VendorNotes {
    QString vendor;  // "Delta ASDA-A2"
    QString before;  // pre-conditions in plain words
    // The control-mode parameter that must hold `controlValue` for the CiA 402 objects to act.
    uint16_t controlIndex = 0;
    uint8_t controlSub = 0;
    int64_t controlValue = 0;
    QString controlName;                  // "P1-01"
    bool resetWhileEnabledAlarm = false;  // Delta: NMT Reset Node while servo on raises AL401
    bool notCia402 = false;               // DEXMART DEV: vendor objects, no 6040h/6041h
};

std::optional<Ds402VendorNotes> ds402VendorNotes(const QString& dictionary);

}  // namespace coscope::gui
