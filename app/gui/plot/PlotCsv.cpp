// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/PlotCsv.h"

#include "core/logio/CsvField.h"

#include <QFile>
#include <QSaveFile>
#include <QTextStream>

#include <map>

namespace coscope::gui {

using logio::csvField;

bool writePlotCsv(const QString& path, const std::vector<PlotSignal>& plotted, int64_t t0, int64_t t1, int64_t originNs,
                  QString* error) {
    // frame -> (time, one value per signal)
    struct Row {
        int64_t timeNs = 0;
        std::vector<std::optional<double>> values;
    };
    std::map<FrameNo, Row> rows;
    for (size_t i = 0; i < plotted.size(); ++i) {
        const PlotSignal& s = plotted[i];
        if (!s.buffer) continue;
        for (const SignalSample& x : s.buffer->samples(t0, t1)) {
            Row& r = rows[x.frame];
            r.timeNs = x.timeNs;
            r.values.resize(plotted.size());
            r.values[i] = s.digital ? double((static_cast<int64_t>(x.value) >> s.key.bit) & 1) : s.scale.apply(x.value);
        }
    }
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) {
        if (error) *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return false;
    }
    QTextStream out(&file);
    out << "time_s,frame";
    for (const PlotSignal& s : plotted) out << ',' << csvField(s.digital ? s.label : s.titleWithUnit());
    out << '\n';
    for (const auto& [frame, r] : rows) {
        out << QString::number(double(r.timeNs - originNs) / 1e9, 'f', 6) << ',' << frame;
        for (size_t i = 0; i < plotted.size(); ++i) {
            out << ',';
            if (i < r.values.size() && r.values[i]) out << QString::number(*r.values[i], 'g', 15);
        }
        out << '\n';
    }
    out.flush();
    if (!file.commit()) {
        if (error) *error = QStringLiteral("%1: %2").arg(path, file.errorString());
        return false;
    }
    return true;
}

}  // namespace coscope::gui
