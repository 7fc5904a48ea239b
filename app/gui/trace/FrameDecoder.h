// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"
#include "core/trace/TraceStore.h"
#include "dissectors/Dissection.h"

#include <memory>

namespace coscope::gui {

// The seam between the views and the dissectors: fills a Dissection (service, node, one-line
// summary and, at Level::Tree, the field tree with byte positions) for one frame.
// The views never decode themselves; they ask a FrameDecoder, lazily, for visible rows only.
// Implementations must be safe to call from several threads at once (the GUI thread decodes
// visible rows, filter jobs decode on a worker).
class FrameDecoder {
public:
    virtual ~FrameDecoder() = default;
    // One frame on its own (no trace context). `out` has been reset to the wanted level.
    virtual void decode(const CanFrame& frame, dissect::Dissection& out) const = 0;
    // Frame n of `store`, in the context of the frames before it (PDO mappings, SDO transfers).
    // The default decodes the frame on its own.
    virtual void decodeAt(const TraceStore& store, FrameNo n, dissect::Dissection& out) const {
        decode(store.frame(n), out);
    }
    // Whether decodeAt(store, n) answers at once, without going far back in the trace (a
    // bounded decoder keeps only some of its context snapshots); if not, the snapshot is asked
    // for in the background: a view draws the row as loading and asks again once readyCount()
    // changed.
    virtual bool readyAt(const TraceStore&, FrameNo) const { return true; }
    virtual uint64_t readyCount() const { return 0; }
    // Changes whenever results given before may be stale (dictionaries reassigned, store replaced).
    virtual uint64_t revision() const { return 0; }
};

// The decoder the app uses: stateless CANopen decoding of single frames from the codecs in
// core/canopen (CiA 301 pre-defined connection set). The dissector registry with its network
// context (dictionary names, PDO mappings, SDO reassembly) is TraceDecoder (TraceDecoder.h).
std::shared_ptr<const FrameDecoder> defaultFrameDecoder();

}  // namespace coscope::gui
