// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QHash>
#include <QString>

#include <cstdint>
#include <vector>

namespace coscope::dissect {

// A vendor alarm table (resources/alarms/NAME.json, schema in resources/README.md): where the
// alarm values sit in the EMCY manufacturer bytes, what they mean, and the vendor's own SDO
// abort codes.
struct VendorTable {
    struct AlarmField {
        QString name;
        int firstByte = 3;   // EMCY byte position
        bool u16 = true;     // u16le, else u8
        int motor = 0;       // 0 = not per motor
    };
    struct Alarm {
        QString code;        // display name, e.g. "AL011"
        QString text;
        int emcyCode = -1;   // CiA code the alarm comes with, -1 = none given
    };
    QString name;
    bool verified = true;    // layout documented by the vendor
    std::vector<AlarmField> fields;
    QHash<uint32_t, Alarm> alarms;     // by "number" (and "alsoNumbers")
    QHash<uint32_t, QString> aborts;   // vendor SDO abort codes

    // Decodes the vendor bytes of an EMCY (8-byte payload); empty when nothing is known.
    // `emcyCode` is used for the plausibility check of unverified layouts.
    QString decodeEmcy(const uint8_t* data, int len, uint16_t emcyCode) const;
};

// The bundled table by name (cached; nullptr when there is none).
const VendorTable* vendorTable(const QString& name);

}  // namespace coscope::dissect
