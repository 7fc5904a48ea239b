// SPDX-License-Identifier: GPL-3.0-or-later
// PDO (CiA 301 §7.2.2): the payload is the concatenation of the objects in the PDO's mapping
// (1600h/1A00h + n), least significant bit first (§7.2.2.4), by the mapping in force in the
// network context (dictionary defaults, then what SDO transfers of 14xxh..1Bxxh set).
#include "core/od/NumberNotation.h"
#include "core/od/PermanentText.h"
#include "dissectors/Ds402Meaning.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/PdoText.h"
#include "dissectors/Services.h"
#include "dissectors/SummaryBuffer.h"
#include "dissectors/ValueText.h"

#include <bit>
#include <cstring>

namespace coscope::dissect {

namespace {
template <typename T>
T loadLittle(const uint8_t* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// "TPDO1".."RPDO4" are built once; other numbers (custom COB-IDs) on demand.
QString pdoKindText(bool tpdo, int number) {
    static const QString kinds[2][4] = {
        {QStringLiteral("RPDO1"), QStringLiteral("RPDO2"), QStringLiteral("RPDO3"), QStringLiteral("RPDO4")},
        {QStringLiteral("TPDO1"), QStringLiteral("TPDO2"), QStringLiteral("TPDO3"), QStringLiteral("TPDO4")}};
    if (number >= 1 && number <= 4) return kinds[tpdo ? 1 : 0][number - 1];
    return (tpdo ? QStringLiteral("TPDO") : QStringLiteral("RPDO")) + QString::number(number);
}

// ds402MeaningText() of a sub 0, permanent (od::permanentText: a PdoTextValue may point to it),
// from a small cache: control- and statuswords rarely change.
QString cachedDs402Text(uint16_t index, uint64_t raw) {
    struct Meaning {
        uint32_t key = 0;  // 0: empty
        QString text;
    };
    thread_local Meaning cache[16];
    const uint32_t v16 = static_cast<uint16_t>(raw);
    const bool isMode = (index & 0x7FE) == 0x60;  // 6060h/6061h are 8 bits
    const uint32_t key = (uint32_t(index) << 16 | (isMode ? static_cast<uint8_t>(raw) : v16)) + 1;
    Meaning& m = cache[(v16 ^ (v16 >> 4) ^ index) & 15];
    if (m.key != key) {
        m.key = key;
        m.text = od::permanentText(ds402MeaningText(index, 0, raw));
    }
    return m.text;
}

// Only 6040h/6041h/6060h/6061h (any axis) have a CiA 402 meaning (Ds402Meaning.h).
bool hasDs402Meaning(const PdoMapEntry& e) {
    return e.index >= 0x6000 && e.index <= 0x67FF && e.sub == 0 &&
           ((e.index & 0x7FE) == 0x40 || (e.index & 0x7FE) == 0x60);
}

// An integer without a scale factor (nearly every PDO signal): its value exactly as
// decodeBits() gives it, in `sig`, and for the text in `v` (all but label, unit and meaning).
void decodeInteger(const PdoMapEntry& e, const uint8_t* data, int at, PdoSignal& sig, PdoTextValue& v) {
    uint64_t raw = 0;
    if (at % 8 == 0 && e.bits % 8 == 0) {
        // Within the payload (the caller checked). Fixed-size loads for the common widths: a
        // variable-length copy into `raw` stalls the load of `raw` after it.
        const uint8_t* p = data + at / 8;
        const int bytes = e.bits / 8;
        if constexpr (std::endian::native == std::endian::little) {
            if (bytes == 2) raw = loadLittle<uint16_t>(p);
            else if (bytes == 4) raw = loadLittle<uint32_t>(p);
            else if (bytes == 1) raw = p[0];
            else if (bytes == 8) raw = loadLittle<uint64_t>(p);
            else
                for (int k = 0; k < bytes; ++k) raw |= uint64_t(p[k]) << (8 * k);
        } else {
            for (int k = 0; k < bytes; ++k) raw |= uint64_t(p[k]) << (8 * k);
        }
    } else {
        for (int k = 0; k < e.bits; ++k) {
            const int b = at + k;
            if (data[b >> 3] & (1u << (b & 7))) raw |= uint64_t(1) << k;
        }
    }
    const bool isSigned = e.typeKnown && e.cls == od::TypeClass::Signed;
    const uint64_t sign = e.bits < 64 ? uint64_t(1) << (e.bits - 1) : 0;
    const auto signedValue = static_cast<int64_t>(e.bits < 64 ? (raw ^ sign) - sign : raw);
    sig.value.kind = isSigned ? FlatField::Kind::Int : FlatField::Kind::UInt;
    if (isSigned) sig.value.i = signedValue;
    else sig.value.u = raw;
    v.bits = e.bits;
    if (e.hex) {  // controlword, statusword…: the bit pattern (od/NumberNotation.h)
        v.form = PdoTextValue::Form::Hex;
        v.hexKind = e.hexKind;
        v.raw = raw;
    } else if (isSigned) {
        v.form = PdoTextValue::Form::Signed;
        v.raw = static_cast<uint64_t>(signedValue);
    } else {
        v.form = PdoTextValue::Form::Unsigned;
        v.raw = raw;
    }
}

// Calls f(entry, bit offset, signal) for each mapped object of the frame, dummies and what lies
// past the payload left out; the signal (Dissection::addSignal) carries its place.
template <typename F>
void forEachSignal(DissectCall& c, const PdoConfig& cfg,
                   F&& f) {  // by reference: a capture block passed by value on the stack stalls its reload
    int bit = 0;
    for (int i = 0; i < cfg.count; ++i) {
        const PdoMapEntry& e = cfg.entries[static_cast<size_t>(i)];
        const int at = bit;
        bit += e.bits;
        if (e.dummy || e.bits == 0) continue;
        if (bit > c.len * 8) break;
        PdoSignal& sig = c.out.addSignal(e.name, e.unit);  // without wantFields: a scratch signal
        sig.index = e.index;
        sig.sub = e.sub;
        sig.bitOffset = static_cast<uint8_t>(at);
        sig.bitLength = e.bits;
        f(e, at, sig);
    }
}

bool isInteger(const PdoMapEntry& e) {
    return e.factor == 1.0 && e.bits <= 64 && (e.cls == od::TypeClass::Signed || e.cls == od::TypeClass::Unsigned);
}

// An integer with a scale factor (the dictionary's unit: velocity in 0.1 rpm, torque in 0.1 %),
// written in decimal, without a CiA 402 meaning: its value is the integer times the factor, as
// decodeBits() makes it (a Real, written as valueText() writes it).
bool isScaledInteger(const PdoMapEntry& e) {
    return e.factor != 1.0 && e.bits <= 64 && (e.cls == od::TypeClass::Signed || e.cls == od::TypeClass::Unsigned) &&
           !e.hex && !hasDs402Meaning(e);
}

// Every signal of the mapping an integer, maybe scaled, with its label made: the frame decodes
// to PdoTextValues (decodeValues), its text written from them.
bool onlyIntegers(const PdoConfig& cfg) {
    for (int i = 0; i < cfg.count; ++i) {
        const PdoMapEntry& e = cfg.entries[static_cast<size_t>(i)];
        if (!e.dummy && e.bits != 0 &&
            (!(isInteger(e) || isScaledInteger(e)) || e.label.isEmpty() || e.label.size() > 0xFFFF ||
             e.unitText.size() > 0xFFFF))
            return false;
    }
    return true;
}

// The values of a frame of integers (onlyIntegers) appended to `values`, the signals and
// CiA 402 fields added as asked.
void decodeValues(DissectCall& c, const PdoConfig& cfg, std::vector<PdoTextValue>& values) {
    Dissection& out = c.out;
    forEachSignal(c, cfg, [&](const PdoMapEntry& e, int at, PdoSignal& sig) {
        PdoTextValue& v = values.emplace_back();
        v.label = reinterpret_cast<const char16_t*>(e.label.constData());
        v.labelLength = static_cast<uint16_t>(e.label.size());
        v.unit = reinterpret_cast<const char16_t*>(e.unitText.constData());
        v.unitLength = static_cast<uint16_t>(e.unitText.size());
        decodeInteger(e, c.data, at, sig, v);
        if (e.factor != 1.0) {  // isScaledInteger
            const double scaled =
                (sig.value.kind == FlatField::Kind::Int ? double(sig.value.i) : double(sig.value.u)) * e.factor;
            sig.value.kind = FlatField::Kind::Real;
            sig.value.d = scaled;
            v.form = PdoTextValue::Form::Real;
            v.raw = std::bit_cast<uint64_t>(scaled);
        } else if (hasDs402Meaning(e)) {
            const uint64_t raw =
                sig.value.kind == FlatField::Kind::Int ? static_cast<uint64_t>(sig.value.i) : sig.value.u;
            if (out.wantFields) {
                const int byteOff = at / 8;
                ds402Meaning(e.index, e.sub, raw, out, 1, byteOff, (at + e.bits + 7) / 8 - byteOff);  // the fields
            }
            ds402LearnMode(c.ctx.nodeForEdit(c.node), e.index, e.sub, raw);
            const QString m = cachedDs402Text(e.index, raw);
            v.meaning = reinterpret_cast<const char16_t*>(m.constData());
            v.meaningLength = static_cast<uint16_t>(m.size());
        }
    });
}

// The summary and, as asked, the signals and the tree items of any PDO (the tree, scaled or
// non-integer signals, a mapping not known).
void writePdoText(SummaryBuffer::Cursor& w, DissectCall& c, const PdoConfig* cfg, bool mapped, bool tpdo) {
    Dissection& out = c.out;
    writePdoHeader(w, tpdo, out.pdoNumber, c.node);
    if (!mapped) {
        w.put(u' ');
        w.put(hexBytes(c.data, c.len, true));
        if (out.wantTree())
            out.item(0, QStringLiteral("Data (mapping not known)"), hexBytes(c.data, c.len, true), 0, c.len);
        return;
    }
    bool first = true;
    forEachSignal(c, *cfg, [&](const PdoMapEntry& e, int at, PdoSignal& sig) {
        if (first) w.put(u' ');
        else w.put(u", ");
        first = false;
        w.put(e.name);
        w.put(u" = ");
        QString text;
        if (!out.wantTree() && isInteger(e)) {
            PdoTextValue v;
            decodeInteger(e, c.data, at, sig, v);
            if (!e.unit.isEmpty()) {
                v.unit = reinterpret_cast<const char16_t*>(e.unitText.constData());
                v.unitLength = static_cast<uint16_t>(e.unitText.size());
            }
            writePdoValue(w, v);
        } else {
            text = decodeBits(e.type, e.typeKnown, c.data, at, e.bits, sig.value, e.unit, e.factor);
            if (e.hex && (sig.value.kind == FlatField::Kind::UInt || sig.value.kind == FlatField::Kind::Int))
                text = od::hexValueText(
                    e.index, e.sub,
                    sig.value.kind == FlatField::Kind::Int ? static_cast<uint64_t>(sig.value.i) : sig.value.u, e.bits);
            w.put(text);
        }
        const int byteOff = at / 8;
        const int byteLen = (at + e.bits + 7) / 8 - byteOff;
        if (out.wantTree())
            out.item(0,
                     QStringLiteral("%1:%2 %3")
                         .arg(e.index, 4, 16, QLatin1Char('0'))
                         .arg(e.sub, 2, 16, QLatin1Char('0'))
                         .arg(e.name),
                     text, byteOff, byteLen, (at % 8 || e.bits % 8) ? at % 8 : -1, (at % 8 || e.bits % 8) ? e.bits : 0);
        if (hasDs402Meaning(e)) {
            const uint64_t raw =
                sig.value.kind == FlatField::Kind::Int ? static_cast<uint64_t>(sig.value.i) : sig.value.u;
            NodeState& node = c.ctx.nodeForEdit(c.node);
            const QString m = ds402Meaning(e.index, e.sub, raw, out, 1, byteOff, byteLen, ds402ModeOf(node, e.index));
            ds402LearnMode(node, e.index, e.sub, raw);
            if (!m.isEmpty()) {
                w.put(u" (");
                w.put(m);
                w.put(u')');
            }
        }
    });
}
}  // namespace

void dissectPdo(DissectCall& c) {
    Dissection& out = c.out;
    const bool tpdo = canopen::isTpdo(out.service);
    auto kindText = [&] { return pdoKindText(tpdo, out.pdoNumber); };
    if (c.frame.isRemote()) {
        const QString kind = kindText();
        if (out.wantText()) out.summary = QStringLiteral("%1 node %2: remote request").arg(kind).arg(c.node);
        return;
    }
    const PdoConfig* cfg = c.ctx.node(c.node).findPdo(tpdo, out.pdoNumber);
    const bool mapped =
        cfg && cfg->mappingKnown && cfg->count > 0 && static_cast<int>(cfg->entries.size()) >= cfg->count;
    if (cfg && cfg->cobIdKnown && !cfg->valid() && !mapped)
        out.warn(QStringLiteral("%1 of node %2 is not valid (COB-ID 0x%3) but was seen on the bus")
                     .arg(kindText())
                     .arg(c.node)
                     .arg(cfg->cobId, 8, 16, QLatin1Char('0')));
    if (mapped) {
        const int bits = cfg->mappedBits();
        if ((bits + 7) / 8 > c.len)
            out.warn(QStringLiteral("%1 has %2 bytes but its mapping needs %3")
                         .arg(kindText())
                         .arg(c.len)
                         .arg((bits + 7) / 8));
    }
    if (!out.wantText()) return;
    // namesFrom goes with the fields: the GUI names the signals by it.
    if (out.wantFields)
        if (const od::ObjectDictionary* names = c.ctx.namesFor(c.node)) out.namesFrom = names->bundledName;
    const bool integers = mapped && !out.wantTree() && onlyIntegers(*cfg);
    if (integers && out.pdoTextSink) {  // the text is written later, by the sink's owner
        PdoTextSink& sink = *out.pdoTextSink;
        PdoTextRecord& r = sink.records.emplace_back();
        r.tpdo = tpdo;
        r.number = static_cast<uint16_t>(out.pdoNumber);
        r.node = static_cast<uint8_t>(c.node);
        r.valuesAt = static_cast<uint32_t>(sink.values.size());
        decodeValues(c, *cfg, sink.values);
        r.valueCount = static_cast<uint32_t>(sink.values.size()) - r.valuesAt;
        return;
    }
    // The summary is assembled in a reused UTF-16 buffer and copied into out.summary once, or
    // written straight into the consumer's buffer (Dissection::summarySink).
    thread_local SummaryBuffer scratch;
    SummaryBuffer& s = out.summarySink ? *out.summarySink : scratch;
    if (!out.summarySink) s.clear();
    {
        SummaryBuffer::Cursor w(s);
        if (integers) {
            thread_local std::vector<PdoTextValue> values;
            values.clear();
            decodeValues(c, *cfg, values);
            PdoTextRecord r;
            r.tpdo = tpdo;
            r.number = static_cast<uint16_t>(out.pdoNumber);
            r.node = static_cast<uint8_t>(c.node);
            r.valueCount = static_cast<uint32_t>(values.size());
            writePdoSummary(w, r, values.data());
        } else {
            writePdoText(w, c, cfg, mapped, tpdo);
        }
    }
    if (!out.summarySink) s.storeIn(out.summary);
}

}  // namespace coscope::dissect
