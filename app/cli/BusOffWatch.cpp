// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/BusOffWatch.h"

#include "core/can/CanBus.h"

#include <cstdio>

namespace coscope::cli {

QString BusOffWatch::optionHelp() {
    return QStringLiteral("After bus-off, restart the CAN controller (where the adapter's plugin allows).");
}

void BusOffWatch::poll() {
    const uint64_t n = bus_->counters().busOffs;
    if (n == seen_) return;
    seen_ = n;
    const QString name = bus_->url().toString();
    if (!restart_) {
        std::fprintf(stderr,
                     "coscope-cli %s: %s is bus-off; the controller sends nothing until it is restarted "
                     "(--restart-on-bus-off, or the adapter's restart-ms)\n",
                     qPrintable(verb_), qPrintable(name));
        return;
    }
    QString why;
    if (bus_->restartController(&why))
        std::fprintf(stderr, "coscope-cli %s: %s was bus-off: controller restarted\n", qPrintable(verb_),
                     qPrintable(name));
    else
        std::fprintf(stderr, "coscope-cli %s: %s is bus-off and could not be restarted: %s\n", qPrintable(verb_),
                     qPrintable(name), qPrintable(why));
}

}  // namespace coscope::cli
