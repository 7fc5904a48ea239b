// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QHash>
#include <QJsonObject>
#include <QString>

namespace coscope::dissect {

// The names in the bundled dictionaries' sidecars (resources/dictionaries/NAME.json), one
// section of each: "objectNames" ("6041" / "1018:01" -> {"zh_TW": …, "zh_CN": …}) or
// "parameterNames" ("P3-00" -> {…}). Read from the resources once per section; any thread.
using SidecarSection = QHash<QString, QJsonObject>;
using SidecarSections = QHash<QString, SidecarSection>;  // dictionary NAME -> its section
const SidecarSections& sidecarSections(const QString& section);

}  // namespace coscope::dissect
