// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

namespace coscope {

// The waits between attempts to reopen a lost adapter (issue 16 "Lost adapter"): the first retry
// after kFirstMs, each further one twice as long, never more than kMaxMs; reset() once the
// adapter is back. Pure, so the schedule is testable without a bus.
class ReconnectBackoff {
public:
    static constexpr int kFirstMs = 500;
    static constexpr int kMaxMs = 8000;

    // The wait before the next attempt; advances the schedule.
    int next() {
        const int wait = nextMs_;
        nextMs_ = nextMs_ >= kMaxMs / 2 ? kMaxMs : nextMs_ * 2;
        ++attempts_;
        return wait;
    }
    int attempts() const { return attempts_; }
    void reset() {
        nextMs_ = kFirstMs;
        attempts_ = 0;
    }

private:
    int nextMs_ = kFirstMs;
    int attempts_ = 0;
};

}  // namespace coscope
