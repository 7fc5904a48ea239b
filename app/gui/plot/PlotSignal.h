// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/trace/SignalBuffer.h"
#include "dissectors/SignalCatalog.h"

#include <QColor>
#include <QString>

#include <memory>

namespace coscope::gui {

// One signal on the plot: what it is, how to scale it and where its samples are.
struct PlotSignal {
    dissect::SignalKey key;
    QString name;   // "Position actual value"
    QString label;  // legend text: "n2 Position actual value"
    dissect::SignalScale scale;
    bool digital = false;
    // A bit pattern (statusword, controlword, digital inputs: od::HexKind::Pattern) plotted
    // unscaled: its axis and readout in hex ("0637h") as the numbers rule says (od/NumberNotation.h).
    bool hex = false;
    QColor color;
    std::shared_ptr<const SignalBuffer> buffer;

    // "Position actual value [pulse]" (axis titles, CSV headers).
    QString titleWithUnit() const {
        return scale.unit.isEmpty() ? label : QStringLiteral("%1 [%2]").arg(label, scale.unit);
    }
    double valueOf(double raw) const { return digital ? raw : scale.apply(raw); }
    // A value as the readout writes it: hex for a bit pattern, else decimal.
    QString valueText(double v) const;
};

// Distinct colours that read well on white and in print (Tableau 10).
QColor plotColor(int i);

}  // namespace coscope::gui
