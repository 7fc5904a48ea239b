// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/health/HealthMonitor.h"

namespace coscope::gui {

HealthMonitor::HealthMonitor() { ctx_.setGenericNames(false); }

void HealthMonitor::consume(const TraceStore& store, FrameNo first, size_t count) {
    if (count == 0) return;
    std::lock_guard lock(mutex_);
    for (size_t i = 0; i < count; ++i) {
        const CanFrame f = store.frame(first + static_cast<FrameNo>(i));
        if (!f.isError()) ctx_.dissect(f, d_, dissect::Dissection::Level::Stats);
        health_.add(f, d_, ctx_);
    }
    revision_.fetch_add(count, std::memory_order_release);
}

void HealthMonitor::clear() {
    std::lock_guard lock(mutex_);
    ctx_ = dissect::NetworkContext();
    ctx_.setGenericNames(false);
    health_ = dissect::NetworkHealth(health_.bitRate());
    revision_.fetch_add(1, std::memory_order_release);
}

dissect::HealthReport HealthMonitor::report(int64_t nowNs) const {
    std::lock_guard lock(mutex_);
    return health_.report(&ctx_, nowNs);
}

}  // namespace coscope::gui
