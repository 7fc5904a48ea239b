// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"

#include <QString>

#include <cstdint>
#include <optional>

namespace coscope::canopen {

// NMT node control command specifiers (CiA 301 §7.2.8.3.1, COB-ID 000h, 2 bytes: cs, node-ID).
enum class NmtCommand : uint8_t {
    Start = 0x01,
    Stop = 0x02,
    EnterPreOperational = 0x80,
    ResetNode = 0x81,
    ResetCommunication = 0x82,
};

// NMT states as carried by boot-up/heartbeat/guarding (CiA 301 §7.2.8.3.2, Table 51).
enum class NmtState : uint8_t {
    BootUp = 0x00,
    Stopped = 0x04,
    Operational = 0x05,
    PreOperational = 0x7F,
};

QString nmtCommandName(uint8_t cs);                                 // "Start", "Reset node", ... or "Unknown (0x..)"
std::optional<NmtCommand> nmtCommandFromName(const QString& word);  // start|stop|preop|reset|reset-comm
QString nmtStateName(uint8_t state);                                // "Boot-up", "Operational", ...
// The state a node is in after command `cs` (CiA 301 §7.3.2.2.1): 05h, 04h, 7Fh; -1 for the
// resets (the node initialises and sends its boot-up) and unknown commands.
int nmtStateAfter(uint8_t cs);

CanFrame nmtFrame(NmtCommand cs, uint8_t node);  // node 0 = all nodes
CanFrame heartbeatFrame(uint8_t node, NmtState state);

}  // namespace coscope::canopen
