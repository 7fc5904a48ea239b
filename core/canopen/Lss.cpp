// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/Lss.h"

namespace coscope::canopen {

QString lssCommandName(uint8_t cs, bool fromMaster) {
    using namespace lss;
    switch (cs) {
    case SwitchStateGlobal: return QStringLiteral("Switch state global");
    case SwitchSelectiveVendor: return QStringLiteral("Switch state selective: vendor-ID");
    case SwitchSelectiveProduct: return QStringLiteral("Switch state selective: product code");
    case SwitchSelectiveRevision: return QStringLiteral("Switch state selective: revision number");
    case SwitchSelectiveSerial: return QStringLiteral("Switch state selective: serial number");
    case SwitchSelectiveResponse: return QStringLiteral("Switch state selective response");
    case ConfigureNodeId:
        return fromMaster ? QStringLiteral("Configure node-ID") : QStringLiteral("Configure node-ID response");
    case ConfigureBitTiming:
        return fromMaster ? QStringLiteral("Configure bit timing") : QStringLiteral("Configure bit timing response");
    case ActivateBitTiming: return QStringLiteral("Activate bit timing");
    case StoreConfiguration:
        return fromMaster ? QStringLiteral("Store configuration") : QStringLiteral("Store configuration response");
    case InquireVendor: return fromMaster ? QStringLiteral("Inquire vendor-ID") : QStringLiteral("Vendor-ID");
    case InquireProduct: return fromMaster ? QStringLiteral("Inquire product code") : QStringLiteral("Product code");
    case InquireRevision:
        return fromMaster ? QStringLiteral("Inquire revision number") : QStringLiteral("Revision number");
    case InquireSerial: return fromMaster ? QStringLiteral("Inquire serial number") : QStringLiteral("Serial number");
    case InquireNodeId: return fromMaster ? QStringLiteral("Inquire node-ID") : QStringLiteral("Node-ID");
    case IdentifyVendor: return QStringLiteral("Identify remote slave: vendor-ID");
    case IdentifyProduct: return QStringLiteral("Identify remote slave: product code");
    case IdentifyRevisionLow: return QStringLiteral("Identify remote slave: revision low");
    case IdentifyRevisionHigh: return QStringLiteral("Identify remote slave: revision high");
    case IdentifySerialLow: return QStringLiteral("Identify remote slave: serial low");
    case IdentifySerialHigh: return QStringLiteral("Identify remote slave: serial high");
    case IdentifyNonConfigured: return QStringLiteral("Identify non-configured remote slave");
    case IdentifySlaveResponse: return QStringLiteral("Identify slave");
    case IdentifyNonConfiguredResponse: return QStringLiteral("Identify non-configured slave");
    case Fastscan: return QStringLiteral("Fastscan");
    default: return QStringLiteral("Unknown LSS command 0x%1").arg(cs, 2, 16, QLatin1Char('0'));
    }
}

int lssBitRate(uint8_t i) {
    static const int table[] = {1000000, 800000, 500000, 250000, 125000, 100000, 50000, 20000, 10000, 0};
    return i < std::size(table) ? table[i] : -1;
}

int lssTableIndexForBitRate(int bitRate) {
    for (uint8_t i = 0; i < 9; ++i)
        if (lssBitRate(i) == bitRate) return i;
    return -1;
}

}  // namespace coscope::canopen
