// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/od/IntegerInput.h"

#include <QRegularExpression>

#include <tuple>

namespace coscope::od {

namespace {
// The notations of TextStyle::Field, whatever the size: a number too long for 64 bits is out of
// range, not something else.
bool isFieldNumber(const QString& text) {
    static const QRegularExpression kNumber(
        QStringLiteral("^\\s*[+-]?(0[xX][0-9a-fA-F]+|[0-9a-fA-F]+[hH]|[0-9]+)\\s*$"));
    return kNumber.match(text).hasMatch();
}
}  // namespace

std::pair<Value, Value> integerRange(DataType type, const Limits& limits) {
    // A limit inside the type's range narrows it; one outside it (an EDS mistake) does not widen it.
    if (isSigned(type)) {
        const std::int64_t min = integerMin(type).toInt64().value_or(0), max = integerMax(type).toInt64().value_or(0);
        std::int64_t low = min, high = max;
        if (const auto v = limits.low ? limits.low->toInt64() : std::nullopt; v && *v >= min && *v <= max) low = *v;
        if (const auto v = limits.high ? limits.high->toInt64() : std::nullopt; v && *v >= min && *v <= max) high = *v;
        return {Value::signedInt(low), Value::signedInt(high)};
    }
    const std::uint64_t max = integerMax(type).toUInt64().value_or(0);
    std::uint64_t low = 0, high = max;
    if (const auto v = limits.low ? limits.low->toUInt64() : std::nullopt; v && *v <= max) low = *v;
    if (const auto v = limits.high ? limits.high->toUInt64() : std::nullopt; v && *v <= max) high = *v;
    return {Value::unsignedInt(low), Value::unsignedInt(high)};
}

IntegerInput readInteger(DataType type, const QString& text, const Limits& limits) {
    IntegerInput in;
    std::tie(in.low, in.high) = integerRange(type, limits);
    if (text.trimmed().isEmpty()) {
        in.problem = IntegerInput::Problem::Empty;
        return in;
    }
    const auto n = parseIntegerText(text, TextStyle::Field);
    if (!n) {
        in.problem = isFieldNumber(text) ? IntegerInput::Problem::OutOfRange : IntegerInput::Problem::NotANumber;
        return in;
    }
    const auto v = integerValue(type, *n);
    if (!v || !withinLimits(type, *v, Limits{in.low, in.high})) {
        in.problem = IntegerInput::Problem::OutOfRange;
        return in;
    }
    in.value = *v;
    return in;
}

QString integerText(DataType type, const Value& value, HexKind kind) {
    const bool isSignedType = isSigned(type);
    const auto raw =
        isSignedType ? static_cast<std::uint64_t>(value.toInt64().value_or(0)) : value.toUInt64().value_or(0);
    char16_t buf[kHexTextRoom];
    if (const int n = hexValueTextTo(buf, kind, raw, bitSize(type))) return QString::fromUtf16(buf, n);
    return isSignedType ? QString::number(value.toInt64().value_or(0)) : QString::number(raw);
}

}  // namespace coscope::od
