// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/trace/FrameDecoder.h"

#include "app/gui/language/CoreText.h"

#include "core/canopen/CobId.h"
#include "core/canopen/Emcy.h"
#include "core/canopen/Lss.h"
#include "core/canopen/Nmt.h"
#include "core/canopen/Sdo.h"
#include "core/canopen/SdoAbort.h"

#include <QCoreApplication>

namespace coscope::gui {
namespace {

using canopen::Service;
using dissect::Dissection;
using dissect::hex;

QString objRef(uint16_t index, uint8_t sub) {
    return QStringLiteral("%1:%2").arg(index, 4, 16, QLatin1Char('0')).arg(sub, 2, 16, QLatin1Char('0')).toUpper();
}

uint32_t littleEndian(const QByteArray& b) {
    uint32_t v = 0;
    for (int i = 0; i < b.size() && i < 4; ++i) v |= static_cast<uint32_t>(static_cast<uint8_t>(b[i])) << (8 * i);
    return v;
}

// NMT node control (CiA 301 §7.2.8.3.1): byte 0 command specifier, byte 1 node-ID.
void decodeNmt(const CanFrame& f, Dissection& d) {
    if (f.len < 2) {
        d.summary = QCoreApplication::translate("FrameDecoder", "NMT (short frame)");
        d.warn(QCoreApplication::translate("FrameDecoder", "NMT frame must carry 2 bytes"));
        return;
    }
    const uint8_t cs = f.data[0], node = f.data[1];
    d.addUInt("nmt.cs", cs);
    d.addUInt("nmt.node", node);
    const QString target = node == 0 ? QCoreApplication::translate("FrameDecoder", "all nodes")
                                     : QCoreApplication::translate("FrameDecoder", "node %1").arg(node);
    d.summary = QStringLiteral("NMT %1 → %2").arg(coreText(canopen::nmtCommandName(cs)), target);
    if (d.wantTree()) {
        d.item(0, QCoreApplication::translate("FrameDecoder", "NMT node control"), {}, 0, 2);
        d.item(1, QCoreApplication::translate("FrameDecoder", "Command specifier"),
               QStringLiteral("%1 (%2)").arg(hex(cs, 2), coreText(canopen::nmtCommandName(cs))), 0, 1);
        d.item(1, QCoreApplication::translate("FrameDecoder", "Node-ID"),
               node == 0 ? QCoreApplication::translate("FrameDecoder", "0 (all)") : QString::number(node), 1, 1);
    }
}

// Boot-up / heartbeat / node guarding (CiA 301 §7.2.8.3.2): byte 0 = toggle bit 7 + state.
void decodeErrorControl(const CanFrame& f, Dissection& d) {
    if (f.isRemote()) {
        d.addBool("nmt.rtr", true);
        d.summary = QCoreApplication::translate("FrameDecoder", "Node guarding request to node %1").arg(d.node);
        if (d.wantTree()) d.item(0, QCoreApplication::translate("FrameDecoder", "Node guarding request (RTR)"), {});
        return;
    }
    if (f.len < 1) {
        d.summary = QCoreApplication::translate("FrameDecoder", "NMT error control (empty)");
        d.warn(QCoreApplication::translate("FrameDecoder", "error control frame without state byte"));
        return;
    }
    const uint8_t state = f.data[0] & 0x7F;
    d.addUInt("nmt.state", state);
    d.summary = state == 0 ? QCoreApplication::translate("FrameDecoder", "Boot-up node %1").arg(d.node)
                           : QCoreApplication::translate("FrameDecoder", "Heartbeat node %1: %2")
                                 .arg(d.node)
                                 .arg(coreText(canopen::nmtStateName(state)));
    if (d.wantTree()) {
        d.item(0,
               state == 0 ? QCoreApplication::translate("FrameDecoder", "Boot-up")
                          : QCoreApplication::translate("FrameDecoder", "Heartbeat / guarding"),
               {}, 0, 1);
        d.item(1, QCoreApplication::translate("FrameDecoder", "Toggle"), QString::number(f.data[0] >> 7), 0, 1, 7, 1);
        d.item(1, QCoreApplication::translate("FrameDecoder", "NMT state"),
               QStringLiteral("%1 (%2)").arg(state).arg(coreText(canopen::nmtStateName(state))), 0, 1, 0, 7);
    }
}

// EMCY (CiA 301 §7.2.7.3.1).
void decodeEmcy(const CanFrame& f, Dissection& d) {
    const auto m = canopen::parseEmcy(f.data.data(), f.len);
    const QString text = canopen::emcyCodeText(m.code);
    d.addUInt("emcy.code", m.code);
    d.addUInt("emcy.reg", m.errorRegister);
    d.addText("emcy.text", text);
    const QString vendor = dissect::hexBytes(m.vendor, 5, true);
    d.addText("emcy.vendor_bytes", vendor);
    d.summary = m.code == 0 ? QCoreApplication::translate("FrameDecoder", "EMCY node %1: error reset").arg(d.node)
                            : QCoreApplication::translate("FrameDecoder", "EMCY node %1: %2 %3, reg %4")
                                  .arg(d.node)
                                  .arg(hex(m.code, 4), text, hex(m.errorRegister, 2));
    if (f.len < 8) d.warn(QCoreApplication::translate("FrameDecoder", "EMCY frame shorter than 8 bytes"));
    if (d.wantTree()) {
        d.item(0, QCoreApplication::translate("FrameDecoder", "Emergency"), {}, 0, f.len);
        d.item(1, QCoreApplication::translate("FrameDecoder", "Error code"),
               QStringLiteral("%1 %2").arg(hex(m.code, 4), text), 0, 2);
        d.item(1, QCoreApplication::translate("FrameDecoder", "Error register (1001h)"), hex(m.errorRegister, 2), 2, 1);
        const QStringList bits = canopen::errorRegisterBits(m.errorRegister);
        int named = 0;  // errorRegisterBits() lists the names of the set bits, lowest first
        for (int b = 0; b < 8; ++b)
            if (m.errorRegister & (1u << b))
                d.item(2, QCoreApplication::translate("FrameDecoder", "Bit %1").arg(b), bits.value(named++), 2, 1, b,
                       1);
        d.item(1, QCoreApplication::translate("FrameDecoder", "Manufacturer-specific"), vendor, 3, 5);
    }
}

// SDO (CiA 301 §7.2.4.3).
void decodeSdo(const CanFrame& f, Dissection& d, bool fromClient) {
    const auto s = canopen::parseSdo(f.data.data(), f.len, fromClient);
    const QString cs = canopen::sdoCommandName(s.command);
    d.addText("sdo.cs", cs);
    const QString dir = fromClient ? QStringLiteral("→") : QStringLiteral("←");
    QString text = QCoreApplication::translate("FrameDecoder", "SDO %1 node %2 %3").arg(dir).arg(d.node).arg(cs);
    if (s.hasMux) {
        d.addUInt("sdo.index", s.index);
        d.addUInt("sdo.sub", s.sub);
        text += QLatin1Char(' ') + objRef(s.index, s.sub);
    }
    if (s.command == canopen::SdoCommand::Abort) {
        d.addUInt("sdo.abort", s.abortCode);
        const QString why = coreText(canopen::sdoAbortText(s.abortCode));
        d.addText("sdo.abort_text", why);
        text += QStringLiteral(": %1 (%2)").arg(why, hex(s.abortCode, 8));
    } else if (s.expedited && !s.data.isEmpty()) {
        const uint32_t v = littleEndian(s.data);
        d.addUInt("sdo.value", v);
        text += QStringLiteral(" = %1 (%2)").arg(v).arg(hex(v, s.data.size() * 2));
    } else if (s.sizeIndicated && !s.expedited) {
        d.addUInt("sdo.size", s.size);
        text += QCoreApplication::translate("FrameDecoder", ", %1 bytes").arg(s.size);
    }
    if (!s.error.isEmpty()) d.warn(s.error);
    d.summary = text;
    if (d.wantTree()) {
        d.item(0,
               fromClient ? QCoreApplication::translate("FrameDecoder", "SDO request (client → server)")
                          : QCoreApplication::translate("FrameDecoder", "SDO response (server → client)"),
               {}, 0, f.len);
        if (f.len >= 1)
            d.item(1, QCoreApplication::translate("FrameDecoder", "Command"),
                   QStringLiteral("%1 (%2)").arg(hex(f.data[0], 2), cs), 0, 1);
        if (s.hasMux) {
            d.item(1, QCoreApplication::translate("FrameDecoder", "Index"), hex(s.index, 4), 1, 2);
            d.item(1, QCoreApplication::translate("FrameDecoder", "Sub-index"), hex(s.sub, 2), 3, 1);
        }
        if (s.command == canopen::SdoCommand::Abort)
            d.item(1, QCoreApplication::translate("FrameDecoder", "Abort code"),
                   QStringLiteral("%1 %2").arg(hex(s.abortCode, 8), coreText(canopen::sdoAbortText(s.abortCode))), 4,
                   4);
        else if (s.expedited && !s.data.isEmpty())
            d.item(1, QCoreApplication::translate("FrameDecoder", "Data"), QString::number(littleEndian(s.data)), 4,
                   static_cast<int>(s.data.size()));
        else if (!s.hasMux && f.len > 1)
            d.item(1, QCoreApplication::translate("FrameDecoder", "Segment data"),
                   dissect::hexBytes(f.data.data() + 1, f.len - 1, true), 1, f.len - 1);
    }
}

class CodecFrameDecoder final : public FrameDecoder {
public:
    void decode(const CanFrame& f, Dissection& d) const override {
        if (f.isError()) {
            d.summary = QCoreApplication::translate("FrameDecoder", "Error frame, class %1").arg(hex(f.id, 8));
            if (d.wantTree()) d.item(0, QCoreApplication::translate("FrameDecoder", "Error frame"), hex(f.id, 8));
            return;
        }
        const auto info = canopen::classifyCobId(f.id, f.isExtended());
        d.service = info.service;
        d.node = info.node;
        switch (info.service) {
        case Service::Nmt: decodeNmt(f, d); break;
        case Service::Sync:
            if (f.len >= 1) d.addUInt("sync.counter", f.data[0]);
            d.summary = f.len >= 1 ? QCoreApplication::translate("FrameDecoder", "SYNC counter %1").arg(f.data[0])
                                   : QStringLiteral("SYNC");
            if (d.wantTree())
                d.item(0, QStringLiteral("SYNC"), f.len ? QString::number(f.data[0]) : QString(), 0, f.len);
            break;
        case Service::Time: d.summary = QCoreApplication::translate("FrameDecoder", "TIME stamp"); break;
        case Service::Emcy: decodeEmcy(f, d); break;
        case Service::SdoRequest: decodeSdo(f, d, true); break;
        case Service::SdoResponse: decodeSdo(f, d, false); break;
        case Service::NmtErrorControl: decodeErrorControl(f, d); break;
        case Service::LssRequest:
        case Service::LssResponse: {
            const bool master = info.service == Service::LssRequest;
            d.summary = QStringLiteral("LSS %1 %2")
                            .arg(master ? QStringLiteral("→") : QStringLiteral("←"),
                                 f.len ? canopen::lssCommandName(f.data[0], master)
                                       : QCoreApplication::translate("FrameDecoder", "(empty)"));
            if (f.len) d.addUInt("lss.cs", f.data[0]);
            if (d.wantTree() && f.len)
                d.item(0, QCoreApplication::translate("FrameDecoder", "LSS command"), QString::number(f.data[0]), 0, 1);
            break;
        }
        case Service::Unknown:
            d.summary = f.isExtended() ? QCoreApplication::translate("FrameDecoder", "(29-bit identifier, not CANopen)")
                                       : QString();
            break;
        default: {  // PDOs: raw unless a mapping is known (network context)
            d.pdoNumber = canopen::pdoNumber(info.service) + 1;
            d.summary = QCoreApplication::translate("FrameDecoder", "%1 node %2, %3 bytes")
                            .arg(canopen::serviceName(info.service))
                            .arg(info.node)
                            .arg(f.len);
            if (d.wantTree() && f.len)
                d.item(0, canopen::serviceName(info.service), dissect::hexBytes(f.data.data(), f.len, true), 0, f.len);
            break;
        }
        }
    }
};

}  // namespace

std::shared_ptr<const FrameDecoder> defaultFrameDecoder() {
    static const auto decoder = std::make_shared<CodecFrameDecoder>();
    return decoder;
}

}  // namespace coscope::gui
