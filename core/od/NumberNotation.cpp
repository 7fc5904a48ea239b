// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/od/NumberNotation.h"

namespace coscope::od {

namespace {

bool between(std::uint16_t v, std::uint16_t lo, std::uint16_t hi) { return v >= lo && v <= hi; }

HexKind communicationKind(std::uint16_t index, std::uint8_t sub) {
    // CiA 301 §7.5.2 (communication profile area).
    switch (index) {
    case 0x1005:
    case 0x1012:
    case 0x1014: return sub == 0 ? HexKind::CobId : HexKind::None;
    case 0x1000:
    case 0x1001:
    case 0x1002:
    case 0x1F80: return sub == 0 ? HexKind::Pattern : HexKind::None;
    case 0x1003:
    case 0x1010:
    case 0x1011:
    case 0x1016: return sub >= 1 ? HexKind::Pattern : HexKind::None;
    case 0x1018: return sub >= 1 && sub <= 4 ? HexKind::Pattern : HexKind::None;
    case 0x1028: return sub >= 1 && sub <= 0x7F ? HexKind::CobId : HexKind::None;
    default: break;
    }
    if (between(index, 0x1200, 0x12FF)) return sub == 1 || sub == 2 ? HexKind::CobId : HexKind::None;
    if (between(index, 0x1400, 0x15FF) || between(index, 0x1800, 0x19FF))
        return sub == 1 ? HexKind::CobId : HexKind::None;
    if (between(index, 0x1600, 0x17FF) || between(index, 0x1A00, 0x1BFF))
        return sub >= 1 && sub <= 0x40 ? HexKind::Pattern : HexKind::None;
    return HexKind::None;
}

HexKind driveKind(std::uint16_t index, std::uint8_t sub) {
    // CiA 402-2: the same objects for each of up to 8 axes, 800h apart.
    const std::uint16_t base = static_cast<std::uint16_t>(0x6000 + (index - 0x6000) % 0x800);
    switch (base) {
    case 0x603F:
    case 0x6040:
    case 0x6041:
    case 0x6502:
    case 0x60FD: return sub == 0 ? HexKind::Pattern : HexKind::None;
    case 0x60FE: return sub >= 1 ? HexKind::Pattern : HexKind::None;
    default: return HexKind::None;
    }
}

}  // namespace

HexKind hexKindFor(std::uint16_t index, std::uint8_t sub) {
    if (between(index, 0x1000, 0x1FFF)) return communicationKind(index, sub);
    if (between(index, 0x6000, 0x9FFF)) return driveKind(index, sub);
    return HexKind::None;
}

int hexTextTo(char16_t* out, std::uint64_t value, int digits) {
    static constexpr char16_t kDigits[] = u"0123456789ABCDEF";
    // Significant digits of `value` (0 has one).
    const int n = value ? (64 - __builtin_clzll(value) + 3) / 4 : 1;
    if (digits > 16) digits = 16;
    const int width = n > digits ? n : digits;
    for (int i = width - 1; i >= 0; --i, value >>= 4) out[i] = kDigits[value & 15];
    out[width] = u'h';
    return width + 1;
}

QString hexText(std::uint64_t value, int digits) {
    char16_t buf[kHexTextRoom];
    if (digits > 16) return QString(digits - 16, u'0') + QString::fromUtf16(buf, hexTextTo(buf, value, 16));
    return QString::fromUtf16(buf, hexTextTo(buf, value, digits));
}

QString objectText(std::uint16_t index, std::uint8_t sub) {
    return hexText(index, 4) + u':' + QString::number(sub, 16).toUpper().rightJustified(2, u'0');
}

int hexValueTextTo(char16_t* out, std::uint16_t index, std::uint8_t sub, std::uint64_t raw, int bits) {
    return hexValueTextTo(out, hexKindFor(index, sub), raw, bits);
}

int hexValueTextTo(char16_t* out, HexKind kind, std::uint64_t raw, int bits) {
    if (bits <= 0 || bits > 64) return 0;
    if (bits < 64) raw &= (std::uint64_t(1) << bits) - 1;
    switch (kind) {
    case HexKind::None: return 0;
    case HexKind::Pattern: return hexTextTo(out, raw, (bits + 3) / 4);
    case HexKind::CobId: return raw <= 0x7FF ? hexTextTo(out, raw, 3) : hexTextTo(out, raw, 8);
    }
    return 0;
}

QString hexValueText(std::uint16_t index, std::uint8_t sub, std::uint64_t raw, int bits) {
    char16_t buf[kHexTextRoom];
    const int n = hexValueTextTo(buf, index, sub, raw, bits);
    return n ? QString::fromUtf16(buf, n) : QString();
}

QString transmissionTypeText(std::uint64_t type) {
    if (type == 0xFF) return QStringLiteral("FFh (event)");
    if (type == 0xFE) return QStringLiteral("FEh (event, manufacturer)");
    return QString::number(type);
}

QString namedValueText(std::uint16_t index, std::uint8_t sub, std::uint64_t raw) {
    const bool pdoCommunication = between(index, 0x1400, 0x15FF) || between(index, 0x1800, 0x19FF);
    return pdoCommunication && sub == 2 && raw >= 0xFE && raw <= 0xFF ? transmissionTypeText(raw) : QString();
}

QString valueText(std::uint16_t index, std::uint8_t sub, std::uint64_t raw, int bits) {
    if (bits <= 0 || bits > 64) return {};
    if (bits < 64) raw &= (std::uint64_t(1) << bits) - 1;
    if (QString named = namedValueText(index, sub, raw); !named.isEmpty()) return named;
    if (QString hex = hexValueText(index, sub, raw, bits); !hex.isEmpty()) return hex;
    const std::uint64_t top = std::uint64_t(1) << (bits - 1);
    if (!(raw & top)) return QString::number(raw);
    const auto negative = static_cast<std::int64_t>(bits == 64 ? raw : raw | ~((top << 1) - 1));
    return QStringLiteral("%1 (%2)").arg(negative).arg(hexText(raw, (bits + 3) / 4));
}

}  // namespace coscope::od
