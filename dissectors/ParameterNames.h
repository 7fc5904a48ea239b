// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

namespace coscope::dissect {

// Vendor parameters (Delta "P1-01", AIMOTOR "H02-00") named as the Chinese manuals name them
// (bundled sidecars resources/dictionaries/NAME.json, "parameterNames": {"P3-00": {"zh_TW": …,
// "zh_CN": …}}). `edsName` is a dictionary entry's name that starts with the parameter code
// ("P3-00 ADR Node-ID (station number)"); the result keeps the code and the mnemonic and puts
// the Chinese name after them ("P3-00 ADR 局號設定"). Returns `edsName` unchanged for "en", for
// names without a vendor code and for parameters the manuals give no Chinese name for.
QString localParameterName(const QString& edsName, const QString& lang);

}  // namespace coscope::dissect
