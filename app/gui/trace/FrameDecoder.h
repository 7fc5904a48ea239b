// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"
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
    virtual void decode(const CanFrame& frame, dissect::Dissection& out) const = 0;
};

// The decoder the app uses: stateless CANopen decoding of single frames from the codecs in
// core/canopen (CiA 301 pre-defined connection set). The dissector registry with its network
// context (dictionary names, PDO mappings, SDO reassembly) replaces it when present.
std::shared_ptr<const FrameDecoder> defaultFrameDecoder();

}  // namespace coscope::gui
