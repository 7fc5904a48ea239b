// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstdint>
#include <functional>

namespace coscope {
class CanBus;
}

namespace coscope::cli {

// Watches a capturing bus for a lost adapter (CanBus::State::Lost, issue 16) and says so on
// stderr: "bus lost (...); retrying" when it goes, "bus back after N s" when it returns. The
// bus reconnects by itself; capturing goes on and the output keeps every frame on either side.
class LostWatch {
public:
    LostWatch(CanBus* bus, const QString& verb) : bus_(bus), verb_(verb) {}
    void poll();  // call from the capture loop
    // Called when the bus is back, with when it was lost and when it came back (record marks
    // the gap in its output: a pcapng packet comment).
    void setOnBack(std::function<void(int64_t lostNs, int64_t backNs)> onBack) { onBack_ = std::move(onBack); }
    bool isLost() const { return lostSinceNs_ != 0; }

private:
    CanBus* bus_;
    QString verb_;
    int64_t lostSinceNs_ = 0;
    std::function<void(int64_t, int64_t)> onBack_;
};

}  // namespace coscope::cli
