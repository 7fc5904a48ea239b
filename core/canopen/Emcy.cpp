// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/Emcy.h"

#include <cstring>

namespace coscope::canopen {

EmcyMessage parseEmcy(const uint8_t* data, int len) {
    uint8_t b[8] = {};
    std::memcpy(b, data, static_cast<size_t>(std::clamp(len, 0, 8)));
    EmcyMessage m;
    m.code = static_cast<uint16_t>(b[0] | (b[1] << 8));
    m.errorRegister = b[2];
    std::memcpy(m.vendor, b + 3, 5);
    return m;
}

QString emcyCodeText(uint16_t code) {
    // Specific codes: CiA 301 Table 21 (communication) and CiA 402 Annex (drives).
    switch (code) {
    case 0x0000: return QStringLiteral("Error reset or no error");
    case 0x1000: return QStringLiteral("Generic error");
    case 0x2310: return QStringLiteral("Continuous over-current");
    case 0x2320: return QStringLiteral("Short circuit / earth leakage");
    case 0x3110: return QStringLiteral("Mains over-voltage");
    case 0x3120: return QStringLiteral("Mains under-voltage");
    case 0x3210: return QStringLiteral("DC link over-voltage");
    case 0x3220: return QStringLiteral("DC link under-voltage");
    case 0x4210: return QStringLiteral("Excess temperature device");
    case 0x4310: return QStringLiteral("Excess temperature drive");
    case 0x5530: return QStringLiteral("Data storage error (EEPROM)");
    case 0x6100: return QStringLiteral("Internal software error");
    case 0x7121: return QStringLiteral("Motor blocked");
    case 0x7305: return QStringLiteral("Incremental sensor 1 fault");
    case 0x8110: return QStringLiteral("CAN overrun (objects lost)");
    case 0x8120: return QStringLiteral("CAN in error passive mode");
    case 0x8130: return QStringLiteral("Life guard error or heartbeat error");
    case 0x8140: return QStringLiteral("Recovered from bus off");
    case 0x8150: return QStringLiteral("CAN-ID collision");
    case 0x8210: return QStringLiteral("PDO not processed due to length error");
    case 0x8220: return QStringLiteral("PDO length exceeded");
    case 0x8230: return QStringLiteral("DAM MPDO not processed, destination object not available");
    case 0x8240: return QStringLiteral("Unexpected SYNC data length");
    case 0x8250: return QStringLiteral("RPDO timeout");
    case 0x8611: return QStringLiteral("Following error");
    case 0x8612: return QStringLiteral("Reference limit");
    default: break;
    }
    switch (code >> 8) {
    case 0x00: return QStringLiteral("Error reset or no error");
    case 0x10: return QStringLiteral("Generic error");
    case 0x20: return QStringLiteral("Current");
    case 0x21: return QStringLiteral("Current, device input side");
    case 0x22: return QStringLiteral("Current inside the device");
    case 0x23: return QStringLiteral("Current, device output side");
    case 0x30: return QStringLiteral("Voltage");
    case 0x31: return QStringLiteral("Mains voltage");
    case 0x32: return QStringLiteral("Voltage inside the device");
    case 0x33: return QStringLiteral("Output voltage");
    case 0x40: return QStringLiteral("Temperature");
    case 0x41: return QStringLiteral("Ambient temperature");
    case 0x42: return QStringLiteral("Device temperature");
    case 0x50: return QStringLiteral("Device hardware");
    case 0x60: return QStringLiteral("Device software");
    case 0x61: return QStringLiteral("Internal software");
    case 0x62: return QStringLiteral("User software");
    case 0x63: return QStringLiteral("Data set");
    case 0x70: return QStringLiteral("Additional modules");
    case 0x80: return QStringLiteral("Monitoring");
    case 0x81: return QStringLiteral("Communication");
    case 0x82: return QStringLiteral("Protocol error");
    case 0x90: return QStringLiteral("External error");
    case 0xF0: return QStringLiteral("Additional functions");
    case 0xFF: return QStringLiteral("Device specific");
    default: break;
    }
    switch (code >> 12) {
    case 0x2: return QStringLiteral("Current");
    case 0x3: return QStringLiteral("Voltage");
    case 0x4: return QStringLiteral("Temperature");
    case 0x5: return QStringLiteral("Device hardware");
    case 0x6: return QStringLiteral("Device software");
    case 0x7: return QStringLiteral("Additional modules");
    case 0x8: return QStringLiteral("Monitoring");
    case 0x9: return QStringLiteral("External error");
    default: return QStringLiteral("Unknown error code");
    }
}

QStringList errorRegisterBits(uint8_t reg) {
    static const char* names[8] = {"generic error",
                                   "current",
                                   "voltage",
                                   "temperature",
                                   "communication error",
                                   "device profile specific",
                                   "reserved",
                                   "manufacturer specific"};
    QStringList out;
    for (int i = 0; i < 8; ++i)
        if (reg & (1u << i)) out << QString::fromLatin1(names[i]);
    return out;
}

}  // namespace coscope::canopen
