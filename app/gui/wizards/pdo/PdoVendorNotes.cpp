// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/wizards/pdo/PdoVendorNotes.h"

#include "core/od/NumberNotation.h"

#include <QCoreApplication>

namespace coscope::gui {

QStringList pdoVendorNotes(const QString& dictionaryName, const canopen::PdoId& pdo) {
    QStringList notes;
    // Facts from shared/seeds/extract-delta-asda-a2.md §1, §2 and §5.
    if (dictionaryName == u"delta-asda-a2") {
        notes << QCoreApplication::translate(
                     "PdoVendorNotes",
                     "Delta ASDA-A2: the drive speaks standard CANopen only when P1-01 (2101h) = 0x0C; check it first.")
              << QCoreApplication::translate(
                     "PdoVendorNotes",
                     "Delta writes every P-parameter (2000h–2FFFh) to EEPROM on each SDO write; P-parameters written "
                     "by PDO are stored only when P3-11 X = 1 (wears the EEPROM).")
              << QCoreApplication::translate(
                     "PdoVendorNotes",
                     "At most 8 objects per PDO. Two PDOs with the same COB-ID within 1 ms raise alarm AL112.");
        if (!pdo.transmit)
            notes << QCoreApplication::translate(
                "PdoVendorNotes",
                "RPDOs with a transmission type 0–240 act at the next SYNC: the master must send SYNC every cycle.");
    } else if (dictionaryName == u"aimotor") {
        // extract-aimotor.md §3.6, §5.
        notes << QCoreApplication::translate(
                     "PdoVendorNotes",
                     "AIMOTOR: CiA 402 objects act only when H02-00 (2002h:01) = 8 (CANopen control).")
              << QCoreApplication::translate(
                     "PdoVendorNotes",
                     "AIMOTOR's default PDOs are synchronous (type 1): they are sent or applied only when a SYNC "
                     "arrives. Start a SYNC producer, or choose an event-driven type.")
              << QCoreApplication::translate(
                     "PdoVendorNotes", "Only CiA 402 objects (6000h–6FFFh) can be mapped; at most 8 objects per PDO.");
    } else if (dictionaryName == u"dexmart-dev") {
        // extract-dexmart-dev-canopen-intro.md §4.6, §4.7, §8.4.
        notes << QCoreApplication::translate("PdoVendorNotes",
                                             "DEXMART DEV: the COB-ID is read-only, so a PDO cannot be switched off "
                                             "while it is remapped: the mapping changes while the message is in use.")
              << QCoreApplication::translate("PdoVendorNotes",
                                             "At most 8 objects per PDO. The power-on mapping comes from parameter "
                                             "09-26; a change made here is lost at power-off unless stored.")
              << QCoreApplication::translate(
                     "PdoVendorNotes",
                     "Two motors: the M1/M2 values live in the Multi-Drive objects (3046h status, 3051h commands).");
    } else if (dictionaryName.isEmpty()) {
        notes << QCoreApplication::translate("PdoVendorNotes",
                                             "No dictionary is known for this node: objects cannot be offered by name. "
                                             "Scan the node (Nodes dock) or assign a dictionary first.");
    }
    return notes;
}

QString pdoFailureAdvice(uint32_t abortCode, bool timedOut, const QString& dictionaryName) {
    if (timedOut || abortCode == 0x05040000u)
        return QCoreApplication::translate("PdoVendorNotes",
                                           "The drive did not answer in time. Check that it is powered, that its "
                                           "node-ID is right, and the cable, termination and bit rate.");
    switch (abortCode) {
    case 0x06040041u:  // CiA 301 §7.2.4.3.17 abort codes
        return QCoreApplication::translate("PdoVendorNotes",
                                           "The drive does not allow this object in a PDO. Take another object, or "
                                           "check the manual's \"PDO\" column for it.");
    case 0x06040042u:
        return QCoreApplication::translate("PdoVendorNotes",
                                           "Too much data for one PDO on this drive: use fewer objects or smaller ones "
                                           "(at most 64 bits; some drives allow at most 8 objects).");
    case 0x06040043u:
    case 0x06040047u:
        return QCoreApplication::translate("PdoVendorNotes",
                                           "The drive reports a general parameter incompatibility: check that the PDO "
                                           "number exists and the values fit together.");
    case 0x06010002u:
        return QCoreApplication::translate(
            "PdoVendorNotes",
            "This parameter is read-only on this drive (some drives fix the COB-ID). Keep the current value.");
    case 0x06020000u:
        return QCoreApplication::translate("PdoVendorNotes",
                                           "The drive does not have this object: this PDO number may not exist on it.");
    case 0x06090030u:
    case 0x06090031u:
    case 0x06090032u:
    case 0x06070010u:
        return QCoreApplication::translate(
            "PdoVendorNotes",
            "The drive refused the value: check the allowed range (transmission type, inhibit time, event timer).");
    case 0x08000020u:
    case 0x08000021u:
    case 0x08000022u: {
        QString s = QCoreApplication::translate("PdoVendorNotes",
                                                "The drive does not accept this in its present state. It must be "
                                                "pre-operational (the wizard sends that first)");
        if (dictionaryName == u"delta-asda-a2") s += QStringLiteral("; on Delta check P1-01 = 0x0C");
        if (dictionaryName == u"aimotor") s += QStringLiteral("; on AIMOTOR check H02-00 = 8");
        return s + QLatin1Char('.');
    }
    default: break;
    }
    if (abortCode)
        return QCoreApplication::translate("PdoVendorNotes", "Look up abort code 0x%1 in the drive's manual.")
            .arg(abortCode, 8, 16, QChar(u'0'));
    return QCoreApplication::translate("PdoVendorNotes",
                                       "The values read back differ from those written: the drive may have adjusted or "
                                       "ignored one. Read the PDO again and compare.");
}

QString transmissionTypeText(uint8_t type, bool transmit) {
    // CiA 301 §7.2.2.2 and the 1400h/1800h sub 2 value table.
    if (type == 0)
        return transmit
                   ? QCoreApplication::translate(
                         "PdoVendorNotes", "Sent at the next SYNC after a value changed (synchronous acyclic, type 0)")
                   : QCoreApplication::translate("PdoVendorNotes", "Applied at the next SYNC (synchronous, type 0)");
    if (type == 1)
        return transmit
                   ? QCoreApplication::translate("PdoVendorNotes", "Sent on every SYNC (synchronous cyclic, type 1)")
                   : QCoreApplication::translate("PdoVendorNotes", "Applied at the next SYNC (synchronous, type 1)");
    if (type <= 240)
        return transmit
                   ? QCoreApplication::translate("PdoVendorNotes",
                                                 "Sent once every %1 SYNCs (synchronous cyclic, type %1)")
                         .arg(type)
                   : QCoreApplication::translate("PdoVendorNotes", "Applied at the next SYNC (synchronous, type %1)")
                         .arg(type);
    if (type == 252)
        return QCoreApplication::translate(
            "PdoVendorNotes", "Sampled at SYNC, sent only when asked for (RTR-only synchronous, type 252)");
    if (type == 253)
        return QCoreApplication::translate("PdoVendorNotes",
                                           "Sent only when asked for (RTR-only event-driven, type 253)");
    if (type == 254 || type == 255)
        return transmit ? QCoreApplication::translate(
                              "PdoVendorNotes",
                              "Sent when a value changes and/or every event-timer period (event-driven, type %1)")
                              .arg(od::hexText(type, 2))
                        : QCoreApplication::translate("PdoVendorNotes",
                                                      "Applied as soon as it arrives (event-driven, type %1)")
                              .arg(od::hexText(type, 2));
    return QCoreApplication::translate("PdoVendorNotes", "Reserved transmission type %1").arg(type);
}

}  // namespace coscope::gui
