// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/od/Value.h"

#include <QStringDecoder>
#include <QtEndian>

#include <cmath>
#include <cstring>
#include <limits>

namespace coscope::od {

namespace {

// Range of an n-bit integer type (CiA 301 7.1.4.4 and 7.1.4.5).
std::int64_t signedMin(int bits) {
    return bits >= 64 ? std::numeric_limits<std::int64_t>::min() : -(std::int64_t(1) << (bits - 1));
}
std::int64_t signedMax(int bits) {
    return bits >= 64 ? std::numeric_limits<std::int64_t>::max() : (std::int64_t(1) << (bits - 1)) - 1;
}
std::uint64_t unsignedMax(int bits) {
    return bits >= 64 ? std::numeric_limits<std::uint64_t>::max() : (std::uint64_t(1) << bits) - 1;
}

QByteArray leBytes(std::uint64_t v, int n) {
    QByteArray out(n, '\0');
    for (int i = 0; i < n; ++i) out[i] = static_cast<char>((v >> (8 * i)) & 0xFF);
    return out;
}

std::uint64_t fromLe(const QByteArray& b) {
    std::uint64_t v = 0;
    for (int i = 0; i < b.size() && i < 8; ++i) v |= std::uint64_t(static_cast<unsigned char>(b[i])) << (8 * i);
    return v;
}

ValueResult fail(QString message) { return {Value(), std::move(message)}; }

QString unquote(const QString& text, bool* wasQuoted) {
    const QString t = text.trimmed();
    *wasQuoted = false;
    if (t.size() >= 2 && t.startsWith(u'"') && t.endsWith(u'"')) {
        *wasQuoted = true;
        QString out;
        const QString inner = t.mid(1, t.size() - 2);
        for (qsizetype i = 0; i < inner.size(); ++i) {
            if (inner[i] == u'\\' && i + 1 < inner.size()) {
                const QChar n = inner[++i];
                if (n == u'n') out += u'\n';
                else if (n == u't') out += u'\t';
                else out += n;
            } else {
                out += inner[i];
            }
        }
        return out;
    }
    return text;
}

// "01 02 FF", "0102FF", "0x0102FF", "01:02:ff".
std::optional<QByteArray> parseHexBytes(const QString& text) {
    QString s = text.trimmed();
    if (s.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)) s = s.mid(2);
    s.remove(u' ');
    s.remove(u':');
    s.remove(u'-');
    s.remove(u'\t');
    if (s.size() % 2 != 0) return std::nullopt;
    for (QChar c : s)
        if (!std::isxdigit(static_cast<unsigned char>(c.toLatin1()))) return std::nullopt;
    return QByteArray::fromHex(s.toLatin1());
}

QString typeRange(DataType type) {
    const int bits = bitSize(type);
    if (isSigned(type)) return QStringLiteral("%1..%2").arg(signedMin(bits)).arg(signedMax(bits));
    return QStringLiteral("0..%1").arg(unsignedMax(bits));
}

int compareValues(DataType type, const Value& a, const Value& b) {
    switch (typeClass(type)) {
    case TypeClass::Signed: {
        const auto x = a.toInt64(), y = b.toInt64();
        if (!x || !y) return 0;
        return *x < *y ? -1 : (*x > *y ? 1 : 0);
    }
    case TypeClass::Unsigned:
    case TypeClass::Time: {
        const auto x = a.toUInt64(), y = b.toUInt64();
        if (!x || !y) return 0;
        return *x < *y ? -1 : (*x > *y ? 1 : 0);
    }
    case TypeClass::Real: {
        const auto x = a.toDouble(), y = b.toDouble();
        if (!x || !y) return 0;
        return *x < *y ? -1 : (*x > *y ? 1 : 0);
    }
    default: return 0;
    }
}

}  // namespace

std::optional<std::int64_t> Value::toInt64() const {
    if (auto p = std::get_if<std::int64_t>(&storage_)) return *p;
    if (auto p = std::get_if<std::uint64_t>(&storage_)) {
        if (*p > std::uint64_t(std::numeric_limits<std::int64_t>::max())) return std::nullopt;
        return std::int64_t(*p);
    }
    if (auto p = std::get_if<bool>(&storage_)) return *p ? 1 : 0;
    if (auto p = std::get_if<double>(&storage_)) {
        if (!std::isfinite(*p) || *p < -9.2e18 || *p > 9.2e18) return std::nullopt;
        return std::int64_t(*p);
    }
    return std::nullopt;
}

std::optional<std::uint64_t> Value::toUInt64() const {
    if (auto p = std::get_if<std::uint64_t>(&storage_)) return *p;
    if (auto p = std::get_if<std::int64_t>(&storage_)) {
        if (*p < 0) return std::nullopt;
        return std::uint64_t(*p);
    }
    if (auto p = std::get_if<bool>(&storage_)) return *p ? 1 : 0;
    if (auto p = std::get_if<double>(&storage_)) {
        if (!std::isfinite(*p) || *p < 0 || *p > 1.8e19) return std::nullopt;
        return std::uint64_t(*p);
    }
    return std::nullopt;
}

std::optional<double> Value::toDouble() const {
    if (auto p = std::get_if<double>(&storage_)) return *p;
    if (auto p = std::get_if<std::int64_t>(&storage_)) return double(*p);
    if (auto p = std::get_if<std::uint64_t>(&storage_)) return double(*p);
    if (auto p = std::get_if<bool>(&storage_)) return *p ? 1.0 : 0.0;
    return std::nullopt;
}

QByteArray Value::toBytes() const {
    if (auto p = std::get_if<QByteArray>(&storage_)) return *p;
    if (auto p = std::get_if<QString>(&storage_)) return p->toLatin1();
    return {};
}

QString Value::toText() const {
    if (auto p = std::get_if<QString>(&storage_)) return *p;
    if (auto p = std::get_if<QByteArray>(&storage_)) return QString::fromLatin1(*p);
    if (auto p = std::get_if<bool>(&storage_)) return *p ? QStringLiteral("true") : QStringLiteral("false");
    if (auto p = std::get_if<std::int64_t>(&storage_)) return QString::number(*p);
    if (auto p = std::get_if<std::uint64_t>(&storage_)) return QString::number(*p);
    if (auto p = std::get_if<double>(&storage_)) return QString::number(*p, 'g', 17);
    return {};
}

QByteArray Value::encode(DataType type, QString* error) const {
    auto bad = [&](const QString& m) {
        if (error) *error = m;
        return QByteArray();
    };
    if (error) error->clear();
    if (isNull()) return bad(QStringLiteral("no value"));
    const int bits = bitSize(type);
    switch (typeClass(type)) {
    case TypeClass::Boolean: {
        const auto v = toUInt64();
        if (!v || *v > 1) return bad(QStringLiteral("BOOLEAN needs true or false"));
        return leBytes(*v, 1);
    }
    case TypeClass::Signed: {
        const auto v = toInt64();
        if (!v || *v < signedMin(bits) || *v > signedMax(bits))
            return bad(QStringLiteral("value does not fit %1 (%2)").arg(dataTypeName(type), typeRange(type)));
        return leBytes(static_cast<std::uint64_t>(*v), bits / 8);
    }
    case TypeClass::Unsigned:
    case TypeClass::Time: {
        const auto v = toUInt64();
        if (!v || *v > unsignedMax(bits))
            return bad(QStringLiteral("value does not fit %1 (%2)").arg(dataTypeName(type), typeRange(type)));
        return leBytes(*v, bits / 8);
    }
    case TypeClass::Real: {
        const auto v = toDouble();
        if (!v) return bad(QStringLiteral("%1 needs a number").arg(dataTypeName(type)));
        if (type == DataType::Real32) {
            const float f = static_cast<float>(*v);
            std::uint32_t u = 0;
            std::memcpy(&u, &f, 4);
            return leBytes(u, 4);
        }
        std::uint64_t u = 0;
        const double d = *v;
        std::memcpy(&u, &d, 8);
        return leBytes(u, 8);
    }
    case TypeClass::VisibleString:
        if (auto p = std::get_if<QString>(&storage_)) return p->toUtf8();
        if (auto p = std::get_if<QByteArray>(&storage_)) return *p;
        return bad(QStringLiteral("VISIBLE_STRING needs text"));
    case TypeClass::UnicodeString: {
        const QString s = std::holds_alternative<QString>(storage_) ? std::get<QString>(storage_) : QString();
        if (!std::holds_alternative<QString>(storage_)) return bad(QStringLiteral("UNICODE_STRING needs text"));
        QByteArray out(s.size() * 2, '\0');
        for (qsizetype i = 0; i < s.size(); ++i) qToLittleEndian<quint16>(s[i].unicode(), out.data() + 2 * i);
        return out;
    }
    case TypeClass::OctetString:
    case TypeClass::Domain:
        if (auto p = std::get_if<QByteArray>(&storage_)) return *p;
        if (auto p = std::get_if<QString>(&storage_)) return p->toLatin1();
        return bad(QStringLiteral("%1 needs bytes").arg(dataTypeName(type)));
    }
    return bad(QStringLiteral("unsupported type"));
}

ValueResult Value::decode(DataType type, const QByteArray& bytes) {
    const int size = byteSize(type);
    if (size > 0 && bytes.size() != size)
        return fail(QStringLiteral("%1 needs %2 byte%3, got %4")
                        .arg(dataTypeName(type))
                        .arg(size)
                        .arg(size == 1 ? "" : "s")
                        .arg(bytes.size()));
    const int bits = bitSize(type);
    switch (typeClass(type)) {
    case TypeClass::Boolean: {
        const auto b = static_cast<unsigned char>(bytes[0]);
        if (b > 1) return fail(QStringLiteral("BOOLEAN byte is 0x%1, not 0 or 1").arg(b, 2, 16, QLatin1Char('0')));
        return {Value::boolean(b == 1), {}};
    }
    case TypeClass::Signed: {
        std::uint64_t u = fromLe(bytes);
        if (bits < 64 && (u >> (bits - 1)) & 1) u |= ~unsignedMax(bits);  // sign extension
        return {Value::signedInt(static_cast<std::int64_t>(u)), {}};
    }
    case TypeClass::Unsigned:
    case TypeClass::Time: {
        std::uint64_t u = fromLe(bytes);
        return {Value::unsignedInt(u), {}};
    }
    case TypeClass::Real:
        if (type == DataType::Real32) {
            const auto u = static_cast<std::uint32_t>(fromLe(bytes));
            float f = 0;
            std::memcpy(&f, &u, 4);
            return {Value::real(f), {}};
        } else {
            const std::uint64_t u = fromLe(bytes);
            double d = 0;
            std::memcpy(&d, &u, 8);
            return {Value::real(d), {}};
        }
    case TypeClass::VisibleString: {
        QByteArray b = bytes;
        while (!b.isEmpty() && b.back() == '\0') b.chop(1);
        // ISO 646 text in the standard; devices also send UTF-8 and Latin-1: UTF-8 when valid.
        QStringDecoder utf8(QStringDecoder::Utf8);
        const QString s = utf8.decode(b);
        return {Value::text(utf8.hasError() ? QString::fromLatin1(b) : s), {}};
    }
    case TypeClass::UnicodeString: {
        if (bytes.size() % 2)
            return fail(QStringLiteral("UNICODE_STRING needs an even number of bytes, got %1").arg(bytes.size()));
        QString s;
        s.reserve(bytes.size() / 2);
        for (qsizetype i = 0; i + 1 < bytes.size(); i += 2)
            s += QChar(qFromLittleEndian<quint16>(bytes.constData() + i));
        while (!s.isEmpty() && s.back() == QChar(0)) s.chop(1);
        return {Value::text(s), {}};
    }
    case TypeClass::OctetString:
    case TypeClass::Domain: return {Value::bytes(bytes), {}};
    }
    return fail(QStringLiteral("unsupported type"));
}

ValueResult Value::parse(DataType type, const QString& text) { return parse(type, text, Limits{}, TextStyle::Person); }

ValueResult Value::parse(DataType type, const QString& rawText, const Limits& limits, TextStyle style) {
    const QString text = rawText.trimmed();
    const QString typeName = dataTypeName(type);
    const int bits = bitSize(type);
    ValueResult r;
    switch (typeClass(type)) {
    case TypeClass::Boolean: {
        const QString t = text.toLower();
        if (t == u"true" || t == u"1" || t == u"yes" || t == u"on") r.value = Value::boolean(true);
        else if (t == u"false" || t == u"0" || t == u"no" || t == u"off") r.value = Value::boolean(false);
        else if (const auto n = parseIntegerText(text, style); n && !n->negative && n->magnitude <= 1)
            r.value = Value::boolean(n->magnitude == 1);
        else return fail(QStringLiteral("'%1' is not a BOOLEAN (use true/false or 1/0)").arg(rawText));
        break;
    }
    case TypeClass::Signed:
    case TypeClass::Unsigned: {
        const auto n = parseIntegerText(text, style);
        if (!n) return fail(QStringLiteral("'%1' is not a number for %2").arg(rawText, typeName));
        const auto v = integerValue(type, *n);
        if (!v) return fail(QStringLiteral("'%1' does not fit %2 (%3)").arg(rawText, typeName, typeRange(type)));
        r.value = *v;
        break;
    }
    case TypeClass::Real: {
        if (text.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)) {
            // CiA 306 allows REAL defaults as the IEEE 754 bit pattern.
            const auto n = parseIntegerText(text, TextStyle::Eds);
            if (!n || n->magnitude > unsignedMax(bits))
                return fail(QStringLiteral("'%1' is not a %2 bit pattern").arg(rawText, typeName));
            const auto decoded = decode(type, leBytes(n->magnitude, bits / 8));
            r.value = decoded.value;
        } else {
            bool ok = false;
            double d = text.toDouble(&ok);
            if (!ok) {
                const QString t = text.toLower();
                if (t == u"nan") d = std::numeric_limits<double>::quiet_NaN(), ok = true;
                else if (t == u"inf" || t == u"+inf") d = std::numeric_limits<double>::infinity(), ok = true;
                else if (t == u"-inf") d = -std::numeric_limits<double>::infinity(), ok = true;
            }
            if (!ok) return fail(QStringLiteral("'%1' is not a number for %2").arg(rawText, typeName));
            if (type == DataType::Real32 && std::isfinite(d) && std::fabs(d) > std::numeric_limits<float>::max())
                return fail(QStringLiteral("'%1' does not fit REAL32").arg(rawText));
            if (type == DataType::Real32) d = static_cast<float>(d);
            r.value = Value::real(d);
        }
        break;
    }
    case TypeClass::VisibleString:
    case TypeClass::UnicodeString: {
        bool quoted = false;
        const QString s = style == TextStyle::Eds ? rawText : unquote(rawText, &quoted);
        r.value = Value::text(s);
        break;
    }
    case TypeClass::OctetString:
    case TypeClass::Domain: {
        bool quoted = false;
        const QString s = unquote(rawText, &quoted);
        if (quoted) {
            r.value = Value::bytes(s.toUtf8());
            break;
        }
        const auto b = parseHexBytes(text);
        if (!b) return fail(QStringLiteral("'%1' is not hex bytes for %2 (e.g. \"01 02 FF\")").arg(rawText, typeName));
        r.value = Value::bytes(*b);
        break;
    }
    case TypeClass::Time: {
        // "DAYS:MS", "5d 1000ms" or the raw 48-bit number.
        QString t = text.toLower();
        t.replace(QLatin1String("ms"), QLatin1String(""));
        t.replace(u'd', u':');
        t.remove(u' ');
        if (t.contains(u':')) {
            bool ok1 = false, ok2 = false;
            const qulonglong days = t.section(u':', 0, 0).toULongLong(&ok1);
            const qulonglong ms = t.section(u':', 1).toULongLong(&ok2);
            if (!ok1 || !ok2 || days > 0xFFFF || ms > 0x0FFFFFFF)
                return fail(
                    QStringLiteral("'%1' is not a %2 (days:ms, ms < 2^28, days < 65536)").arg(rawText, typeName));
            r.value = Value::timeOfDay(static_cast<std::uint32_t>(ms), static_cast<std::uint16_t>(days));
        } else {
            const auto n = parseIntegerText(text, style);
            if (!n || n->negative || n->magnitude > unsignedMax(48))
                return fail(QStringLiteral("'%1' is not a %2").arg(rawText, typeName));
            r.value = Value::unsignedInt(n->magnitude);
        }
        break;
    }
    }
    QString why;
    if (!withinLimits(type, r.value, limits, &why)) return fail(QStringLiteral("'%1' is %2").arg(rawText, why));
    return r;
}

std::optional<Value> integerValue(DataType type, const ParsedInteger& n) {
    const int bits = bitSize(type);
    if (typeClass(type) == TypeClass::Unsigned) {
        if (n.negative || n.magnitude > unsignedMax(bits)) return std::nullopt;
        return Value::unsignedInt(n.magnitude);
    }
    if (typeClass(type) != TypeClass::Signed) return std::nullopt;
    if (n.hex && !n.negative) {
        // A hex number is the bit pattern of the type (0xFF as INTEGER8 is -1).
        if (n.magnitude > unsignedMax(bits)) return std::nullopt;
        std::uint64_t u = n.magnitude;
        if (bits < 64 && (u >> (bits - 1)) & 1) u |= ~unsignedMax(bits);
        return Value::signedInt(static_cast<std::int64_t>(u));
    }
    if (n.negative) {
        if (n.magnitude > std::uint64_t(-(signedMin(bits) + 1)) + 1) return std::nullopt;
        return Value::signedInt(static_cast<std::int64_t>(0 - n.magnitude));
    }
    if (n.magnitude > std::uint64_t(signedMax(bits))) return std::nullopt;
    return Value::signedInt(static_cast<std::int64_t>(n.magnitude));
}

Value integerMin(DataType type) {
    return isSigned(type) ? Value::signedInt(signedMin(bitSize(type))) : Value::unsignedInt(0);
}
Value integerMax(DataType type) {
    return isSigned(type) ? Value::signedInt(signedMax(bitSize(type))) : Value::unsignedInt(unsignedMax(bitSize(type)));
}

bool withinLimits(DataType type, const Value& value, const Limits& limits, QString* error) {
    if (limits.low && compareValues(type, value, *limits.low) < 0) {
        if (error) *error = QStringLiteral("below LowLimit %1").arg(Value::format(type, *limits.low));
        return false;
    }
    if (limits.high && compareValues(type, value, *limits.high) > 0) {
        if (error) *error = QStringLiteral("above HighLimit %1").arg(Value::format(type, *limits.high));
        return false;
    }
    return true;
}

QString Value::format(DataType type, const Value& v, const FormatOptions& o) {
    if (v.isNull()) return {};
    QString s;
    const int bits = bitSize(type);
    const bool scaled = o.factor != 1.0 && !o.hex;
    switch (typeClass(type)) {
    case TypeClass::Boolean: s = v.toUInt64().value_or(0) ? QStringLiteral("true") : QStringLiteral("false"); break;
    case TypeClass::Signed:
    case TypeClass::Unsigned: {
        if (o.hex) {
            std::uint64_t u = typeClass(type) == TypeClass::Signed ? static_cast<std::uint64_t>(v.toInt64().value_or(0))
                                                                   : v.toUInt64().value_or(0);
            u &= unsignedMax(bits);
            s = QStringLiteral("0x") + QString::number(u, 16).toUpper().rightJustified(bits / 4, QLatin1Char('0'));
        } else if (scaled) {
            s = QString::number(v.toDouble().value_or(0) * o.factor, 'g', 12);
        } else {
            s = typeClass(type) == TypeClass::Signed ? QString::number(v.toInt64().value_or(0))
                                                     : QString::number(v.toUInt64().value_or(0));
        }
        break;
    }
    case TypeClass::Real: {
        const double d = v.toDouble().value_or(0) * (scaled ? o.factor : 1.0);
        s = QString::number(d, 'g', type == DataType::Real32 && !scaled ? 9 : 17);
        // Shortest text that still reads back to the same value.
        for (int p = 1; p <= 17; ++p) {
            const QString t = QString::number(d, 'g', p);
            if (type == DataType::Real32 && !scaled ? static_cast<float>(t.toDouble()) == static_cast<float>(d)
                                                    : t.toDouble() == d) {
                s = t;
                break;
            }
        }
        break;
    }
    case TypeClass::VisibleString:
    case TypeClass::UnicodeString:
        s = v.toText();
        if (o.quoteStrings) {
            QString q = s;
            q.replace(QLatin1String("\\"), QLatin1String("\\\\")).replace(QLatin1String("\""), QLatin1String("\\\""));
            s = u'"' + q + u'"';
        }
        break;
    case TypeClass::OctetString:
    case TypeClass::Domain: s = QString::fromLatin1(v.toBytes().toHex(' ').toUpper()); break;
    case TypeClass::Time: {
        const std::uint64_t u = v.toUInt64().value_or(0);
        s = QStringLiteral("%1d %2ms").arg(u >> 32).arg(u & 0x0FFFFFFF);
        break;
    }
    }
    if (!o.unit.isEmpty()) s += u' ' + o.unit;
    return s;
}

}  // namespace coscope::od
