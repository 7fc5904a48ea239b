// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/trace/TimeBase.h"

#include <QDateTime>

namespace coscope {

namespace {
// Floor division: a time before the epoch still splits into a millisecond and its microseconds.
int64_t floorDiv(int64_t a, int64_t b) { return a / b - ((a % b) < 0 ? 1 : 0); }
}  // namespace

QString TimeBase::text(int64_t ns, bool withDate) const {
    if (shown() == Mode::Relative) return QString::number(seconds(ns), 'f', 6);
    const int64_t ms = floorDiv(ns, 1'000'000);
    const QDateTime dt = QDateTime::fromMSecsSinceEpoch(ms);
    const QString clock =
        dt.toString(withDate ? QStringLiteral("yyyy-MM-dd HH:mm:ss.zzz") : QStringLiteral("HH:mm:ss.zzz"));
    return clock + QStringLiteral("%1").arg(floorDiv(ns, 1000) - ms * 1000, 3, 10, QLatin1Char('0'));
}

QString TimeBase::shortText(int64_t ns) const {
    if (shown() == Mode::Relative) return QStringLiteral("%1 s").arg(seconds(ns), 0, 'f', 3);
    return QDateTime::fromMSecsSinceEpoch(floorDiv(ns, 1'000'000)).toString(QStringLiteral("HH:mm:ss.zzz"));
}

}  // namespace coscope
