// SPDX-License-Identifier: GPL-3.0-or-later
// NMT error control (CiA 301 §7.2.8.3.2): COB-ID 700h + node. Boot-up = 1 byte 00h; heartbeat =
// 1 byte state (04h stopped, 05h operational, 7Fh pre-operational); node guarding = a remote
// frame from the master, answered with the state in bits 0..6 and a toggle bit in bit 7 that
// alternates from 0 (§7.2.8.3.2.1).
#include "core/canopen/Nmt.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/Services.h"

namespace coscope::dissect {

void dissectErrorControl(DissectCall& c) {
    Dissection& out = c.out;
    NodeState& n = c.ctx.nodeForEdit(c.node);
    if (c.frame.isRemote()) {
        n.guardRequested = true;
        if (!out.wantText()) return;
        out.addBool("nmt.rtr", true);
        out.summary = QStringLiteral("Node guarding request, node %1").arg(c.node);
        return;
    }
    if (c.len != 1) out.warn(QStringLiteral("error control frame with %1 bytes; CiA 301 requires 1").arg(c.len));
    if (c.len < 1) {
        if (out.wantText()) out.summary = QStringLiteral("Error control (malformed), node %1").arg(c.node);
        return;
    }
    const uint8_t b = c.data[0];
    auto isState = [](int s) { return s == 0 || s == 4 || s == 5 || s == 127; };
    // A reply with bit 7 set is a guarding reply even when the request is not in the trace.
    const bool guarding = n.guardRequested || ((b & 0x80) && isState(b & 0x7F));
    const int toggle = guarding ? (b >> 7) : -1;
    const uint8_t state = guarding ? (b & 0x7F) : b;
    if (!isState(state)) out.warn(QStringLiteral("unknown NMT state 0x%1").arg(state, 2, 16, QLatin1Char('0')));
    if (guarding) {
        if (n.guardToggle >= 0 && toggle == n.guardToggle)
            out.warn(QStringLiteral("node guarding toggle bit did not alternate (still %1)").arg(toggle));
        n.guardToggle = toggle;
        n.guardRequested = false;
    }
    if (state == 0) n.guardToggle = -1;  // boot-up restarts the toggle sequence
    n.nmtState = state;
    n.lastNmtNs = c.frame.timestampNs;
    if (!out.wantText()) return;
    out.addInt("nmt.state", state);
    if (guarding) out.addInt("nmt.toggle", toggle);
    const QString name = canopen::nmtStateName(state);
    if (state == 0) out.summary = QStringLiteral("Boot-up, node %1").arg(c.node);
    else if (guarding)
        out.summary = QStringLiteral("Node guarding, node %1: %2, toggle %3").arg(c.node).arg(name).arg(toggle);
    else out.summary = QStringLiteral("Heartbeat, node %1: %2").arg(c.node).arg(name);
    if (out.wantTree()) {
        if (guarding) out.item(0, QStringLiteral("Toggle bit"), QString::number(toggle), 0, 1, 7, 1);
        out.item(0, QStringLiteral("State"), QStringLiteral("%1 (0x%2)").arg(name).arg(state, 2, 16, QLatin1Char('0')),
                 0, 1, guarding ? 0 : -1, guarding ? 7 : 0);
    }
}

}  // namespace coscope::dissect
