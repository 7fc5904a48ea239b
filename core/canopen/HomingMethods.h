// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstdint>
#include <vector>

namespace coscope::canopen::homing {

// What a homing method (6098h, CiA 402-2 §13) looks for. The virtual drives move by it, the
// controller, the CLI and the wizard list and check methods by it.
enum class Reference : uint8_t {
    None,             // 0: no homing method assigned
    CurrentPosition,  // 35 (and 37 in CiA 402-2): the current position is home, no movement
    LimitSwitch,      // 1, 2, 17, 18: the negative/positive limit switch
    HomeSwitch,       // 3-6, 19-22: a home switch active on one side of its edge
    HomeCam,          // 7-14, 23-30: a home switch with two edges; a limit switch reverses the search
    IndexPulse,       // 33, 34: the next index (Z) pulse
    HardStop,         // AIMOTOR 37, 38: the mechanical end stop, found by the torque limit
};

// One method as the drive's manual describes it, and how it moves (for the simulator).
struct Method {
    int8_t number = 0;
    QString description;  // English, the manual's meaning in short
    Reference reference = Reference::None;
    int8_t direction = 0;   // first move +1/-1; 0 = from the switch state (HomeSwitch) or none
    int8_t switchSide = 0;  // HomeSwitch: +1 active above its edge, -1 below; LimitSwitch: +1 positive
    int8_t edge = 0;        // HomeCam: 1 = lower edge, 2 = upper edge
    int8_t homeSide = 0;    // side of the edge where home lies (+1 above, -1 below); without the
                            // index pulse, the side the last slow approach comes from
    bool index = false;     // home is the index pulse next to the edge
    int8_t sameAs = 0;      // the manual says it behaves as this method (Delta 20 = 19, ...)
};

// What a drive does with a method it does not have.
enum class Refusal : uint8_t {
    SdoAbort,      // the write of 6098h is aborted (abortCode)
    AlarmAtStart,  // 6098h takes the value; starting homing raises the vendor alarm `alarm`
};

// The homing methods of one drive: the one table used by the virtual drive, the CiA 402
// controller, the CLI and the wizard.
struct DriveHoming {
    QString dictionary;  // bundled dictionary name: delta-asda-a2, aimotor, generic-cia402
    QString title;       // "Delta ASDA-A2", for messages
    std::vector<Method> methods;
    int8_t defaultMethod = 0;     // 6098h after power-on
    int lowest = 0, highest = 0;  // range of 6098h (dictionary limits); outside: value too low/high
    Refusal refusal = Refusal::SdoAbort;
    uint32_t abortCode = 0;                // SdoAbort: the abort code for a method in range the drive lacks
    QString alarm;                         // AlarmAtStart: vendor alarm name, e.g. "Er.668"
    bool changeOnlyWhileDisabled = false;  // 6098h is refused in Operation enabled
    int homeFoundBit = -1;                 // statusword bit set once home was found (AIMOTOR 15); -1 = none
    QString source;                        // manual section

    const Method* method(int number) const;
    bool supports(int number) const { return method(number) && number != 0; }
    // "1, 2, 4, 6, 17, 18, ..."
    QString numbers() const;
    // "method 35 (home on the current position, no movement)" or "method 3 (not supported by ...)"
    QString describe(int number) const;
};

// The table for a bundled dictionary; a drive without its own table gets CiA 402-2's.
const DriveHoming& drive(const QString& dictionary);
// CiA 402-2's own methods (the generic drive).
const DriveHoming& cia402();

}  // namespace coscope::canopen::homing
