// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanBus.h"
#include "core/sim/SimNetwork.h"

#include <memory>

namespace coscope::sim {

// The URL that reopens `bus` at `bitRate` bit/s (the bitrate= option). For sim:// the virtual
// network is published under a name (sim://NAME, SimNetwork::publish) and *keepAlive holds it,
// so the devices keep their state (a new node-ID, a new bit rate) while the bus is closed and
// reopened; keep it until the new endpoint is open.
QString urlAtBitRate(const CanBus& bus, int bitRate, std::shared_ptr<SimNetwork>* keepAlive);

}  // namespace coscope::sim
