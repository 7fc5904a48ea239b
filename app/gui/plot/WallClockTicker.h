// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <qcustomplot.h>

#include <cstdint>

namespace coscope::gui {

// The plot's time axis in wall-clock time (issue 37 item 3: one time base): the axis still
// counts seconds from the trace's first frame, the ticks fall on round times of the local
// clock (every 10 s, 1 min, 15 min, ...) and read "14:03:20" (".250" below a second).
class WallClockTicker : public QCPAxisTicker {
public:
    explicit WallClockTicker(int64_t originNs);

protected:
    double getTickStep(const QCPRange& range) override;
    QVector<double> createTickVector(double tickStep, const QCPRange& range) override;
    QString getTickLabel(double tick, const QLocale& locale, QChar formatChar, int precision) override;

private:
    int64_t originNs_;
    double originLocalS_;  // the origin as seconds of the local clock since the epoch
    double step_ = 1;
};

}  // namespace coscope::gui
