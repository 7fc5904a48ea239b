// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/NodeSettingsObjects.h"

namespace coscope::canopen {

std::optional<VendorNodeSettings> vendorNodeSettings(const QString& dictionary) {
    VendorNodeSettings s;
    s.dictionary = dictionary;
    if (dictionary == u"delta-asda-a2") {
        // Delta ASDA-A2 manual §1.3.1 (extract-delta §2.3-2.4): P3-00 ADR = node-ID 01h-7Fh at
        // 2300h (INTEGER16, documented); P3-01 BRT at 2301h, digit Z (bits 8-11) = CAN rate
        // 0: 125k, 1: 250k, 2: 500k, 3: 750k, 4: 1M; only digit Z changes when written over CAN.
        // P3-00 carries the "●" mark: takes effect after a power cycle. Every SDO write of a
        // P-parameter goes to EEPROM.
        VendorSettingObject id;
        id.index = 0x2300;
        id.parameter = QStringLiteral("P3-00");
        id.storedOnWrite = true;
        id.takesEffect = TakesEffect::PowerCycle;
        id.source = QStringLiteral("Delta ASDA-A2 manual §1.3.1, P3-00 (\"●\": after power cycle)");
        s.nodeId = id;
        VendorSettingObject br;
        br.index = 0x2301;
        br.parameter = QStringLiteral("P3-01");
        br.mask = 0x0F00;
        br.shift = 8;
        br.bitRates = {125000, 250000, 500000, 750000, 1000000};
        br.storedOnWrite = true;
        br.takesEffect = TakesEffect::PowerCycle;
        br.source = QStringLiteral("Delta ASDA-A2 manual §1.3.1, P3-01 digit Z");
        s.bitRate = br;
        s.note = QStringLiteral(
            "Delta: P-parameters written over CAN are saved to EEPROM at once. "
            "P3-00 takes effect after a power cycle (marked ●).");
        return s;
    }
    if (dictionary == u"aimotor") {
        // AIMOTOR manual [L78] (extract-aimotor §1): "NodeId = 1, 500 kbps; change H0C_00 and
        // H0C-08 with the RS485 host software". H0C-00 -> 200Ch:01 is inferred; H0C-08's value
        // codes are not given, so the bit rate is changed by LSS only. Max 63 stations.
        VendorSettingObject id;
        id.index = 0x200C;
        id.sub = 0x01;
        id.parameter = QStringLiteral("H0C-00");
        id.takesEffect = TakesEffect::PowerCycle;
        id.inferred = true;
        id.source = QStringLiteral("AIMOTOR manual, CAN settings (H0C-00; object 200Ch:01 inferred)");
        s.nodeId = id;
        s.maxNodeId = 63;
        s.note = QStringLiteral(
            "AIMOTOR: the manual sets H0C-00 (node-ID) with the RS485 tool; writing it over CAN "
            "(200Ch:01) is inferred, save with 1010h and power-cycle. The bit-rate codes of "
            "H0C-08 are not documented: use LSS for the bit rate.");
        return s;
    }
    if (dictionary == u"dexmart-dev") {
        // DEXMART DEV (extract-dexmart §8.7): Rev A sets the node-ID with parameter 09-19
        // (3009h:13 in the bundled dictionary, saved to EEPROM); Rev B/C/D with DIP switch SW2.
        // No bit-rate parameter is documented.
        VendorSettingObject id;
        id.index = 0x3009;
        id.sub = 0x13;
        id.parameter = QStringLiteral("09-19");
        id.storedOnWrite = true;
        id.takesEffect = TakesEffect::PowerCycle;
        id.source = QStringLiteral("DEXMART DEV tutorial §8.7 (parameter 09-19, DEV Rev A only)");
        s.nodeId = id;
        s.note = QStringLiteral(
            "DEXMART DEV: parameter 09-19 sets the node-ID on Rev A only; Rev B/C/D use DIP "
            "switch SW2. No bit-rate parameter: use LSS.");
        return s;
    }
    return std::nullopt;
}

std::optional<uint32_t> encodeVendorBitRate(const VendorSettingObject& o, int bitRate, uint32_t current) {
    for (size_t i = 0; i < o.bitRates.size(); ++i)
        if (o.bitRates[i] == bitRate) return (current & ~o.mask) | ((uint32_t(i) << o.shift) & o.mask);
    return std::nullopt;
}

int decodeVendorBitRate(const VendorSettingObject& o, uint32_t value) {
    const uint32_t code = (value & o.mask) >> o.shift;
    return code < o.bitRates.size() ? o.bitRates[code] : 0;
}

QString bitRateText(int bitRate) {
    if (bitRate >= 1000000 && bitRate % 1000000 == 0) return QStringLiteral("%1 Mbit/s").arg(bitRate / 1000000);
    if (bitRate >= 1000) return QStringLiteral("%1 kbit/s").arg(bitRate / 1000.0);
    return QStringLiteral("%1 bit/s").arg(bitRate);
}

}  // namespace coscope::canopen
