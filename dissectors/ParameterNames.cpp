// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/ParameterNames.h"

#include "dissectors/SidecarNames.h"

#include <QRegularExpression>

namespace coscope::dissect {

QString localParameterName(const QString& edsName, const QString& lang) {
    if (lang != u"zh_TW" && lang != u"zh_CN") return edsName;
    // "P3-00 ADR Node-ID …" (Delta: code, mnemonic in capitals, text) or "H02-00 Control mode …".
    static const QRegularExpression code(
        QStringLiteral(R"(^((?:P\d-\d\d|H[0-9A-F]{2}-\d\d)(?: [A-Z][A-Z0-9]+(?= ))?) )"));
    const QRegularExpressionMatch m = code.match(edsName);
    if (!m.hasMatch()) return edsName;
    const QString key = edsName.left(edsName.indexOf(u' '));
    for (const SidecarSection& names : sidecarSections(QStringLiteral("parameterNames"))) {
        const auto it = names.constFind(key);
        if (it == names.constEnd()) continue;
        const QString zh = it->value(lang).toString();
        return zh.isEmpty() ? edsName : m.captured(1) + u' ' + zh;
    }
    return edsName;
}

}  // namespace coscope::dissect
