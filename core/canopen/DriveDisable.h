// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/EnabledDrives.h"

#include <QString>

#include <vector>

namespace coscope::canopen {

class MasterContext;

// What disableEnabledDrives() did, per drive.
struct DriveDisableOutcome {
    struct Drive {
        EnabledDrives::Drive drive;
        bool quickStopSent = false;  // it may have been moving: Quick stop went first
        bool seen = false;           // the Disable voltage request's own Tx copy came back from the bus
        bool answered = false;       // the drive confirmed the write
        QString error;               // why not seen / not confirmed ("" when both)
    };
    std::vector<Drive> drives;
    int waitedMs = 0;

    bool allSeen() const;
    // The drives whose Disable voltage was not seen going out, as one line (empty when none).
    QString notSeen() const;
    // One line per drive, English (CLI, log).
    QString summary() const;
};

// Before a bus closes, whatever closes it (disconnect, another connection, a log opened, the
// app quitting; the CLI's end): Disable voltage (6040h = 0000h) to every drive the bus's record
// says CoScope enabled (EnabledDrives), Quick stop (0002h) first to one that may be moving, as
// expedited SDO downloads (CiA 301 §7.2.4.3.3) sent straight on the bus; then a wait until the
// bus's Tx copy of each request came back through the dispatcher, so it went out and is in the
// trace and the capture journal, and until the drives answered, at most `timeoutMs` in all.
// The wait blocks the calling thread without an event loop or a dialog (it runs while windows
// and services are torn down). Drives whose Disable voltage was seen leave the record. The
// caller closes the SDO client first (no transfer of its own in the way); listen-only or a
// bus that is not open sends nothing and says so.
DriveDisableOutcome disableEnabledDrives(MasterContext& context, int timeoutMs = 500);

}  // namespace coscope::canopen
