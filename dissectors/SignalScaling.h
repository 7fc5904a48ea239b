// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstdint>
#include <functional>
#include <optional>
#include <utility>

namespace coscope::dissect {

// How a raw PDO value becomes an engineering value: value = raw * factor + offset, in `unit`.
struct SignalScale {
    SignalScale() = default;
    SignalScale(double f, double o, QString u, QString written = {})
        : factor(f), offset(o), unit(std::move(u)), factorWritten(std::move(written)) {}

    double factor = 1.0;
    double offset = 0.0;
    QString unit;
    // The factor as the dictionary or the vendor's rule writes it ("1/1280000" rev per PUU), when
    // that is not the plain number; see factorText().
    QString factorWritten;

    double apply(double raw) const { return raw * factor + offset; }
    bool operator==(const SignalScale&) const = default;
};

// The factor as written ("1/1280000", "0.1", "60/1280000"), never "7.8125e-07".
QString factorText(const SignalScale& scale);
// A factor typed as a number or a fraction ("0.1", "1/1280000"); nullopt when it is neither or 0.
std::optional<double> parseFactor(const QString& text);

// A vendor's counts-per-revolution rule, from the "scaling"."revolution" block of a bundled
// dictionary's sidecar (resources/dictionaries/NAME.json):
//   "revolution": {"countUnit": "PUU", "countsPerRevolution": 1280000,
//                  "multiplyBy": "6093:02", "divideBy": "6093:01"}
// = countsPerRevolution x (6093h:02) / (6093h:01) counts per motor revolution, the parameter
// objects taken as 1 until their values are seen in the trace.
struct RevolutionRule {
    QString countUnit;
    double countsPerRevolution = 0;
    uint16_t multiplyIndex = 0;  // 0 = none
    uint8_t multiplySub = 0;
    uint16_t divideIndex = 0;
    uint8_t divideSub = 0;

    bool dependsOn(uint16_t index, uint8_t sub) const {
        return (index == multiplyIndex && sub == multiplySub) || (index == divideIndex && sub == divideSub);
    }
};
std::optional<RevolutionRule> revolutionRule(const QString& dictionaryName);  // cached, thread safe

// The unit and factor the bundled sidecar's "units" block gives index:sub of a dictionary, for
// dictionaries loaded without their sidecar. Cached, thread safe.
std::optional<SignalScale> sidecarUnit(const QString& dictionaryName, uint16_t index, uint8_t sub);

// Values of parameter objects seen in the trace (6093h:01 ...), nullopt when not seen.
using ParameterLookup = std::function<std::optional<double>(uint16_t index, uint8_t sub)>;

// The engineering scale of an object whose dictionary gives `unit` and `factor` (the sidecar's
// "units"): that scale, except that positions and speeds in a vendor's counts become
// revolutions and rpm when the vendor's rule says how (Delta ASDA-A2: PUU, extract §4.7).
SignalScale engineeringScale(const QString& dictionaryName, const QString& unit, double factor,
                             const ParameterLookup& params = {});

}  // namespace coscope::dissect
