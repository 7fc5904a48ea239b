// SPDX-License-Identifier: GPL-3.0-or-later
// PDO (CiA 301 §7.2.2): the payload is the concatenation of the objects in the PDO's mapping
// (1600h/1A00h + n), least significant bit first (§7.2.2.4), by the mapping in force in the
// network context (dictionary defaults, then what SDO transfers of 14xxh..1Bxxh set).
#include "core/od/NumberNotation.h"
#include "dissectors/Ds402Meaning.h"
#include "dissectors/NetworkContext.h"
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
    const bool mapped = cfg && cfg->mappingKnown && cfg->count > 0 && static_cast<int>(cfg->entries.size()) >= cfg->count;
    if (cfg && cfg->cobIdKnown && !cfg->valid() && !mapped)
        out.warn(QStringLiteral("%1 of node %2 is not valid (COB-ID 0x%3) but was seen on the bus").arg(kindText()).arg(c.node).arg(cfg->cobId, 8, 16, QLatin1Char('0')));
    if (mapped) {
        const int bits = cfg->mappedBits();
        if ((bits + 7) / 8 > c.len)
            out.warn(QStringLiteral("%1 has %2 bytes but its mapping needs %3").arg(kindText()).arg(c.len).arg((bits + 7) / 8));
    }
    if (!out.wantText()) return;
    // namesFrom goes with the fields: the GUI names the signals by it.
    if (out.wantFields)
        if (const od::ObjectDictionary* names = c.ctx.namesFor(c.node)) out.namesFrom = names->bundledName;
    // The summary is assembled in a reused UTF-16 buffer and copied into out.summary once, or
    // written straight into the consumer's buffer (Dissection::summarySink).
    thread_local SummaryBuffer scratch;
    SummaryBuffer& s = out.summarySink ? *out.summarySink : scratch;
    if (!out.summarySink) s.clear();
    auto finish = [&] {
        if (!out.summarySink) s.storeIn(out.summary);
    };
    s.appendLiteral(tpdo ? u"TPDO" : u"RPDO");  // pdoKindText() without a QString
    s.appendDecimal(out.pdoNumber);
    s.appendLiteral(u" node ");
    s.appendDecimal(c.node);
    s += u':';
    if (!mapped) {
        s += u' ';
        s += hexBytes(c.data, c.len, true);
        finish();
        if (out.wantTree()) out.item(0, QStringLiteral("Data (mapping not known)"), hexBytes(c.data, c.len, true), 0, c.len);
        return;
    }
    int bit = 0;
    bool first = true;
    for (int i = 0; i < cfg->count; ++i) {
        const PdoMapEntry& e = cfg->entries[static_cast<size_t>(i)];
        const int at = bit;
        bit += e.bits;
        if (e.dummy || e.bits == 0) continue;
        if (bit > c.len * 8) break;
        thread_local PdoSignal scratchSignal;  // without wantFields: the value is still decoded here
        PdoSignal& sig = out.wantFields ? out.addSignal(e.name, e.unit) : scratchSignal;
        sig.index = e.index;
        sig.sub = e.sub;
        sig.bitOffset = static_cast<uint8_t>(at);
        sig.bitLength = e.bits;
        if (first) s += u' ';
        else s.appendLiteral(u", ");
        first = false;
        s += e.name;
        s.appendLiteral(u" = ");
        const od::TypeClass cls = e.cls;
        QString text;
        if (!out.wantTree() && e.factor == 1.0 && e.bits <= 64 && (cls == od::TypeClass::Signed || cls == od::TypeClass::Unsigned)) {
            // Integers without a scale factor (nearly every PDO signal): the value and its
            // text exactly as decodeBits() gives them, written straight into the summary.
            uint64_t raw = 0;
            if (at % 8 == 0 && e.bits % 8 == 0) {
                // Within the payload: bit <= len * 8. Fixed-size loads for the common widths: a
                // variable-length copy into `raw` stalls the load of `raw` after it.
                const uint8_t* p = c.data + at / 8;
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
                    if (c.data[b >> 3] & (1u << (b & 7))) raw |= uint64_t(1) << k;
                }
            }
            if (e.hex) {  // controlword, statusword…: the bit pattern (od/NumberNotation.h)
                sig.value.kind = FlatField::Kind::UInt;
                sig.value.u = raw;
                if (e.typeKnown && cls == od::TypeClass::Signed) {
                    sig.value.kind = FlatField::Kind::Int;
                    const uint64_t sign = e.bits < 64 ? uint64_t(1) << (e.bits - 1) : 0;
                    sig.value.i = static_cast<int64_t>(e.bits < 64 ? (raw ^ sign) - sign : raw);
                }
                s.grew(static_cast<size_t>(od::hexValueTextTo(s.room(od::kHexTextRoom), e.hexKind, raw, e.bits)));
            } else if (e.typeKnown && cls == od::TypeClass::Signed) {
                sig.value.kind = FlatField::Kind::Int;
                if (e.bits < 64) {
                    const uint64_t sign = uint64_t(1) << (e.bits - 1);
                    sig.value.i = static_cast<int64_t>((raw ^ sign) - sign);
                } else {
                    sig.value.i = static_cast<int64_t>(raw);
                }
                s.appendDecimal(sig.value.i);
            } else {
                sig.value.kind = FlatField::Kind::UInt;
                sig.value.u = raw;
                s.appendDecimal(raw, false);
            }
            if (!e.unit.isEmpty()) {
                s += u' ';
                s += e.unit;
            }
        } else {
            text = decodeBits(e.type, e.typeKnown, c.data, at, e.bits, sig.value, e.unit, e.factor);
            if (e.hex && (sig.value.kind == FlatField::Kind::UInt || sig.value.kind == FlatField::Kind::Int))
                text = od::hexValueText(e.index, e.sub, sig.value.kind == FlatField::Kind::Int ? static_cast<uint64_t>(sig.value.i) : sig.value.u, e.bits);
            s += text;
        }
        const int byteOff = at / 8;
        const int byteLen = (at + e.bits + 7) / 8 - byteOff;
        if (out.wantTree())
            out.item(0, QStringLiteral("%1:%2 %3").arg(e.index, 4, 16, QLatin1Char('0')).arg(e.sub, 2, 16, QLatin1Char('0')).arg(e.name), text,
                     byteOff, byteLen, (at % 8 || e.bits % 8) ? at % 8 : -1, (at % 8 || e.bits % 8) ? e.bits : 0);
        // Only 6040h/6041h/6060h/6061h (any axis) have a CiA 402 meaning (Ds402Meaning.h).
        if (e.index >= 0x6000 && e.index <= 0x67FF && e.sub == 0 && ((e.index & 0x7FE) == 0x40 || (e.index & 0x7FE) == 0x60)) {
            uint64_t raw = sig.value.kind == FlatField::Kind::Int ? static_cast<uint64_t>(sig.value.i) : sig.value.u;
            const QString m = ds402Meaning(e.index, e.sub, raw, out, 1, byteOff, byteLen);
            if (!m.isEmpty()) {
                s.appendLiteral(u" (");
                s += m;
                s += u')';
            }
        }
    }
    finish();
}

}  // namespace coscope::dissect
