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
    int axes = 1;                 // DEXMART DEV: 2 motors
    uint32_t supportedModes = 0;  // 6502h bit mask when the dictionary has no default
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

    // Motion units of the drive model (CiA 402 position units per motor revolution and how the
    // vendor gives speeds and ramps). Delta: PUU, 1280000 x 6093h:02 / 6093h:01 per revolution,
    // homing speeds 6099h in 0.1 rpm (P1-01 = 0Ch), ramps 6083h/6084h/6085h/609Ah as ms from 0
    // to 3000 rpm (extract-delta §3.3, §4.7). AIMOTOR: pulses, 1000 per revolution at the
    // factory gear, everything per second (extract-aimotor §2.5, §6). Generic: the simulator's
    // own 10000 increments per revolution.
    double countsPerRevolution = 10000;
    bool positionFactorScalesRevolution = false;  // Delta: x 6093h:02 / 6093h:01
    bool homingSpeedInDeciRpm = false;
    bool rampsAsTimeTo3000Rpm = false;
    // AIMOTOR homing (extract-aimotor §4.2, §4.7): statusword bit 15 "home found"; H05-35 homing
    // time limit (2005h:24h, ER.601 when exceeded; unit not in the extract, the simulator reads
    // ms, 0 = none); H05-58 homing torque limit of 37/38 (2005h:3Bh, read as 0.1 % like 6077h,
    // 0 = 10 %); halt does not act in homing mode (§4.5 "quick stop and halt do not apply to HM").
    bool homeFoundBit15 = false;
    uint16_t homingTimeLimitIndex = 0;
    uint8_t homingTimeLimitSub = 0;
    uint16_t homingTorqueLimitIndex = 0;
    uint8_t homingTorqueLimitSub = 0;
    bool haltIgnoredInHoming = false;

    // The alarm a plain injectDriveFault() raises.
    VendorAlarm typicalFault;
    // A few documented alarms of the vendor, looked up by name ("AL011", "Er.601").
    std::optional<VendorAlarm> alarm(const QString& name) const;
};

// The dictionaries the simulator can build a device from, and the personality of each.
QStringList simulatableDictionaries();
std::optional<Personality> personalityFor(const QString& dictionaryName, QString* error);

}  // namespace coscope::sim
