// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>

namespace coscope::sim {

// Faults a virtual device's LSS slave injects, for testing LSS masters and the node-ID/bit-rate
// wizard. Touch only on the network thread (SimNetwork::runOnNetworkThread).
struct LssFaults {
    // While non-zero, store configuration is answered with this error code (CiA 305 §6.4.5:
    // 1 = store not supported, 2 = storage media access error) and nothing is stored.
    uint8_t storeError = 0;
    // While non-zero, configure node-ID is answered with this error code (§6.4.2: 1 = node-ID
    // out of range) and the node-ID stays as it is.
    uint8_t configureNodeIdError = 0;
    // While non-zero, every LSS answer leaves this many ms after the request: a busy slave or a
    // gateway in between. CiA 305 §6.7.4 leaves the fastscan timeout to the master.
    int replyDelayMs = 0;
};

}  // namespace coscope::sim
