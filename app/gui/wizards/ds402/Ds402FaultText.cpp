// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/ds402/Ds402FaultText.h"

#include "app/gui/language/CoreText.h"

#include "core/canopen/Emcy.h"
#include "dissectors/VendorTable.h"

#include <QCoreApplication>

namespace coscope::gui {

QString Ds402Fault::text() const {
    //: CiA 402 wizard, a drive fault: %1 = the error code in hex
    QString out = QCoreApplication::translate("Ds402Fault", "Error code (603Fh) %1h")
                      .arg(QStringLiteral("%1").arg(errorCode, 4, 16, QChar(u'0')).toUpper());
    if (!ciaText.isEmpty()) out += QStringLiteral(": ") + coreText(ciaText);  // the CiA 301/402 name in the UI language
    //: CiA 402 wizard, after the error code: %1 = the vendor's alarm code and name ("AL013 Emergency stop")
    if (!vendorAlarm.isEmpty()) out += QCoreApplication::translate("Ds402Fault", " — vendor alarm %1").arg(vendorAlarm);
    return out;
}

Ds402Fault describeDs402Fault(const QString& dictionary, uint16_t errorCode, uint32_t history1003) {
    Ds402Fault f;
    f.errorCode = errorCode;
    f.ciaText = canopen::emcyCodeText(errorCode);
    const dissect::VendorTable* table = dissect::vendorTable(dictionary);
    if (!table) return f;
    // 1003h:01 = (vendor alarm number << 16) | error code (Delta and AIMOTOR manuals; see the
    // tables' historyLayout). Only trusted when its low word is the current error code.
    if (history1003 && (history1003 & 0xFFFF) == errorCode && (history1003 >> 16)) {
        auto it = table->alarms.constFind(history1003 >> 16);
        if (it != table->alarms.constEnd()) {
            f.vendorAlarm = it->code + QStringLiteral(" ") + it->localText();
            return f;
        }
        //: %1 = the vendor alarm number in hex, %2 = the alarm table's name (e.g. delta-asda-a2)
        f.vendorAlarm = QCoreApplication::translate("Ds402Fault", "alarm number 0x%1 (not in the %2 table)")
                            .arg(history1003 >> 16, 4, 16, QChar(u'0'))
                            .arg(table->name);
        return f;
    }
    // Without the history: the alarm whose error code is this one, when only one has it.
    QString only;
    int matches = 0;
    for (auto it = table->alarms.constBegin(); it != table->alarms.constEnd(); ++it)
        if (it->emcyCode == errorCode) {
            const QString t = it->code + QStringLiteral(" ") + it->localText();
            if (t != only) ++matches, only = t;
        }
    if (matches == 1) f.vendorAlarm = only;
    return f;
}

}  // namespace coscope::gui
