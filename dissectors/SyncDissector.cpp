// SPDX-License-Identifier: GPL-3.0-or-later
// SYNC (CiA 301 §7.2.5.3): COB-ID 080h, no data, or 1 byte counter 1..240 when 1019h > 1.
#include "dissectors/Services.h"
#include "dissectors/SummaryBuffer.h"

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
        if (out.wantTree()) out.item(0, QStringLiteral("Counter"), QString::number(c.data[0]), 0, 1);
    }
    // One SYNC per cycle: the summary goes straight into the consumer's buffer
    // (Dissection::summarySink), or a reused one copied into out.summary, without a QString::arg.
    thread_local SummaryBuffer scratch;
    SummaryBuffer& sb = out.summarySink ? *out.summarySink : scratch;
    if (!out.summarySink) sb.clear();
    {
        SummaryBuffer::Cursor w(sb);
        if (hasCounter) {
            w.put(u"SYNC counter ");
            w.putDecimal(static_cast<int64_t>(c.data[0]));
        } else {
            w.put(u"SYNC");
        }
    }
    if (!out.summarySink) sb.storeIn(out.summary);
}

}  // namespace coscope::dissect
