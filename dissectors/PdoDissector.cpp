// SPDX-License-Identifier: GPL-3.0-or-later
// PDO (CiA 301 §7.2.2): the payload is the concatenation of the objects in the PDO's mapping
// (1600h/1A00h + n), least significant bit first (§7.2.2.4), by the mapping in force in the
// network context (dictionary defaults, then what SDO transfers of 14xxh..1Bxxh set).
#include "dissectors/Ds402Meaning.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/Services.h"
#include "dissectors/ValueText.h"

namespace coscope::dissect {

void dissectPdo(DissectCall& c) {
    Dissection& out = c.out;
    const bool tpdo = canopen::isTpdo(out.service);
    auto kindText = [&] { return (tpdo ? QStringLiteral("TPDO") : QStringLiteral("RPDO")) + QString::number(out.pdoNumber); };
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
    QString& s = out.summary;
    s.resize(0);
    s += kindText();
    s += QStringLiteral(" node ");
    s += QString::number(c.node);
    s += u':';
    if (!mapped) {
        s += u' ';
        s += hexBytes(c.data, c.len, true);
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
        PdoSignal& sig = out.addSignal();
        sig.index = e.index;
        sig.sub = e.sub;
        sig.bitOffset = static_cast<uint8_t>(at);
        sig.bitLength = e.bits;
        sig.name = e.name;
        sig.unit = e.unit;
        const QString text = decodeBits(e.type, e.typeKnown, c.data, at, e.bits, sig.value, e.unit, e.factor);
        if (first) s += u' ';
        else s += QLatin1String(", ");
        first = false;
        s += e.name;
        s += QLatin1String(" = ");
        s += text;
        const int byteOff = at / 8;
        const int byteLen = (at + e.bits + 7) / 8 - byteOff;
        if (out.wantTree())
            out.item(0, QStringLiteral("%1:%2 %3").arg(e.index, 4, 16, QLatin1Char('0')).arg(e.sub, 2, 16, QLatin1Char('0')).arg(e.name), text,
                     byteOff, byteLen, (at % 8 || e.bits % 8) ? at % 8 : -1, (at % 8 || e.bits % 8) ? e.bits : 0);
        if (e.index >= 0x6000 && e.index <= 0x67FF) {
            uint64_t raw = sig.value.kind == FlatField::Kind::Int ? static_cast<uint64_t>(sig.value.i) : sig.value.u;
            const QString m = ds402Meaning(e.index, e.sub, raw, out, 1, byteOff, byteLen);
            if (!m.isEmpty()) {
                s += QLatin1String(" (");
                s += m;
                s += u')';
            }
        }
    }
}

}  // namespace coscope::dissect
