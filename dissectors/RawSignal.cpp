// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/RawSignal.h"

#include "dissectors/ValueText.h"

#include <QStringList>

#include <cmath>
#include <cstring>

namespace coscope::dissect {

namespace {
// The DBC Motorola walk: from the most significant bit towards bit 0 of its byte, then bit 7
// of the next byte. Returns the bit after `pos`.
int motorolaNext(int pos) { return pos % 8 == 0 ? pos + 15 : pos - 1; }

QString typeLetter(RawSignal::Type t) {
    switch (t) {
    case RawSignal::Type::Signed: return QStringLiteral("s");
    case RawSignal::Type::Float: return QStringLiteral("f");
    default: return QStringLiteral("u");
    }
}
QString number(double v) { return QString::number(v, 'g', 15); }
}  // namespace

int RawSignal::bytesNeeded() const {
    if (length <= 0) return 0;
    if (order == Order::Intel) return (startBit + length - 1) / 8 + 1;
    int pos = startBit;
    for (int k = 1; k < length; ++k) pos = motorolaNext(pos);
    return pos / 8 + 1;
}

QString RawSignal::problem() const {
    if (name.trimmed().isEmpty()) return QStringLiteral("no name");
    if (cobId > (extended ? 0x1FFFFFFFu : 0x7FFu)) return QStringLiteral("COB-ID out of range");
    if (length < 1 || length > 64) return QStringLiteral("length must be 1..64 bits");
    if (type == Type::Float && length != 32 && length != 64) return QStringLiteral("a float is 32 or 64 bits");
    if (startBit < 0 || startBit > 511) return QStringLiteral("start bit must be 0..511");
    if (bytesNeeded() > 64) return QStringLiteral("the signal does not fit in 64 bytes");
    if (factor == 0 || !std::isfinite(factor) || !std::isfinite(offset))
        return QStringLiteral("factor must be a non-zero number");
    return {};
}

std::optional<double> RawSignal::rawValue(const uint8_t* data, int len) const {
    if (length < 1 || length > 64 || startBit < 0 || bytesNeeded() > len) return std::nullopt;
    uint64_t raw = 0;
    if (order == Order::Intel) {
        for (int k = 0; k < length; ++k) {
            const int b = startBit + k;
            if (data[b >> 3] & (1u << (b & 7))) raw |= uint64_t(1) << k;
        }
    } else {
        int pos = startBit;
        for (int k = 0; k < length; ++k, pos = motorolaNext(pos)) raw = raw << 1 | ((data[pos >> 3] >> (pos & 7)) & 1u);
    }
    switch (type) {
    case Type::Signed:
        if (length < 64) {
            const uint64_t sign = uint64_t(1) << (length - 1);
            return double(static_cast<int64_t>((raw ^ sign) - sign));
        }
        return double(static_cast<int64_t>(raw));
    case Type::Float:
        if (length == 32) {
            float f;
            const auto u = static_cast<uint32_t>(raw);
            std::memcpy(&f, &u, 4);
            return double(f);
        }
        if (length == 64) {
            double d;
            std::memcpy(&d, &raw, 8);
            return d;
        }
        return std::nullopt;
    default: return double(raw);
    }
}

std::optional<double> RawSignal::value(const uint8_t* data, int len) const {
    const std::optional<double> r = rawValue(data, len);
    if (!r) return std::nullopt;
    return *r * factor + offset;
}

std::optional<RawSignal> RawSignal::parse(const QString& spec, QString* error) {
    auto fail = [&](const QString& why) -> std::optional<RawSignal> {
        if (error) *error = QStringLiteral("--signal '%1': %2").arg(spec, why);
        return std::nullopt;
    };
    const qsizetype eq = spec.indexOf(u'=');
    if (eq <= 0) return fail(QStringLiteral("expected NAME=COBID:START:LEN:TYPE[:FACTOR[:OFFSET[:UNIT]]]"));
    RawSignal s;
    s.name = spec.left(eq).trimmed();
    const QStringList f = spec.mid(eq + 1).split(u':');
    if (f.size() < 4 || f.size() > 7)
        return fail(QStringLiteral("expected NAME=COBID:START:LEN:TYPE[:FACTOR[:OFFSET[:UNIT]]]"));
    QString cob = f[0].trimmed().toLower();
    if (cob.size() > 2 && cob.endsWith(u'x') && cob.startsWith(QStringLiteral("0x"))) {
        s.extended = true;
        cob.chop(1);
    }
    bool ok = false;
    s.cobId = cob.toUInt(&ok, 0);
    if (!ok) return fail(QStringLiteral("COB-ID '%1' is not a number").arg(f[0]));
    if (s.cobId > 0x7FF) s.extended = true;
    s.startBit = f[1].trimmed().toInt(&ok);
    if (!ok) return fail(QStringLiteral("start bit '%1' is not a number").arg(f[1]));
    s.length = f[2].trimmed().toInt(&ok);
    if (!ok) return fail(QStringLiteral("length '%1' is not a number").arg(f[2]));
    QString type = f[3].trimmed().toLower();
    if (type.endsWith(QStringLiteral("@0"))) s.order = Order::Motorola;
    if (type.endsWith(QStringLiteral("@0")) || type.endsWith(QStringLiteral("@1"))) type.chop(2);
    if (type == u"u") s.type = Type::Unsigned;
    else if (type == u"s") s.type = Type::Signed;
    else if (type == u"f") s.type = Type::Float;
    else return fail(QStringLiteral("type '%1' must be u, s or f, with @0 for Motorola byte order").arg(f[3]));
    if (f.size() > 4 && !f[4].trimmed().isEmpty()) {
        s.factor = f[4].trimmed().toDouble(&ok);
        if (!ok) return fail(QStringLiteral("factor '%1' is not a number").arg(f[4]));
    }
    if (f.size() > 5 && !f[5].trimmed().isEmpty()) {
        s.offset = f[5].trimmed().toDouble(&ok);
        if (!ok) return fail(QStringLiteral("offset '%1' is not a number").arg(f[5]));
    }
    if (f.size() > 6) s.unit = f[6].trimmed();
    if (const QString p = s.problem(); !p.isEmpty()) return fail(p);
    return s;
}

QString RawSignal::spec() const {
    QString t = QStringLiteral("%1=0x%2%3:%4:%5:%6%7")
                    .arg(name, QString::number(cobId, 16).toUpper(),
                         extended && cobId <= 0x7FF ? QStringLiteral("x") : QString())
                    .arg(startBit)
                    .arg(length)
                    .arg(typeLetter(type), order == Order::Motorola ? QStringLiteral("@0") : QString());
    if (factor != 1.0 || offset != 0.0 || !unit.isEmpty()) t += u':' + number(factor);
    if (offset != 0.0 || !unit.isEmpty()) t += u':' + number(offset);
    if (!unit.isEmpty()) t += u':' + unit;
    return t;
}

void applyRawSignals(const std::vector<RawSignal>& raw, const CanFrame& f, Dissection& d) {
    bool first = true;
    for (const RawSignal& r : raw) {
        if (!r.matches(f)) continue;
        const std::optional<double> v = r.rawValue(f.data.data(), f.payloadSize());
        if (!v) continue;
        PdoSignal& sig = d.addSignal(r.name, r.unit);
        sig.raw = true;
        sig.index = 0;
        sig.sub = 0;
        sig.bitOffset = static_cast<uint8_t>(r.startBit);
        sig.bitLength = static_cast<uint8_t>(r.length);
        const bool integer = r.type != RawSignal::Type::Float && r.factor == 1.0 && r.offset == 0.0;
        if (integer && r.type == RawSignal::Type::Signed) {
            sig.value.kind = FlatField::Kind::Int;
            sig.value.i = static_cast<int64_t>(*v);
        } else if (integer) {
            sig.value.kind = FlatField::Kind::UInt;
            sig.value.u = static_cast<uint64_t>(*v);
        } else {
            sig.value.kind = FlatField::Kind::Real;
            sig.value.d = *v * r.factor + r.offset;
        }
        if (!d.wantText()) continue;
        d.summary += first ? QStringLiteral("  | ") : QStringLiteral(", ");
        first = false;
        d.summary += r.name + QStringLiteral(" = ") + valueText(sig.value);
        if (!r.unit.isEmpty()) d.summary += u' ' + r.unit;
    }
}

}  // namespace coscope::dissect
