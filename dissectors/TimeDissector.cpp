// SPDX-License-Identifier: GPL-3.0-or-later
// TIME (CiA 301 §7.2.6.3, TIME_OF_DAY §7.1.6.5): COB-ID 100h, 6 bytes: bits 0..27 milliseconds
// after midnight, bytes 4-5 days since 1 January 1984.
#include "dissectors/Services.h"

#include <QDate>

namespace coscope::dissect {

void dissectTime(DissectCall& c) {
    Dissection& out = c.out;
    out.node = -1;
    if (c.len < 6) {
        out.warn(QStringLiteral("TIME with %1 bytes; CiA 301 requires 6").arg(c.len));
        if (out.wantText()) out.summary = QStringLiteral("TIME (malformed)");
        return;
    }
    if (c.len > 6) out.warn(QStringLiteral("TIME with %1 bytes; CiA 301 requires 6").arg(c.len));
    const uint32_t ms = (c.data[0] | (c.data[1] << 8) | (c.data[2] << 16) | (uint32_t(c.data[3]) << 24)) & 0x0FFFFFFFu;
    const uint16_t days = static_cast<uint16_t>(c.data[4] | (c.data[5] << 8));
    if (ms >= 86400000u) out.warn(QStringLiteral("TIME milliseconds %1 exceed one day").arg(ms));
    if (!out.wantText()) return;
    out.addInt("time.ms", ms);
    out.addInt("time.days", days);
    const QDate date = QDate(1984, 1, 1).addDays(days);
    const QString clock = QStringLiteral("%1:%2:%3.%4")
                              .arg(ms / 3600000u, 2, 10, QLatin1Char('0'))
                              .arg(ms / 60000u % 60u, 2, 10, QLatin1Char('0'))
                              .arg(ms / 1000u % 60u, 2, 10, QLatin1Char('0'))
                              .arg(ms % 1000u, 3, 10, QLatin1Char('0'));
    out.summary = QStringLiteral("TIME %1 %2").arg(date.toString(Qt::ISODate), clock);
    if (out.wantTree()) {
        out.item(0, QStringLiteral("Milliseconds after midnight"), QString::number(ms), 0, 4, 0, 28);
        out.item(0, QStringLiteral("Days since 1984-01-01"), QString::number(days), 4, 2);
    }
}

}  // namespace coscope::dissect
