// SPDX-License-Identifier: GPL-3.0-or-later
#include "eds/Diagnostic.h"

namespace coscope::eds {

QString Diagnostic::toString() const {
    const QString sev = severity == Severity::Error ? QStringLiteral("error") : QStringLiteral("warning");
    if (line > 0) return QStringLiteral("%1:%2: %3: %4").arg(file).arg(line).arg(sev, message);
    return QStringLiteral("%1: %2: %3").arg(file, sev, message);
}

}  // namespace coscope::eds
