// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/BusLoad.h"

namespace coscope::dissect {

bool BusLoad::enterSecond(int64_t delta) {
    const int64_t sec = delta / 1000000000;           // truncates toward zero
    if (sec < 0 || sec >= kMaxSeconds) return false;  // out of order or absurd
    sec_ = sec;
    secLo_ = sec == 0 ? -999999999 : sec * 1000000000;
    secHi_ = (sec + 1) * 1000000000;
    if (static_cast<size_t>(sec) >= bitsPerSecond_.size()) bitsPerSecond_.resize(static_cast<size_t>(sec) + 1, 0.0);
    return true;
}

}  // namespace coscope::dissect
