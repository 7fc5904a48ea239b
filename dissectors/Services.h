// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"
#include "dissectors/Dissection.h"

#include <cstdint>

namespace coscope::dissect {

class NetworkContext;

// What a per-service dissector gets: the frame, its payload, the node the COB-ID names, the
// context to read and update, and the result to fill.
struct DissectCall {
    const CanFrame& frame;
    NetworkContext& ctx;
    Dissection& out;
    int node;
    const uint8_t* data;
    int len;
};

using Dissector = void (*)(DissectCall&);

// The registry: one dissector per service (DissectorRegistry.cpp), each in its own file.
Dissector dissectorFor(canopen::Service service);

void dissectNmt(DissectCall& c);           // NmtDissector.cpp
void dissectSync(DissectCall& c);          // SyncDissector.cpp
void dissectTime(DissectCall& c);          // TimeDissector.cpp
void dissectEmcy(DissectCall& c);          // EmcyDissector.cpp
void dissectErrorControl(DissectCall& c);  // ErrorControlDissector.cpp
void dissectSdo(DissectCall& c);           // SdoDissector.cpp
void dissectPdo(DissectCall& c);           // PdoDissector.cpp
void dissectLss(DissectCall& c);           // LssDissector.cpp
void dissectCanError(DissectCall& c);      // CanErrorDissector.cpp (error frames, any COB-ID)
void dissectUnknown(DissectCall& c);       // DissectorRegistry.cpp

}  // namespace coscope::dissect
