// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/Personality.h"

namespace coscope::sim {

namespace {
// 6502h bits: pp 0, pv 2, pt 3, hm 5, ip 6, csp 7, csv 8, cst 9 (CiA 402-2 §6.4.3).
constexpr uint32_t PP = 1u << 0, PV = 1u << 2, PT = 1u << 3, HM = 1u << 5, IP = 1u << 6, CSP = 1u << 7, CSV = 1u << 8,
                   CST = 1u << 9;

// A few documented alarms per vendor (resources/alarms/*.json, from the manuals' tables).
struct NamedAlarm {
    Vendor vendor;
    const char* name;
    uint16_t emcy;
    uint16_t number;
};
constexpr NamedAlarm kAlarms[] = {
    // Delta ASDA-A2 (extract-delta §6.3): number = hex digits of ALxxx.
    {Vendor::Delta, "AL001", 0x2310, 0x0001},
    {Vendor::Delta, "AL002", 0x3110, 0x0002},
    {Vendor::Delta, "AL009", 0x8611, 0x0009},
    {Vendor::Delta, "AL011", 0x7305, 0x0011},
    {Vendor::Delta, "AL013", 0x5441, 0x0013},
    {Vendor::Delta, "AL401", 0x8100, 0x0401},
    {Vendor::Delta, "AL170", 0x8130, 0x0170},  // heartbeat or node guarding error, servo on
    {Vendor::Delta, "AL180", 0x8130, 0x0180},  // the same, servo off
    // AIMOTOR (extract-aimotor §6b): vendor code in the 1003h high word.
    {Vendor::Aimotor, "Er.201", 0x2312, 0x0201},
    {Vendor::Aimotor, "Er.601", 0x8610, 0x0601},
    {Vendor::Aimotor, "Er.620", 0x3230, 0x0620},
    {Vendor::Aimotor, "Er.668", 0xFF00, 0x0668},  // homing method mismatch
    {Vendor::Aimotor, "Er.B00", 0x8611, 0x0B00},
    {Vendor::Aimotor, "Er.D03", 0x8130, 0x0D03},  // CAN communication interrupted (alarms/aimotor.json)
    // Generic CiA 402 (CiA 402-2 error codes; no vendor number).
    {Vendor::GenericCia402, "overcurrent", 0x2310, 0},
    {Vendor::GenericCia402, "following-error", 0x8611, 0},
    {Vendor::GenericCia402, "encoder", 0x7305, 0},
    // DEXMART DEV: alarm code byte per motor, error code from its EMCY list (extract-dexmart §5).
    {Vendor::Dexmart, "overcurrent", 0x2300, 0x01},
    {Vendor::Dexmart, "overvoltage", 0x3200, 0x02},
};
}  // namespace

std::optional<VendorAlarm> Personality::alarm(const QString& name) const {
    for (const auto& a : kAlarms)
        if (a.vendor == vendor && name.compare(QLatin1String(a.name), Qt::CaseInsensitive) == 0)
            return VendorAlarm{a.emcy, a.number, QString::fromLatin1(a.name)};
    return std::nullopt;
}

QStringList simulatableDictionaries() {
    return {QStringLiteral("delta-asda-a2"), QStringLiteral("aimotor"), QStringLiteral("dexmart-dev"),
            QStringLiteral("generic-cia402")};
}

std::optional<Personality> personalityFor(const QString& name, QString* error) {
    Personality p;
    p.dictionaryName = name;
    if (name == u"delta-asda-a2") {
        p.vendor = Vendor::Delta;
        p.supportedModes = PP | PV | PT | HM | IP;  // extract-delta §4.4
        p.controlModeIndex = 0x2101;                // P1-01 = 0Ch standard CANopen
        p.controlModeValue = 0x0C;
        p.alarmOnResetWhileEnabled = true;
        p.parametersStoredOnWrite = true;
        p.typicalFault = *p.alarm(QStringLiteral("AL011"));
        p.countsPerRevolution = 1280000;
        p.positionFactorScalesRevolution = true;
        p.homingSpeedInDeciRpm = true;
        p.rampsAsTimeTo3000Rpm = true;
    } else if (name == u"aimotor") {
        p.vendor = Vendor::Aimotor;
        p.supportedModes = PP | PV | PT | HM | CSP | CSV | CST;  // extract-aimotor §4
        p.controlModeIndex = 0x2002;                             // H02-00 = 8 CANopen control
        p.controlModeSub = 0x01;
        p.controlModeValue = 8;
        p.typicalFault = *p.alarm(QStringLiteral("Er.201"));
        p.countsPerRevolution = 1000;
        p.homeFoundBit15 = true;
        p.homingTimeLimitIndex = 0x2005;  // H05-35
        p.homingTimeLimitSub = 0x24;
        p.homingTorqueLimitIndex = 0x2005;  // H05-58
        p.homingTorqueLimitSub = 0x3B;
        p.haltIgnoredInHoming = true;
    } else if (name == u"dexmart-dev") {
        p.vendor = Vendor::Dexmart;
        p.cia402 = false;
        p.axes = 2;
        p.alarmU8PerMotor = true;
        p.tpdoFeAnswersRpdo = true;
        p.typicalFault = *p.alarm(QStringLiteral("overcurrent"));
    } else if (name == u"generic-cia402") {
        p.vendor = Vendor::GenericCia402;
        p.supportedModes = PP | PV | PT | HM | IP | CSP | CSV | CST;
        p.typicalFault = *p.alarm(QStringLiteral("overcurrent"));
    } else if (name == u"icpdas-ecat-2094p") {
        if (error)
            *error = QStringLiteral(
                "icpdas-ecat-2094p is an EtherCAT device: it is bundled for offline reference and cannot be simulated "
                "on CAN");
        return std::nullopt;
    } else {
        if (error)
            *error = QStringLiteral("unknown virtual drive '%1'; known: %2")
                         .arg(name, simulatableDictionaries().join(QStringLiteral(", ")));
        return std::nullopt;
    }
    p.nodeSettings = canopen::vendorNodeSettings(name);
    if (p.nodeSettings && p.nodeSettings->nodeId) {
        p.nodeIdIndex = p.nodeSettings->nodeId->index;
        p.nodeIdSub = p.nodeSettings->nodeId->sub;
    }
    if (p.nodeSettings && p.nodeSettings->bitRate) {
        p.bitRateIndex = p.nodeSettings->bitRate->index;
        p.bitRateSub = p.nodeSettings->bitRate->sub;
    }
    return p;
}

}  // namespace coscope::sim
