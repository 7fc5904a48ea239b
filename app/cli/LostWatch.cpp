// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/LostWatch.h"

#include "core/can/CanBus.h"

#include <cstdio>

namespace coscope::cli {

void LostWatch::poll() {
    const CanBus::State s = bus_->state();
    if (s == CanBus::State::Lost && lostSinceNs_ == 0) {
        lostSinceNs_ = bus_->lostSinceNs() ? bus_->lostSinceNs() : nowNs();
        const int retryMs = bus_->nextRetryInMs();
        std::fprintf(stderr,
                     "coscope-cli %s: bus lost (%s); retrying in %s s, with back-off up to 8 s, until it is back\n",
                     qPrintable(verb_), qPrintable(bus_->errorString()),
                     qPrintable(QString::number(retryMs < 0 ? 0.5 : retryMs / 1000.0, 'f', 1)));
        std::fflush(stderr);
    } else if (s == CanBus::State::Open && lostSinceNs_ != 0) {
        const int64_t back = nowNs();
        const double gapS = static_cast<double>(back - lostSinceNs_) / 1e9;
        if (onBack_) onBack_(lostSinceNs_, back);
        std::fprintf(stderr, "coscope-cli %s: bus back after %.1f s\n", qPrintable(verb_), gapS);
        std::fflush(stderr);
        lostSinceNs_ = 0;
    }
}

}  // namespace coscope::cli
