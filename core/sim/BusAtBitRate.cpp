// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/BusAtBitRate.h"

#include "core/sim/SimBus.h"

#include <atomic>

namespace coscope::sim {

QString urlAtBitRate(const CanBus& bus, int bitRate, std::shared_ptr<SimNetwork>* keepAlive) {
    BusUrl url = bus.url();
    if (bitRate > 0) url.options.insert(QStringLiteral("bitrate"), QString::number(bitRate));
    if (const auto* simBus = dynamic_cast<const SimBus*>(&bus); simBus && simBus->sharedNetwork()) {
        static std::atomic<int> counter{0};
        if (url.target.trimmed().isEmpty()) url.target = QStringLiteral("coscope-net%1").arg(++counter);
        SimNetwork::publish(url.target.trimmed(), simBus->sharedNetwork());
        if (keepAlive) *keepAlive = simBus->sharedNetwork();
    }
    return url.toString();
}

}  // namespace coscope::sim
