// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/NodeSettingsObjects.h"

#include <QString>
#include <QStringList>

#include <cstdint>
#include <optional>

namespace coscope::sim {

// Vendor behaviour of a virtual device, keyed by the bundled dictionary's name (the sidecar's
// "personality": delta, aimotor, dexmart, cia402). Facts from shared/seeds/extract-*.md.
enum class Vendor : uint8_t { GenericCia402, Delta, Aimotor, Dexmart };

// A vendor alarm as the virtual drive raises it: EMCY error code (= 603Fh), the vendor's alarm
// number as carried in the EMCY manufacturer bytes, and a display name.
struct VendorAlarm {
    uint16_t emcyCode = 0;
    uint16_t number = 0;
    QString name;
};

struct Personality {
    Vendor vendor = Vendor::GenericCia402;
    QString dictionaryName;
    bool cia402 = true;
    int axes = 1;                  // DEXMART DEV: 2 motors
    uint32_t supportedModes = 0;   // 6502h bit mask when the dictionary has no default
    uint32_t defaultBitRate = 500000;

    // Where the node-ID and bit rate live besides LSS (canopen::vendorNodeSettings, the one
    // source: Delta P3-00/P3-01, AIMOTOR H0C-00, DEXMART 09-19); the fields below repeat its
    // indexes. Zero index = none.
    std::optional<canopen::VendorNodeSettings> nodeSettings;
    uint16_t nodeIdIndex = 0;
    uint8_t nodeIdSub = 0;
    uint16_t bitRateIndex = 0;
    uint8_t bitRateSub = 0;
    // The control-mode parameter that must hold `controlModeValue` for CiA 402 objects to act
    // (Delta P1-01 = 0Ch, 2101h; AIMOTOR H02-00 = 8, 2002h:01). The virtual drive starts with it
    // set, as a commissioned drive would be.
    uint16_t controlModeIndex = 0;
    uint8_t controlModeSub = 0;
    int64_t controlModeValue = 0;

    // Where the vendor alarm number goes in the EMCY frame: bytes 3-4 u16le (Delta, AIMOTOR), or
    // byte 6 + motor (DEXMART: 6 = M1, 7 = M2, u8).
    bool alarmU8PerMotor = false;
    // Delta: NMT Reset Node while the servo is on raises AL401 (EMCY 8100h) (extract-delta §1).
    bool alarmOnResetWhileEnabled = false;
    // Delta: every SDO write of a P-parameter (2000h-2FFFh) goes to EEPROM at once.
    bool parametersStoredOnWrite = false;

    // DEXMART: a TPDO of type FEh is sent when the RPDO of the same number arrives, and its
    // event timer has no function (extract-dexmart §4.2-4.3, a deviation from CiA 301).
    bool tpdoFeAnswersRpdo = false;

    // The alarm a plain injectDriveFault() raises.
    VendorAlarm typicalFault;
    // A few documented alarms of the vendor, looked up by name ("AL011", "Er.601").
    std::optional<VendorAlarm> alarm(const QString& name) const;
};

// The dictionaries the simulator can build a device from, and the personality of each.
QStringList simulatableDictionaries();
std::optional<Personality> personalityFor(const QString& dictionaryName, QString* error);

}  // namespace coscope::sim
