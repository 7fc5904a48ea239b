// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cstdint>
#include <optional>
#include <tuple>
#include <utility>

namespace coscope::sim {

// Faults a virtual device's SDO server injects, for testing SDO clients. Touch only on the
// network thread (SimNetwork::runOnNetworkThread).
struct SdoFaults {
    // The next N responses the server would send are swallowed (the request is still handled:
    // a dropped download response does not undo the write). Counts down to 0.
    int dropResponses = 0;
    // Every response is sent this many milliseconds late (while > 0).
    int delayMs = 0;
    // One-shot: the next segmented upload segment / download segment response carries the
    // wrong toggle bit. Cleared when used.
    bool wrongToggle = false;
    // One-shot: the next block upload ends with a wrong CRC; the next block download is
    // answered with abort 05040004h (CRC error) at its end. Cleared when used.
    bool blockCrcError = false;
    // While set, block transfers are refused with abort 05040001h (command specifier not valid
    // or unknown, CiA 301 §7.2.4.3.17): the server behaves like one without block support.
    bool declineBlock = false;
    // While set, a segmented or block download (of any object) is aborted by the server with
    // the code once it holds at least `bytes` of it: a device that gives up half-way.
    std::optional<std::pair<int, uint32_t>> abortDownloadAfter;
    // While set, any request for (index, sub) is aborted with the code.
    std::optional<std::tuple<uint16_t, uint8_t, uint32_t>> abortOn;
};

}  // namespace coscope::sim
