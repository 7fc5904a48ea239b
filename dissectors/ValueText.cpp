// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/ValueText.h"

#include "dissectors/DoubleText.h"

#include <cstring>

namespace coscope::dissect {

namespace {

bool printable(const uint8_t* d, int len) {
    int n = len;
    while (n > 0 && d[n - 1] == 0) --n;  // trailing NULs (VISIBLE_STRING padding)
    if (n == 0) return false;
    for (int i = 0; i < n; ++i)
        if (d[i] < 0x20 || d[i] > 0x7E) return false;
    return true;
}

QString withUnit(const FlatField& v, const QString& unit, double factor, FlatField& out) {
    if (factor != 1.0 &&
        (v.kind == FlatField::Kind::Int || v.kind == FlatField::Kind::UInt || v.kind == FlatField::Kind::Real)) {
        const double raw = v.kind == FlatField::Kind::Int    ? double(v.i)
                           : v.kind == FlatField::Kind::UInt ? double(v.u)
                                                             : v.d;
        out.kind = FlatField::Kind::Real;
        out.d = raw * factor;
    }
    QString t = valueText(out);
    if (!unit.isEmpty()) {
        t.reserve(t.size() + 1 + unit.size());
        t += u' ';
        t += unit;
    }
    return t;
}

void fromInteger(od::DataType type, bool typeKnown, uint64_t raw, int bits, FlatField& value) {
    using T = od::DataType;
    if (typeKnown && (type == T::Real32) && bits == 32) {
        float f;
        const auto u = static_cast<uint32_t>(raw);
        std::memcpy(&f, &u, 4);
        value.kind = FlatField::Kind::Real;
        value.d = f;
        return;
    }
    if (typeKnown && type == T::Real64 && bits == 64) {
        double d;
        std::memcpy(&d, &raw, 8);
        value.kind = FlatField::Kind::Real;
        value.d = d;
        return;
    }
    if (typeKnown && od::isSigned(type) && bits > 0 && bits < 64) {
        const uint64_t sign = uint64_t(1) << (bits - 1);
        value.kind = FlatField::Kind::Int;
        value.i = static_cast<int64_t>((raw ^ sign) - sign);
        return;
    }
    if (typeKnown && od::isSigned(type)) {
        value.kind = FlatField::Kind::Int;
        value.i = static_cast<int64_t>(raw);
        return;
    }
    value.kind = FlatField::Kind::UInt;
    value.u = raw;
}

// Decimal text of an integer, as QString::number gives it, without its general machinery.
QString decimalText(uint64_t u, bool negative) {
    char16_t buf[24];
    char16_t* e = buf + 24;
    char16_t* p = e;
    do {
        *--p = char16_t(u'0' + u % 10);
        u /= 10;
    } while (u);
    if (negative) *--p = u'-';
    return QString(reinterpret_cast<const QChar*>(p), e - p);
}

}  // namespace

QString valueText(const FlatField& v) {
    switch (v.kind) {
    case FlatField::Kind::Int:
        return v.i < 0 ? decimalText(0 - static_cast<uint64_t>(v.i), true)
                       : decimalText(static_cast<uint64_t>(v.i), false);
    case FlatField::Kind::UInt: return decimalText(v.u, false);
    case FlatField::Kind::Real: return doubleTextG(v.d, 9);  // QString::number(v.d, 'g', 9)
    case FlatField::Kind::Bool: return v.i ? QStringLiteral("true") : QStringLiteral("false");
    case FlatField::Kind::Text: return v.text;
    }
    return {};
}

QString decodeValue(od::DataType type, bool typeKnown, const uint8_t* data, int len, FlatField& value,
                    const QString& unit, double factor) {
    const bool stringType = typeKnown && (type == od::DataType::VisibleString || type == od::DataType::UnicodeString);
    const bool bytesType =
        typeKnown && (type == od::DataType::OctetString || type == od::DataType::Domain ||
                      od::typeClass(type) == od::TypeClass::Domain || od::typeClass(type) == od::TypeClass::Time);
    const int size = typeKnown ? od::byteSize(type) : 0;
    if (stringType || (!typeKnown && len > 8 && printable(data, len))) {
        int n = len;
        while (n > 0 && data[n - 1] == 0) --n;
        value.kind = FlatField::Kind::Text;
        value.text = type == od::DataType::UnicodeString && typeKnown
                         ? QString::fromUtf16(reinterpret_cast<const char16_t*>(data), n / 2)
                         : QString::fromLatin1(reinterpret_cast<const char*>(data), n);
        return value.text;
    }
    if (bytesType || len > 8 || len == 0 || (size && size != len && !(type == od::DataType::Boolean && len == 1))) {
        value.kind = FlatField::Kind::Text;
        value.text = hexBytes(data, len, true);
        return value.text;
    }
    uint64_t raw = 0;
    for (int i = 0; i < len; ++i) raw |= uint64_t(data[i]) << (8 * i);
    if (typeKnown && type == od::DataType::Boolean) {
        value.kind = FlatField::Kind::Bool;
        value.i = raw ? 1 : 0;
        return valueText(value);
    }
    fromInteger(type, typeKnown, raw, len * 8, value);
    return withUnit(value, unit, factor, value);
}

QString decodeBits(od::DataType type, bool typeKnown, const uint8_t* data, int bitOffset, int bits, FlatField& value,
                   const QString& unit, double factor) {
    if (bits > 64 || (bitOffset % 8 == 0 && bits % 8 == 0 && bits > 0 && typeKnown && od::isString(type)))
        return decodeValue(type, typeKnown, data + bitOffset / 8, bits / 8, value, unit, factor);
    uint64_t raw = 0;
    if (bitOffset % 8 == 0 && bits % 8 == 0) {  // byte-aligned: the common case
        for (int i = 0; i < bits / 8; ++i) raw |= uint64_t(data[bitOffset / 8 + i]) << (8 * i);
    } else
        for (int i = 0; i < bits; ++i) {
            const int b = bitOffset + i;
            if (data[b >> 3] & (1u << (b & 7))) raw |= uint64_t(1) << i;
        }
    if (typeKnown && type == od::DataType::Boolean) {
        value.kind = FlatField::Kind::Bool;
        value.i = raw ? 1 : 0;
        return valueText(value);
    }
    fromInteger(type, typeKnown, raw, bits, value);
    return withUnit(value, unit, factor, value);
}

}  // namespace coscope::dissect
