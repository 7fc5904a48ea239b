// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/ds402/Ds402VendorNotes.h"

#include <QCoreApplication>

namespace coscope::gui {

std::optional<Ds402VendorNotes> ds402VendorNotes(const QString& dictionary) {
    Ds402VendorNotes n;
    if (dictionary == u"delta-asda-a2") {
        // extract-delta §1, §4: P1-01 = 0Ch selects standard CANopen (CiA 402) control;
        // an NMT Reset Node while the servo is on raises AL401.
        n.vendor = QStringLiteral("Delta ASDA-A2");
        n.before = QCoreApplication::translate(
            "Ds402VendorNotes",
            "P1-01 must be 0x0C (standard CANopen mode) or the drive ignores the controlword. "
            "Do not send NMT Reset Node while the servo is on: the drive raises AL401.");
        n.controlIndex = 0x2101;
        n.controlValue = 0x0C;
        n.controlName = QStringLiteral("P1-01");
        n.resetWhileEnabledAlarm = true;
        return n;
    }
    if (dictionary == u"aimotor") {
        // extract-aimotor §4: H02-00 = 8 selects CANopen control.
        n.vendor = QStringLiteral("AIMOTOR");
        n.before = QCoreApplication::translate(
            "Ds402VendorNotes", "H02-00 must be 8 (CANopen control) or the drive ignores the controlword.");
        n.controlIndex = 0x2002;
        n.controlSub = 0x01;
        n.controlValue = 8;
        n.controlName = QStringLiteral("H02-00");
        return n;
    }
    if (dictionary == u"dexmart-dev") {
        // extract-dexmart §6-7: commanded through the Multi-Drive objects, no CiA 402 profile.
        n.vendor = QStringLiteral("DEXMART DEV");
        n.before = QCoreApplication::translate(
            "Ds402VendorNotes",
            "The DEXMART DEV has no CiA 402 state machine: its two motors are run through the Multi-Drive "
            "objects (3051h/3052h). Use the Object dictionary dock for it.");
        n.notCia402 = true;
        return n;
    }
    return std::nullopt;
}

}  // namespace coscope::gui
