// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/SignalCatalog.h"

#include "core/canopen/Ds402.h"

#include <QRegularExpression>

#include <cstring>

namespace coscope::dissect {

QString SignalKey::text() const {
    QString t = bus ? QStringLiteral("bus%1 ").arg(bus) : QString();
    if (raw) return t + QStringLiteral("raw%1").arg(raw);
    t += QStringLiteral("n%1 ").arg(node) +
         QStringLiteral("%1:%2").arg(index, 4, 16, QLatin1Char('0')).arg(sub, 2, 16, QLatin1Char('0')).toUpper();
    if (bit >= 0) t += QStringLiteral(".%1").arg(bit);
    return t;
}

std::optional<SignalKey> SignalKey::parse(const QString& text) {
    static const QRegularExpression re(
        QStringLiteral(
            R"(^\s*(?:bus(\d+)\s+)?(?:raw(\d+)|n(\d+)\s+([0-9A-Fa-f]{1,4}):([0-9A-Fa-f]{1,2})(?:\.(\d+))?)\s*$)"),
        QRegularExpression::CaseInsensitiveOption);
    const QRegularExpressionMatch m = re.match(text);
    if (!m.hasMatch()) return std::nullopt;
    SignalKey k;
    const uint bus = m.captured(1).isEmpty() ? 0 : m.captured(1).toUInt();
    if (bus > 255) return std::nullopt;
    k.bus = static_cast<uint8_t>(bus);
    if (!m.captured(2).isEmpty()) {
        const uint raw = m.captured(2).toUInt();
        if (raw == 0 || raw > 0xFFFF) return std::nullopt;
        k.raw = static_cast<uint16_t>(raw);
        return k;
    }
    const uint node = m.captured(3).toUInt();
    const int bit = m.captured(6).isEmpty() ? -1 : m.captured(6).toInt();
    if (node > 127 || bit > 63) return std::nullopt;
    k.node = static_cast<uint8_t>(node);
    k.index = static_cast<uint16_t>(m.captured(4).toUInt(nullptr, 16));
    k.sub = static_cast<uint8_t>(m.captured(5).toUInt(nullptr, 16));
    k.bit = static_cast<int8_t>(bit);
    return k;
}

bool hasDigitalBits(uint16_t index, uint8_t sub) {
    if (sub != 0 || index < 0x6000 || index > 0x67FF) return false;
    const uint16_t base = index % 0x800;
    return base == 0x040 || base == 0x041;
}

QString digitalBitName(uint16_t index, int bit, std::optional<int8_t> mode) {
    if (bit < 0 || bit > 15) return {};
    if (index % 0x800 == 0x041) return canopen::ds402::statuswordBitName(bit, mode);
    // Controlword 6040h, CiA 402-2 §6.3.1 (extract-delta-asda-a2 §4.1).
    switch (bit) {
    case 0: return QStringLiteral("switch on");
    case 1: return QStringLiteral("enable voltage");
    case 2: return QStringLiteral("quick stop (active low)");
    case 3: return QStringLiteral("enable operation");
    case 4: return QStringLiteral("operation mode specific (bit 4)");
    case 5: return QStringLiteral("operation mode specific (bit 5)");
    case 6: return QStringLiteral("operation mode specific (bit 6)");
    case 7: return QStringLiteral("fault reset");
    case 8: return QStringLiteral("halt");
    case 9: return QStringLiteral("operation mode specific (bit 9)");
    case 10: return QStringLiteral("reserved (bit 10)");
    default: return QStringLiteral("manufacturer specific (bit %1)").arg(bit);
    }
}

std::optional<double> pdoValue(const PdoMapEntry& e, const uint8_t* data, int len, int bitOffset) {
    if (e.dummy || e.bits == 0 || e.bits > 64 || bitOffset < 0 || bitOffset + e.bits > len * 8) return std::nullopt;
    uint64_t raw = 0;
    if (bitOffset % 8 == 0 && e.bits % 8 == 0) {
        for (int k = 0; k < e.bits / 8; ++k) raw |= uint64_t(data[bitOffset / 8 + k]) << (8 * k);
    } else {
        for (int k = 0; k < e.bits; ++k) {
            const int b = bitOffset + k;
            if (data[b >> 3] & (1u << (b & 7))) raw |= uint64_t(1) << k;
        }
    }
    const od::TypeClass cls = e.typeKnown ? od::typeClass(e.type) : od::TypeClass::Unsigned;
    switch (cls) {
    case od::TypeClass::Signed:
        if (e.bits < 64) {
            const uint64_t sign = uint64_t(1) << (e.bits - 1);
            return double(static_cast<int64_t>((raw ^ sign) - sign));
        }
        return double(static_cast<int64_t>(raw));
    case od::TypeClass::Unsigned:
    case od::TypeClass::Boolean: return double(raw);
    case od::TypeClass::Real:
        if (e.bits == 32) {
            float f;
            const auto u = static_cast<uint32_t>(raw);
            std::memcpy(&f, &u, 4);
            return double(f);
        }
        if (e.bits == 64) {
            double d;
            std::memcpy(&d, &raw, 8);
            return d;
        }
        return std::nullopt;
    default: return std::nullopt;
    }
}

}  // namespace coscope::dissect
