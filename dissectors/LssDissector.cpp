// SPDX-License-Identifier: GPL-3.0-or-later
// LSS (CiA 305 §4): master -> slave on 7E5h, slave -> master on 7E4h, 8 bytes, byte 0 the
// command specifier; identity values are 32-bit little-endian in bytes 1-4.
#include "core/canopen/Lss.h"
#include "dissectors/Services.h"

namespace coscope::dissect {

void dissectLss(DissectCall& c) {
    Dissection& out = c.out;
    out.node = -1;
    const bool fromMaster = out.service == canopen::Service::LssRequest;
    if (c.frame.isRemote() || c.len < 1) {
        out.warn(QStringLiteral("LSS frame with %1 bytes; CiA 305 requires 8").arg(c.len));
        if (out.wantText()) out.summary = QStringLiteral("LSS (malformed)");
        return;
    }
    if (c.len != 8) out.warn(QStringLiteral("LSS frame with %1 bytes; CiA 305 requires 8").arg(c.len));
    if (!out.wantText()) return;
    uint8_t d[8] = {};
    for (int i = 0; i < c.len && i < 8; ++i) d[i] = c.data[i];
    const uint8_t cs = d[0];
    const uint32_t value = d[1] | (d[2] << 8) | (d[3] << 16) | (uint32_t(d[4]) << 24);
    const QString name = canopen::lssCommandName(cs, fromMaster);
    out.addInt("lss.cs", cs);
    out.summary = QStringLiteral("LSS %1").arg(name);
    namespace l = canopen::lss;
    switch (cs) {
    case l::SwitchStateGlobal:
        if (fromMaster) out.summary += d[1] ? QStringLiteral(": configuration") : QStringLiteral(": waiting");
        break;
    case l::ConfigureNodeId:
        if (fromMaster) {
            out.addInt("lss.node", d[1]);
            out.summary += QStringLiteral(": node-ID %1").arg(d[1]);
        } else {
            out.summary += d[1] ? QStringLiteral(": error %1").arg(d[1]) : QStringLiteral(": ok");
        }
        break;
    case l::ConfigureBitTiming:
        if (fromMaster) {
            const int rate = d[1] == 0 ? canopen::lssBitRate(d[2]) : -1;
            out.summary += rate > 0 ? QStringLiteral(": %1 kbit/s").arg(rate / 1000)
                                    : QStringLiteral(": table %1 index %2").arg(d[1]).arg(d[2]);
        } else {
            out.summary += d[1] ? QStringLiteral(": error %1").arg(d[1]) : QStringLiteral(": ok");
        }
        break;
    case l::ActivateBitTiming: out.summary += QStringLiteral(": delay %1 ms").arg(d[1] | (d[2] << 8)); break;
    case l::StoreConfiguration:
        if (!fromMaster) out.summary += d[1] ? QStringLiteral(": error %1").arg(d[1]) : QStringLiteral(": ok");
        break;
    case l::InquireNodeId:
        if (!fromMaster) {
            out.addInt("lss.node", d[1]);
            out.summary += QStringLiteral(": %1").arg(d[1]);
        }
        break;
    case l::SwitchSelectiveVendor:
    case l::SwitchSelectiveProduct:
    case l::SwitchSelectiveRevision:
    case l::SwitchSelectiveSerial:
    case l::IdentifyVendor:
    case l::IdentifyProduct:
    case l::IdentifyRevisionLow:
    case l::IdentifyRevisionHigh:
    case l::IdentifySerialLow:
    case l::IdentifySerialHigh:
        if (fromMaster) {
            out.addInt("lss.value", value);
            out.summary += QStringLiteral(": %1").arg(hex(value, 8));
        }
        break;
    case l::InquireVendor:
    case l::InquireProduct:
    case l::InquireRevision:
    case l::InquireSerial:
        if (!fromMaster) {
            out.addInt("lss.value", value);
            out.summary += QStringLiteral(": %1").arg(hex(value, 8));
        }
        break;
    case l::Fastscan:
        if (fromMaster) {
            out.addInt("lss.value", value);
            out.summary += QStringLiteral(": IDNumber %1, bit %2, sub %3, next %4")
                               .arg(hex(value, 8))
                               .arg(d[5])
                               .arg(d[6])
                               .arg(d[7]);
        }
        break;
    default: break;
    }
    if (out.wantTree()) {
        out.item(0, QStringLiteral("Command specifier"),
                 QStringLiteral("%1 (0x%2)").arg(name).arg(cs, 2, 16, QLatin1Char('0')), 0, 1);
        out.item(0, QStringLiteral("Data"), hexBytes(d + 1, std::max(0, std::min(c.len, 8) - 1), true), 1,
                 std::max(0, std::min(c.len, 8) - 1));
    }
}

}  // namespace coscope::dissect
