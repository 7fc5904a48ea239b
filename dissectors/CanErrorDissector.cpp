// SPDX-License-Identifier: GPL-3.0-or-later
// CAN error frames (not CANopen, but what a technician must see first when the wiring or the bit
// rate is wrong): decoded by core/can/CanErrorFrame from the SocketCAN layout.
#include "core/can/CanErrorFrame.h"
#include "dissectors/Services.h"

namespace coscope::dissect {

void dissectCanError(DissectCall& c) {
    Dissection& out = c.out;
    const CanErrorReport r = decodeCanError(c.frame);
    const QString state = busStateName(r.state);
    if (r.isSevere()) out.warn(QStringLiteral("CAN error: ") + r.summary());
    if (!out.wantText()) return;
    out.addUInt("can.err.class", r.classes);
    if (!state.isEmpty()) out.addText("can.err.state", state);
    if (r.txErrors) {
        out.addInt("can.err.tx_errors", *r.txErrors);
        out.addInt("can.err.rx_errors", *r.rxErrors);
    }
    out.addText("can.err.text", r.summary());
    out.summary = QStringLiteral("CAN error: ") + r.summary();
    if (out.wantTree()) {
        out.item(0, QStringLiteral("Error classes"), QStringLiteral("0x%1").arg(r.classes, 8, 16, QLatin1Char('0')));
        if (!state.isEmpty()) out.item(0, QStringLiteral("Bus state"), state);
        for (const QString& p : r.problems) out.item(1, QStringLiteral("Problem"), p);
        if (r.txErrors) {
            out.item(0, QStringLiteral("TX error counter"), QString::number(*r.txErrors), 6, 1);
            out.item(0, QStringLiteral("RX error counter"), QString::number(*r.rxErrors), 7, 1);
        }
    }
}

}  // namespace coscope::dissect
