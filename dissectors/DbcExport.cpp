// SPDX-License-Identifier: GPL-3.0-or-later
#include "dissectors/DbcExport.h"

#include "dissectors/SignalScaling.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace coscope::dissect {

namespace {
struct DbcSignal {
    QByteArray name;
    int start = 0;
    int length = 0;
    bool motorola = false;
    bool isSigned = false;
    int floatBits = 0;  // 32/64 for IEEE floats (SIG_VALTYPE_)
    double factor = 1.0;
    double offset = 0.0;
    QString unit;
    QByteArray receiver = "Vector__XXX";
    QString comment;
};
struct DbcMessage {
    uint32_t id = 0;  // DBC id: bit 31 set for 29-bit identifiers
    QByteArray name;
    int dlc = 0;
    QByteArray transmitter = "Vector__XXX";
    QString comment;
    std::vector<DbcSignal> sigs;
};

QByteArray num(double v) { return QByteArray::number(v, 'g', 15); }
QByteArray quoted(const QString& text) {
    QString t = text;
    t.replace(u'"', u'\'');
    return '"' + t.toUtf8() + '"';
}
QByteArray nodeName(int node) { return "Node" + QByteArray::number(node); }

// Range of the physical value, as [min|max].
std::pair<double, double> range(const DbcSignal& s) {
    if (s.floatBits || s.length >= 64) return {0, 0};
    const double span = std::ldexp(1.0, s.length);
    double lo = s.isSigned ? -span / 2 : 0;
    double hi = s.isSigned ? span / 2 - 1 : span - 1;
    lo = lo * s.factor + s.offset;
    hi = hi * s.factor + s.offset;
    return {std::min(lo, hi), std::max(lo, hi)};
}

void addSignal(DbcMessage& m, DbcSignal s) {
    std::set<QByteArray> names;
    for (const DbcSignal& o : m.sigs) names.insert(o.name);
    const QByteArray base = s.name;
    for (int k = 2; names.count(s.name); ++k) s.name = base + '_' + QByteArray::number(k);
    m.sigs.push_back(std::move(s));
}

uint32_t defaultCobId(bool tpdo, int number, int node) {
    if (number < 1 || number > 4) return 0;
    return static_cast<uint32_t>((tpdo ? 0x180 : 0x200) + 0x100 * (number - 1) + node);
}
}  // namespace

QByteArray dbcIdentifier(const QString& name) {
    QByteArray out;
    for (const QChar c : name) {
        const char l = c.toLatin1();
        const bool ok = (l >= 'a' && l <= 'z') || (l >= 'A' && l <= 'Z') || (l >= '0' && l <= '9');
        if (ok) out += l;
        else if (!out.isEmpty() && !out.endsWith('_')) out += '_';
    }
    while (out.endsWith('_')) out.chop(1);
    if (out.isEmpty()) out = "signal";
    if (out[0] >= '0' && out[0] <= '9') out.prepend("s_");
    return out;
}

QByteArray pdoLayoutDbc(const NetworkContext& ctx, const std::vector<RawSignal>& raw, int bus, int* pdos) {
    std::map<uint32_t, DbcMessage> messages;  // by DBC id
    std::set<int> nodes;
    for (int node = 1; node < 128; ++node) {
        const NodeState& ns = ctx.node(bus, node);
        if (!ns.seen && !ns.dictionary) continue;
        for (int dir = 0; dir < 2; ++dir) {
            const bool tpdo = dir == 1;
            const auto& list = tpdo ? ns.tpdo : ns.rpdo;
            for (size_t p = 0; p < list.size(); ++p) {
                const PdoConfig& cfg = list[p];
                const int number = static_cast<int>(p) + 1;
                if (!cfg.mappingKnown || cfg.count == 0 || (cfg.cobIdKnown && !cfg.valid())) continue;
                const uint32_t can = cfg.cobIdKnown ? cfg.canId() : defaultCobId(tpdo, number, node);
                if (!can) continue;
                const bool ext = cfg.cobIdKnown && (cfg.cobId & 0x20000000u);
                DbcMessage m;
                m.id = can | (ext ? 0x80000000u : 0);
                const QString kind = (tpdo ? QStringLiteral("TPDO") : QStringLiteral("RPDO")) + QString::number(number);
                m.name = kind.toLatin1() + "_node" + QByteArray::number(node);
                m.comment =
                    QStringLiteral("%1 of node %2%3")
                        .arg(kind)
                        .arg(node)
                        .arg(ns.dictionaryName.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(ns.dictionaryName));
                m.dlc = (cfg.mappedBits() + 7) / 8;
                if (tpdo) m.transmitter = nodeName(node);
                nodes.insert(node);
                int bit = 0;
                for (int k = 0; k < cfg.count && k < static_cast<int>(cfg.entries.size()); ++k) {
                    const PdoMapEntry& e = cfg.entries[static_cast<size_t>(k)];
                    const int at = bit;
                    bit += e.bits;
                    if (e.dummy || e.bits == 0) continue;
                    DbcSignal s;
                    s.name = dbcIdentifier(e.name);
                    s.start = at;
                    s.length = e.bits;
                    const od::TypeClass cls = e.typeKnown ? od::typeClass(e.type) : od::TypeClass::Unsigned;
                    s.isSigned = cls == od::TypeClass::Signed;
                    if (cls == od::TypeClass::Real) s.floatBits = e.bits;
                    if (!e.unit.isEmpty()) {
                        s.factor = e.factor;
                        s.unit = e.unit;
                    } else if (const auto u = sidecarUnit(ns.dictionaryName, e.index, e.sub)) {
                        s.factor = u->factor;
                        s.unit = u->unit;
                    }
                    if (!tpdo) s.receiver = nodeName(node);
                    s.comment = QStringLiteral("%1:%2 %3")
                                    .arg(e.index, 4, 16, QLatin1Char('0'))
                                    .arg(e.sub, 2, 16, QLatin1Char('0'))
                                    .toUpper()
                                    .arg(e.name);
                    addSignal(m, std::move(s));
                }
                if (m.sigs.empty()) continue;
                if (messages.count(m.id)) continue;  // two PDOs on one COB-ID: the first
                if (pdos) ++*pdos;
                messages.emplace(m.id, std::move(m));
            }
        }
    }
    for (const RawSignal& r : raw) {
        const uint32_t id = r.cobId | (r.extended ? 0x80000000u : 0);
        auto it = messages.find(id);
        if (it == messages.end()) {
            DbcMessage m;
            m.id = id;
            m.name = "RAW_" + QByteArray::number(r.cobId, 16).toUpper() + 'h';
            m.comment = QStringLiteral("raw signals of COB-ID %1h").arg(QString::number(r.cobId, 16).toUpper());
            m.dlc = 8;
            it = messages.emplace(id, std::move(m)).first;
        }
        DbcSignal s;
        s.name = dbcIdentifier(r.name);
        s.start = r.startBit;
        s.length = r.length;
        s.motorola = r.order == RawSignal::Order::Motorola;
        s.isSigned = r.type == RawSignal::Type::Signed;
        if (r.type == RawSignal::Type::Float) s.floatBits = r.length;
        s.factor = r.factor;
        s.offset = r.offset;
        s.unit = r.unit;
        s.comment = QStringLiteral("raw signal %1").arg(r.spec());
        it->second.dlc = std::max(it->second.dlc, std::min(r.bytesNeeded(), 64));
        addSignal(it->second, std::move(s));
    }

    QByteArray out;
    out += "VERSION \"\"\n\n\nNS_ :\n";
    for (const char* ns : {"NS_DESC_",     "CM_",
                           "BA_DEF_",      "BA_",
                           "VAL_",         "CAT_DEF_",
                           "CAT_",         "FILTER",
                           "BA_DEF_DEF_",  "EV_DATA_",
                           "ENVVAR_DATA_", "SGTYPE_",
                           "SGTYPE_VAL_",  "BA_DEF_SGTYPE_",
                           "BA_SGTYPE_",   "SIG_TYPE_REF_",
                           "VAL_TABLE_",   "SIG_GROUP_",
                           "SIG_VALTYPE_", "SIGTYPE_VALTYPE_",
                           "BO_TX_BU_",    "BA_DEF_REL_",
                           "BA_REL_",      "BA_DEF_DEF_REL_",
                           "BU_SG_REL_",   "BU_EV_REL_",
                           "BU_BO_REL_",   "SG_MUL_VAL_"})
        out += QByteArray("\t") + ns + '\n';
    out += "\nBS_:\n\nBU_:";
    for (int n : nodes) out += ' ' + nodeName(n);
    out += "\n\n";
    for (const auto& [id, m] : messages) {
        out += "BO_ " + QByteArray::number(id) + ' ' + m.name + ": " + QByteArray::number(m.dlc) + ' ' + m.transmitter +
               '\n';
        for (const DbcSignal& s : m.sigs) {
            const auto [lo, hi] = range(s);
            out += " SG_ " + s.name + " : " + QByteArray::number(s.start) + '|' + QByteArray::number(s.length) + '@' +
                   (s.motorola ? '0' : '1') + (s.isSigned || s.floatBits ? '-' : '+') + " (" + num(s.factor) + ',' +
                   num(s.offset) + ") [" + num(lo) + '|' + num(hi) + "] " + quoted(s.unit) + ' ' + s.receiver + '\n';
        }
        out += '\n';
    }
    for (const auto& [id, m] : messages) {
        out += "CM_ BO_ " + QByteArray::number(id) + ' ' + quoted(m.comment) + ";\n";
        for (const DbcSignal& s : m.sigs)
            out += "CM_ SG_ " + QByteArray::number(id) + ' ' + s.name + ' ' + quoted(s.comment) + ";\n";
    }
    for (const auto& [id, m] : messages)
        for (const DbcSignal& s : m.sigs)
            if (s.floatBits)
                out += "SIG_VALTYPE_ " + QByteArray::number(id) + ' ' + s.name + " : " +
                       (s.floatBits == 64 ? '2' : '1') + ";\n";
    return out;
}

}  // namespace coscope::dissect
