// SPDX-License-Identifier: GPL-3.0-or-later
// Error frames as Linux SocketCAN reports them (include/uapi/linux/can/error.h); Qt's socketcan
// plugin, candump -L (ids with CAN_ERR_FLAG 20000000h), Vector and PEAK logs all map to it.
#include "core/can/CanErrorFrame.h"

#include <linux/can.h>
#include <linux/can/error.h>

#include <algorithm>

namespace coscope {

namespace {

// Where in the frame a protocol error was seen (data[3], CAN_ERR_PROT_LOC_*).
QString protocolLocation(uint8_t loc) {
    switch (loc) {
    case CAN_ERR_PROT_LOC_SOF: return QStringLiteral("start of frame");
    case CAN_ERR_PROT_LOC_ID28_21: return QStringLiteral("identifier bits 28-21");
    case CAN_ERR_PROT_LOC_ID20_18: return QStringLiteral("identifier bits 20-18");
    case CAN_ERR_PROT_LOC_SRTR: return QStringLiteral("SRTR bit");
    case CAN_ERR_PROT_LOC_IDE: return QStringLiteral("IDE bit");
    case CAN_ERR_PROT_LOC_ID17_13: return QStringLiteral("identifier bits 17-13");
    case CAN_ERR_PROT_LOC_ID12_05: return QStringLiteral("identifier bits 12-5");
    case CAN_ERR_PROT_LOC_ID04_00: return QStringLiteral("identifier bits 4-0");
    case CAN_ERR_PROT_LOC_RTR: return QStringLiteral("RTR bit");
    case CAN_ERR_PROT_LOC_RES1: return QStringLiteral("reserved bit 1");
    case CAN_ERR_PROT_LOC_RES0: return QStringLiteral("reserved bit 0");
    case CAN_ERR_PROT_LOC_DLC: return QStringLiteral("data length code");
    case CAN_ERR_PROT_LOC_DATA: return QStringLiteral("data field");
    case CAN_ERR_PROT_LOC_CRC_SEQ: return QStringLiteral("CRC sequence");
    case CAN_ERR_PROT_LOC_CRC_DEL: return QStringLiteral("CRC delimiter");
    case CAN_ERR_PROT_LOC_ACK: return QStringLiteral("ACK slot");
    case CAN_ERR_PROT_LOC_ACK_DEL: return QStringLiteral("ACK delimiter");
    case CAN_ERR_PROT_LOC_EOF: return QStringLiteral("end of frame");
    case CAN_ERR_PROT_LOC_INTERM: return QStringLiteral("intermission");
    default: return {};
    }
}

// The protocol violation types of data[2] (CAN_ERR_PROT_*), joined.
QString protocolTypes(uint8_t t) {
    static const struct {
        uint8_t bit;
        const char* text;
    } kTypes[] = {
        {CAN_ERR_PROT_BIT, "bit error"},
        {CAN_ERR_PROT_FORM, "form error"},
        {CAN_ERR_PROT_STUFF, "stuff error"},
        {CAN_ERR_PROT_BIT0, "could not send a dominant bit"},
        {CAN_ERR_PROT_BIT1, "could not send a recessive bit"},
        {CAN_ERR_PROT_OVERLOAD, "bus overload"},
        {CAN_ERR_PROT_ACTIVE, "active error flag"},
        {CAN_ERR_PROT_TX, "while transmitting"},
    };
    QStringList parts;
    for (const auto& k : kTypes)
        if (t & k.bit) parts << QString::fromLatin1(k.text);
    return parts.join(QStringLiteral(", "));
}

CanErrorReport::BusState worse(CanErrorReport::BusState a, CanErrorReport::BusState b) { return a > b ? a : b; }

}  // namespace

CanErrorReport decodeCanError(const CanFrame& frame) {
    using S = CanErrorReport::BusState;
    CanErrorReport r;
    r.classes = frame.id & CAN_ERR_MASK;
    const uint8_t* d = frame.data.data();
    const int len = frame.len;
    auto byte = [&](int i) -> uint8_t { return i < len ? d[i] : 0; };

    if (r.classes & CAN_ERR_BUSOFF) {
        r.state = S::BusOff;
        r.problems << QStringLiteral("bus-off (the controller stopped sending after too many errors)");
    }
    if (r.classes & CAN_ERR_CRTL) {
        const uint8_t c = r.controller = byte(1);
        QStringList s;
        if (c & CAN_ERR_CRTL_TX_PASSIVE) s << QStringLiteral("TX error passive");
        if (c & CAN_ERR_CRTL_RX_PASSIVE) s << QStringLiteral("RX error passive");
        if (c & CAN_ERR_CRTL_TX_WARNING) s << QStringLiteral("TX error warning");
        if (c & CAN_ERR_CRTL_RX_WARNING) s << QStringLiteral("RX error warning");
        if (c & CAN_ERR_CRTL_RX_OVERFLOW) s << QStringLiteral("RX buffer overflow (frames lost)");
        if (c & CAN_ERR_CRTL_TX_OVERFLOW) s << QStringLiteral("TX buffer overflow");
        if (c & CAN_ERR_CRTL_ACTIVE) s << QStringLiteral("back to error active");
        if (s.isEmpty()) s << QStringLiteral("unspecified");
        r.problems << QStringLiteral("controller: ") + s.join(QStringLiteral(", "));
        if (c & (CAN_ERR_CRTL_TX_PASSIVE | CAN_ERR_CRTL_RX_PASSIVE)) r.state = worse(r.state, S::Passive);
        else if (c & (CAN_ERR_CRTL_TX_WARNING | CAN_ERR_CRTL_RX_WARNING)) r.state = worse(r.state, S::Warning);
        else if ((c & CAN_ERR_CRTL_ACTIVE) && r.state == S::Unknown) r.state = S::Active;
    }
    if (r.classes & CAN_ERR_ACK)
        r.problems << QStringLiteral("no acknowledge (no other node on the bus, or a different bit rate)");
    if (r.classes & CAN_ERR_PROT) {
        QString p = QStringLiteral("protocol violation");
        if (const QString t = protocolTypes(byte(2)); !t.isEmpty()) p += QStringLiteral(": ") + t;
        if (const QString where = protocolLocation(byte(3)); !where.isEmpty()) p += QStringLiteral(" in the ") + where;
        r.problems << p;
    }
    if (r.classes & CAN_ERR_TRX)
        r.problems << QStringLiteral("transceiver problem (status 0x%1)").arg(byte(4), 2, 16, QLatin1Char('0'));
    if (r.classes & CAN_ERR_LOSTARB)
        r.problems << (byte(0) ? QStringLiteral("lost arbitration at bit %1").arg(byte(0))
                               : QStringLiteral("lost arbitration"));
    if (r.classes & CAN_ERR_TX_TIMEOUT) r.problems << QStringLiteral("transmit timeout");
    if (r.classes & CAN_ERR_BUSERROR) r.problems << QStringLiteral("bus error");
    if (r.classes & CAN_ERR_RESTARTED) {
        r.problems << QStringLiteral("controller restarted");
        if (r.state == S::Unknown) r.state = S::Active;
    }
    if (r.classes & CAN_ERR_CNT) {
        r.txErrors = byte(6);
        r.rxErrors = byte(7);
        // Counters alone still tell the state (ISO 11898-1 fault confinement: passive at 128).
        if (r.state == S::Unknown) {
            const int worst = std::max(*r.txErrors, *r.rxErrors);
            r.state = worst >= 128 ? S::Passive : worst >= 96 ? S::Warning : S::Active;
        }
    }
    if (r.problems.isEmpty() && !r.txErrors)
        r.problems << QStringLiteral("error frame (class %1h)").arg(r.classes, 0, 16);
    return r;
}

QString CanErrorReport::summary() const {
    QString s = problems.join(QStringLiteral("; "));
    if (txErrors) {
        if (!s.isEmpty()) s += QStringLiteral("; ");
        s += QStringLiteral("error counters TX %1, RX %2").arg(*txErrors).arg(*rxErrors);
    }
    return s;
}

bool CanErrorReport::isSevere() const {
    return state == BusState::BusOff || state == BusState::Passive ||
           (controller & (CAN_ERR_CRTL_RX_OVERFLOW | CAN_ERR_CRTL_TX_OVERFLOW));
}

QString busStateName(CanErrorReport::BusState state) {
    switch (state) {
    case CanErrorReport::BusState::Active: return QStringLiteral("error active");
    case CanErrorReport::BusState::Warning: return QStringLiteral("error warning");
    case CanErrorReport::BusState::Passive: return QStringLiteral("error passive");
    case CanErrorReport::BusState::BusOff: return QStringLiteral("bus-off");
    case CanErrorReport::BusState::Unknown: break;
    }
    return {};
}

}  // namespace coscope
