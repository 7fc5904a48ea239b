// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What we sent, read back from the trace: the intervals between our frames of one identifier
// (periodic sends measured as they went out), their median, and their count.

#include "core/trace/TraceStore.h"

#include <algorithm>
#include <vector>

namespace coscope::testing {

// The intervals (ms) between the frames we sent with 11-bit identifier `id`, from frame `from` on.
inline std::vector<double> txIntervalsMs(const TraceStore& store, uint32_t id, size_t from = 0) {
    std::vector<double> out;
    int64_t last = 0;
    for (size_t n = from; n < store.size(); ++n) {
        const CanFrame f = store.frame(static_cast<FrameNo>(n));
        if (f.id != id || !f.isTx() || f.isExtended()) continue;
        if (last) out.push_back(double(f.timestampNs - last) / 1e6);
        last = f.timestampNs;
    }
    return out;
}

inline double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

inline size_t countTx(const TraceStore& store, uint32_t id) {
    size_t n = 0;
    for (size_t i = 0; i < store.size(); ++i) {
        const CanFrame f = store.frame(static_cast<FrameNo>(i));
        n += f.id == id && f.isTx();
    }
    return n;
}

}  // namespace coscope::testing
