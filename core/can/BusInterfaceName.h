// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/BusUrl.h"

namespace coscope {

// The interface name a candump -L line shows for frames of this bus: the device for Qt plugins
// ("can0" for socketcan://can0), the channel for socketcand ("can0" for
// socketcand://host:29536/can0), "sim" for sim://, the file's base name for replay://.
QString busInterfaceName(const BusUrl& url);

}  // namespace coscope
