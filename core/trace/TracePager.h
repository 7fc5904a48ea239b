// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"

#include <cstdint>
#include <string>
#include <vector>

namespace coscope {

// Where a TraceStore pages evicted chunks back from (issue 16 "Bounded memory"): frame n of the
// store is frame n of the pager. Called from any thread.
class TracePager {
public:
    virtual ~TracePager() = default;
    // Frames [0, durableFrames()) can be loaded back; a store never evicts a chunk beyond it.
    virtual uint64_t durableFrames() const = 0;
    // Frames [first, first + count) in order into `out`; false if they cannot be read (the
    // file went away), with a reason in `why`.
    virtual bool load(uint64_t first, uint32_t count, std::vector<CanFrame>& out, std::string* why) = 0;
    // A folder on disk where the store may keep what else would grow in RAM (its per-COB-ID
    // index blocks, see IndexSpill); empty: none.
    virtual std::string spillDirectory() const { return {}; }
};

}  // namespace coscope
