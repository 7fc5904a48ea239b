// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/common/BusLossAdvice.h"

#include "core/canopen/Nmt.h"
#include "core/canopen/NodeTable.h"

namespace coscope::gui {

QString BusLossAdvice::lastNmtState(const canopen::NodeTable& nodes, int node) {
    const auto info = nodes.node(node);
    if (!info || info->nmtState < 0) return tr("NMT state unknown");
    return tr("NMT: %1").arg(canopen::nmtStateName(static_cast<uint8_t>(info->nmtState)));
}

QString BusLossAdvice::driveMessage(const QString& reason, int node, const QString& nmt, const QString& lastDriveState, bool mayBeEnabled) {
    QString text = tr("Bus lost (%1). The wizard stopped: nothing more can be sent to node %2.").arg(reason).arg(node);
    text += u' ' + tr("Last known state: %1, %2.").arg(lastDriveState, nmt);
    if (mayBeEnabled)
        text += u' ' + tr("The drive may still be enabled (and moving, if it was): only its own communication-loss reaction "
                          "(6007h) or heartbeat consumer (1016h) stops it.");
    else
        text += u' ' + tr("The drive was not enabled by this wizard; it should still be in that state.");
    text += u' ' + tr("Check at the drive (display, enable LED, brake) before going near the machine. CoScope reconnects by itself; "
                      "choose the drive again when the bus is back.");
    return text;
}

QString BusLossAdvice::scriptMessage(const QString& reason, int step, int steps) {
    return tr("Stopped: bus lost (%1) during step %2 of %3. The steps before it were sent; this one may or may not have reached "
              "the device, nothing after it was sent. The device may be half-configured (a PDO left disabled, a new node-ID or bit "
              "rate stored but not applied). When the bus is back, read the objects of this script back before running it again.")
        .arg(reason)
        .arg(step + 1)
        .arg(steps);
}

}  // namespace coscope::gui
