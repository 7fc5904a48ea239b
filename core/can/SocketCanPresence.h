// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

namespace coscope {

// Whether a SocketCAN interface is still there and up (issue 16 "Lost adapter"): a USB adapter
// unplugged or `ip link del` makes it Gone (ENODEV), `ip link set down` makes it Down (ENETDOWN).
// Qt's socketcan plugin reports neither while idle, so QtCanBus asks once a second.
enum class LinkPresence { Up, Down, Gone };
LinkPresence socketCanPresence(const QString& interfaceName);

}  // namespace coscope
