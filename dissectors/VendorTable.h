// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QHash>
#include <QString>

#include <cstdint>
#include <vector>

namespace coscope::dissect {

// The language of the vendor texts the dissectors write (alarm names in EMCY summaries, the
// CiA 402 wizard's fault line): "en" unless the GUI sets its UI language. The CLI never sets it,
// so its output stays English.
void setVendorTextLanguage(const QString& lang);
QString vendorTextLanguage();

// A vendor alarm table (resources/alarms/NAME.json, schema in resources/README.md): where the
// alarm values sit in the EMCY manufacturer bytes, what they mean, and the vendor's own SDO
// abort codes.
struct VendorTable {
    struct AlarmField {
        QString name;
        int firstByte = 3;  // EMCY byte position
        bool u16 = true;    // u16le, else u8
        int motor = 0;      // 0 = not per motor
    };
    struct Alarm {
        QString code;       // display name, e.g. "AL011"
        QString text;       // English
        QString textZhTW;   // the manual's own name in Traditional Chinese ("name_zh_TW"), may be empty
        QString textZhCN;   // ... in Simplified Chinese ("name_zh_CN"), may be empty
        int emcyCode = -1;  // CiA code the alarm comes with, -1 = none given
        // The name in `lang` ("zh_TW", "zh_CN"; anything else = English), English when the table has none.
        QString textIn(const QString& lang) const;
        // The name in vendorTextLanguage().
        QString localText() const { return textIn(vendorTextLanguage()); }
    };
    QString name;
    bool verified = true;  // layout documented by the vendor
    std::vector<AlarmField> fields;
    QHash<uint32_t, Alarm> alarms;    // by "number" (and "alsoNumbers")
    QHash<uint32_t, QString> aborts;  // vendor SDO abort codes

    // Decodes the vendor bytes of an EMCY (8-byte payload); empty when nothing is known.
    // `emcyCode` is used for the plausibility check of unverified layouts.
    QString decodeEmcy(const uint8_t* data, int len, uint16_t emcyCode) const;
};

// The bundled table by name (cached; nullptr when there is none).
const VendorTable* vendorTable(const QString& name);

}  // namespace coscope::dissect
