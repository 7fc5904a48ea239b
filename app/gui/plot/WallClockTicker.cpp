// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/WallClockTicker.h"

#include "core/trace/TimeBase.h"

#include <QDateTime>
#include <QTimeZone>

#include <cmath>

namespace coscope::gui {

WallClockTicker::WallClockTicker(int64_t originNs) : originNs_(originNs) {
    const QDateTime at = QDateTime::fromMSecsSinceEpoch(originNs / 1'000'000);
    originLocalS_ = double(originNs) / 1e9 + double(QTimeZone::systemTimeZone().offsetFromUtc(at));
}

double WallClockTicker::getTickStep(const QCPRange& range) {
    // Below a second the plain 1-2-5 steps; above, the clock's own: 1 2 5 10 15 30 s, 1 2 5 10
    // 15 30 min, 1 2 3 6 12 h, days.
    const double plain = QCPAxisTicker::getTickStep(range);
    step_ = plain;
    if (plain >= 1.0) {
        static const double clock[] = {1,   2,   5,    10,   15,   30,    60,    120,   300,
                                       600, 900, 1800, 3600, 7200, 10800, 21600, 43200, 86400};
        step_ = clock[std::size(clock) - 1] * std::ceil(plain / clock[std::size(clock) - 1]);
        for (double c : clock)
            if (c >= plain * 0.9) {
                step_ = c;
                break;
            }
    }
    return step_;
}

QVector<double> WallClockTicker::createTickVector(double tickStep, const QCPRange& range) {
    QVector<double> ticks;
    if (tickStep <= 0) return ticks;
    // Ticks where the local clock is a whole multiple of the step.
    const double first = std::ceil((originLocalS_ + range.lower) / tickStep) * tickStep - originLocalS_;
    for (double t = first; t <= range.upper && ticks.size() < 1000; t += tickStep) ticks << t;
    return ticks;
}

QString WallClockTicker::getTickLabel(double tick, const QLocale&, QChar, int) {
    const int64_t ns = originNs_ + static_cast<int64_t>(std::llround(tick * 1e9));
    const TimeBase clock{originNs_, TimeBase::Mode::WallClock};
    if (step_ < 0.001) return clock.text(ns);  // to the microsecond
    const QString text = clock.shortText(ns);  // "HH:mm:ss.zzz"
    return step_ >= 1.0 ? text.left(8) : text;
}

}  // namespace coscope::gui
