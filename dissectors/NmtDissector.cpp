// SPDX-License-Identifier: GPL-3.0-or-later
// NMT node control (CiA 301 §7.2.8.3.1): COB-ID 000h, byte 0 command specifier, byte 1 node-ID
// (0 = all nodes).
#include "core/canopen/Nmt.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/Services.h"

namespace coscope::dissect {

void dissectNmt(DissectCall& c) {
    Dissection& out = c.out;
    out.node = -1;
    if (c.frame.isRemote() || c.len < 2) {
        out.warn(QStringLiteral("NMT command with %1 bytes; CiA 301 requires 2").arg(c.len));
        if (out.wantText()) out.summary = QStringLiteral("NMT (malformed)");
        return;
    }
    if (c.len != 2) out.warn(QStringLiteral("NMT command with %1 bytes; CiA 301 requires 2").arg(c.len));
    const uint8_t cs = c.data[0];
    const uint8_t target = c.data[1];
    int newState = -2;  // -2 = unknown command
    switch (cs) {
    case 0x01: newState = 5; break;
    case 0x02: newState = 4; break;
    case 0x80: newState = 127; break;
    case 0x81:
    case 0x82: newState = -1; break;  // resetting: a boot-up follows
    default: out.warn(QStringLiteral("unknown NMT command specifier 0x%1").arg(cs, 2, 16, QLatin1Char('0'))); break;
    }
    if (target > 127) out.warn(QStringLiteral("NMT target node-ID %1 is outside 0..127").arg(target));
    if (newState != -2) {
        auto apply = [&](int n) {
            NodeState& s = c.ctx.nodeForEdit(n);
            s.nmtState = newState;
            s.seen = true;
            s.lastNmtNs = c.frame.timestampNs;
            if (newState == -1) s.guardToggle = -1;
        };
        if (target == 0) {
            for (int n = 1; n < 128; ++n)
                if (c.ctx.node(n).seen) apply(n);
        } else if (target <= 127) {
            apply(target);
        }
    }
    if (!out.wantText()) return;
    out.addInt("nmt.cs", cs);
    out.addInt("nmt.node", target);
    const QString name = canopen::nmtCommandName(cs);
    out.summary = QStringLiteral("NMT %1, %2")
                      .arg(name, target ? QStringLiteral("node %1").arg(target) : QStringLiteral("all nodes"));
    if (out.wantTree()) {
        out.item(0, QStringLiteral("Command specifier"),
                 QStringLiteral("%1 (0x%2)").arg(name).arg(cs, 2, 16, QLatin1Char('0')), 0, 1);
        out.item(0, QStringLiteral("Node-ID"), target ? QString::number(target) : QStringLiteral("0 (all nodes)"), 1,
                 1);
    }
}

}  // namespace coscope::dissect
