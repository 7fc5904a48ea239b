// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/NmtMaster.h"

#include <spdlog/spdlog.h>

namespace coscope::canopen {

bool NmtMaster::send(NmtCommand command, uint8_t node, QString* error) {
    if (node > 127) {
        if (error) *error = QStringLiteral("node-ID %1 is outside 1-127 (0 = all nodes)").arg(node);
        return false;
    }
    spdlog::info("NMT {} to {}", nmtCommandName(static_cast<uint8_t>(command)).toStdString(),
                 node ? std::to_string(node) : std::string("all nodes"));
    return context_.send(nmtFrame(command, node), error);
}

}  // namespace coscope::canopen
