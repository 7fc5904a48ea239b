// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstdint>
#include <mutex>
#include <vector>

namespace coscope::canopen {

// The drives CoScope itself switched on over one bus: a per-bus record (MasterContext) fed by
// every controlword 6040h CoScope writes (Ds402Controller, and any later writer: process data,
// transmit list), so that whatever closes the bus can first disable them (DriveDisable.h) and
// the app can ask before it does. Thread-safe.
//
// A drive counts as enabled once a controlword with "enable voltage" (bit 1) set went to it:
// Shutdown, Switch on, Enable operation and Quick stop (CiA 402-2 §6.2.1, Table 28) all leave
// voltage on; Disable voltage and Fault reset have bit 1 low and end in Switch on disabled.
class EnabledDrives {
public:
    struct Drive {
        uint8_t node = 0;
        int axis = 0;              // multi-axis device: objects at +axis*800h (CiA 402-2 §5.2)
        uint16_t controlword = 0;  // the last one CoScope wrote
        // Operation enabled asked for (bits 0-3 set): the motor may be moving.
        bool mayMove() const { return (controlword & 0x000F) == 0x000F; }
        QString name() const;  // "node 3", "node 3 axis 1"
    };

    // A controlword CoScope writes (or wrote) to `node`'s axis `axis`. Writers call it with an
    // enabling word before sending it, and with a disabling one once the drive took it.
    void noteControlword(uint8_t node, int axis, uint16_t controlword);
    // The drive is known to be off (or left to the user on purpose): no longer recorded.
    void forget(uint8_t node, int axis);
    static bool enablesVoltage(uint16_t controlword) { return controlword & 0x0002; }

    std::vector<Drive> drives() const;
    bool isEmpty() const;
    // "node 3", "node 1 and node 3": for questions and messages.
    QString names() const;

private:
    mutable std::mutex mutex_;
    std::vector<Drive> drives_;
};

}  // namespace coscope::canopen
