// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/BusMaster.h"

namespace coscope::canopen {

BusMaster::BusMaster(MasterContext& context)
    : context_(context), sync_(context), heartbeat_(context), transmit_(context) {}

BusMaster::~BusMaster() { stopAll(); }

void BusMaster::stopAll() {
    sync_.stop();
    heartbeat_.stop();
    transmit_.stopAll();
}

bool BusMaster::anyRunning() const {
    return sync_.isRunning() || heartbeat_.isRunning() || transmit_.runningCount() > 0;
}

}  // namespace coscope::canopen
