// SPDX-License-Identifier: GPL-3.0-or-later
// EMCY (CiA 301 §7.2.7.3.1): COB-ID 080h + node, 8 bytes: error code (LE), error register
// (1001h), 5 manufacturer-specific bytes, decoded with the node's vendor alarm table
// (resources/alarms: Delta alarm number in bytes 3-4, AIMOTOR fault code, DEXMART M1/M2 bytes 6/7).
#include "core/canopen/Emcy.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/Services.h"
#include "dissectors/VendorTable.h"

namespace coscope::dissect {

void dissectEmcy(DissectCall& c) {
    Dissection& out = c.out;
    if (c.frame.isRemote() || c.len < 3) {
        out.warn(QStringLiteral("EMCY with %1 bytes; CiA 301 requires 8").arg(c.len));
        if (out.wantText()) out.summary = QStringLiteral("EMCY (malformed), node %1").arg(c.node);
        return;
    }
    if (c.len != 8) out.warn(QStringLiteral("EMCY with %1 bytes; CiA 301 requires 8").arg(c.len));
    if (!out.wantText()) return;
    const canopen::EmcyMessage m = canopen::parseEmcy(c.data, c.len);
    const QString text = m.code == 0 ? QStringLiteral("Error reset or no error") : canopen::emcyCodeText(m.code);
    const int vendorLen = std::max(0, std::min(c.len, 8) - 3);
    const QString vendorHex = hexBytes(c.data + 3, vendorLen, false);
    QString vendor;
    if (const VendorTable* vt = c.ctx.node(c.node).vendor) vendor = vt->decodeEmcy(c.data, c.len, m.code);
    out.addInt("emcy.code", m.code);
    out.addInt("emcy.reg", m.errorRegister);
    out.addText("emcy.text", text);
    out.addText("emcy.vendor", vendor.isEmpty() ? vendorHex : vendor);
    out.addText("emcy.vendor_bytes", vendorHex);
    out.summary = QStringLiteral("EMCY node %1: %2 %3, register 0x%4")
                      .arg(c.node)
                      .arg(hex(m.code, 4), text)
                      .arg(m.errorRegister, 2, 16, QLatin1Char('0'));
    if (!vendor.isEmpty()) out.summary += QStringLiteral(", ") + vendor;
    if (out.wantTree()) {
        out.item(0, QStringLiteral("Error code"), QStringLiteral("%1 %2").arg(hex(m.code, 4), text), 0, 2);
        out.item(0, QStringLiteral("Error register"), hex(m.errorRegister, 2), 2, 1);
        for (int b = 0; b < 8; ++b)
            if (m.errorRegister & (1 << b))
                out.item(1, QStringLiteral("Bit %1").arg(b), canopen::errorRegisterBits(uint8_t(1u << b)).value(0), 2,
                         1, b, 1);
        out.item(0, QStringLiteral("Manufacturer-specific error field"), hexBytes(c.data + 3, vendorLen, true), 3,
                 vendorLen);
        if (!vendor.isEmpty()) out.item(1, QStringLiteral("Vendor alarm"), vendor, 3, vendorLen);
    }
}

}  // namespace coscope::dissect
