// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/common/BusLossAdvice.h"

#include "app/gui/language/CoreText.h"

#include "core/canopen/Nmt.h"
#include "core/canopen/NodeTable.h"

namespace coscope::gui {

QString BusLossAdvice::lastNmtState(const canopen::NodeTable& nodes, int node) {
    const auto info = nodes.node(node);
    if (!info || info->nmtState < 0) return tr("NMT state unknown");
    return tr("NMT: %1").arg(coreText(canopen::nmtStateName(static_cast<uint8_t>(info->nmtState))));
}

QString BusLossAdvice::driveMessage(const QString& reason, int node, const QString& nmt, const QString& lastDriveState,
                                    bool mayBeEnabled) {
    QString text = tr("Bus lost (%1). The wizard stopped: nothing more can be sent to node %2.").arg(reason).arg(node);
    text += u' ' + tr("Last known state: %1, %2.").arg(lastDriveState, nmt);
    if (mayBeEnabled)
        text += u' ' +
                tr("The drive may still be enabled (and moving, if it was): only its own communication-loss reaction "
                   "(6007h) or heartbeat consumer (1016h) stops it.");
    else text += u' ' + tr("The drive was not enabled by this wizard; it should still be in that state.");
    text += u' ' + tr("Check at the drive (display, enable LED, brake) before going near the machine. CoScope "
                      "reconnects by itself; "
                      "press “Read state” when the bus is back.");
    return text;
}

QString BusLossAdvice::scriptMessage(const QString& reason, int step, int steps) {
    return tr("Stopped: bus lost (%1) during step %2 of %3. The steps before it were sent; this one may or may not "
              "have reached "
              "the device, nothing after it was sent. The device may be half-configured (a PDO left disabled, a new "
              "node-ID or bit "
              "rate stored but not applied). When the bus is back, read the objects of this script back before running "
              "it again.")
        .arg(reason)
        .arg(step + 1)
        .arg(steps);
}

QString BusLossAdvice::pdoMessage(const QString& reason, int node, const QString& pdo, const QString& nmt) {
    return tr("Stopped: bus lost (%1) while applying %2 of node %3 (last known %4). The PDO may be left disabled "
              "(COB-ID bit 31 "
              "set) with its mapping half written, and the node pre-operational. When the bus is back, read %2 back "
              "(Choose page) "
              "and apply again; the drive's own communication-loss reaction decides what it does meanwhile.")
        .arg(reason, pdo)
        .arg(node)
        .arg(nmt);
}

QString BusLossAdvice::settingsMessage(const QString& reason, int node, const QString& nmt) {
    return tr("Stopped: bus lost (%1) during the change of node %2 (last known %3). The device may have taken the new "
              "node-ID or "
              "bit rate, stored it without applying it, or kept the old one. When the bus is back, scan (and if "
              "nothing answers, "
              "connect at the other bit rate) to see where the device is before changing anything else.")
        .arg(reason)
        .arg(node)
        .arg(nmt);
}

}  // namespace coscope::gui
