// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/master/ owns what makes CoScope the master of a bus: the SYNC producer and the
// tool's own heartbeat (their settings, dialog, Bus menu and toolbar actions) and the transmit
// panel. The services themselves are in core (SyncProducer, HeartbeatProducer, TransmitList on
// the bus's PeriodicSender); these are their faces.
#pragma once

#include <QString>

#include <cstdint>

namespace coscope::gui {

// What the user set for the master services (Bus ▸ Master settings…), kept in QSettings
// ("master/…") between sessions.
struct MasterSettings {
    uint32_t syncPeriodUs = 10000;  // 1006h communication cycle period
    uint8_t syncCounter = 0;        // 1019h: 0 = no counter, 2..240
    uint32_t syncCobId = 0x80;      // 1005h
    bool writeCyclePeriod = false;  // write 1006h to the nodes when SYNC starts
    bool heartbeat = false;         // produce CoScope's own heartbeat
    int heartbeatNode = 127;        // its node-ID
    int heartbeatMs = 1000;         // its period (1017h of a producer)

    static MasterSettings load();
    void save() const;
    // "10 ms", "2.5 ms", "500 µs".
    static QString periodText(uint32_t us);
};

}  // namespace coscope::gui
