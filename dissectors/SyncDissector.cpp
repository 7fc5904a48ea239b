// SPDX-License-Identifier: GPL-3.0-or-later
// SYNC (CiA 301 §7.2.5.3): COB-ID 080h, no data, or 1 byte counter 1..240 when 1019h > 1.
#include "dissectors/Services.h"

namespace coscope::dissect {

void dissectSync(DissectCall& c) {
    Dissection& out = c.out;
    out.node = -1;
    const bool hasCounter = c.len >= 1;
    if (c.len > 1) out.warn(QStringLiteral("SYNC with %1 bytes; CiA 301 allows 0 or 1").arg(c.len));
    if (hasCounter && (c.data[0] < 1 || c.data[0] > 240))
        out.warn(QStringLiteral("SYNC counter %1 is outside 1..240").arg(c.data[0]));
    if (!out.wantText()) return;
    if (hasCounter) {
        out.addInt("sync.counter", c.data[0]);
        out.summary = QStringLiteral("SYNC counter %1").arg(c.data[0]);
        if (out.wantTree()) out.item(0, QStringLiteral("Counter"), QString::number(c.data[0]), 0, 1);
    } else {
        out.summary = QStringLiteral("SYNC");
    }
}

}  // namespace coscope::dissect
