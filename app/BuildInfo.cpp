// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/BuildInfo.h"

#include "coscope_revision.h"  // generated on every build: COSCOPE_REVISION

namespace coscope::buildinfo {

QString version() { return QStringLiteral(COSCOPE_VERSION); }

QString revision() { return QStringLiteral(COSCOPE_REVISION); }

QString versionLine(const QString& program) {
    return QStringLiteral("%1 %2 (revision %3)").arg(program, version(), revision());
}

QString applicationId() { return QStringLiteral(COSCOPE_APP_ID); }

}  // namespace coscope::buildinfo
