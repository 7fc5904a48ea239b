// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QByteArray>
#include <QString>

#include <chrono>
#include <cstdint>
#include <utility>
#include <vector>

namespace coscope::canopen {

class MasterContext;

// One expedited SDO download (CiA 301 §7.2.4.3.3, at most 4 bytes) sent straight on the bus,
// without an SdoClient, and what came back of it.
struct DirectDownload {
    uint8_t node = 0;
    uint16_t index = 0;
    uint8_t sub = 0;
    QByteArray data;
    // Filled by downloadDirect():
    bool seen = false;       // its own Tx copy came back from the bus (it went out, it is in the trace)
    bool answered = false;   // the server confirmed it (60h)
    uint32_t abortCode = 0;  // the server refused it (80h)
    QString error;           // why not seen / not confirmed; empty when both

    static DirectDownload of(uint8_t node, uint16_t index, uint8_t sub, QByteArray data) {
        DirectDownload d;
        d.node = node;
        d.index = index;
        d.sub = sub;
        d.data = std::move(data);
        return d;
    }
};

// The last words before a bus closes (DriveDisable.h, GuardedDrives.h): sends `downloads` and
// waits, blocking the calling thread without an event loop, until each one's Tx copy came back
// through the context's dispatcher and its server answered, at most until `deadline`. An SDO
// server takes one request at a time: downloads to one node go one after the other, in the
// given order (the next once the previous was answered or the time ran out); different nodes
// run side by side. `what` names the server in messages ("the drive", "the node").
void downloadDirect(MasterContext& context, std::vector<DirectDownload>& downloads,
                    std::chrono::steady_clock::time_point deadline, const QString& what = QStringLiteral("the node"));

}  // namespace coscope::canopen
