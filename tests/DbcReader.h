// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A small DBC reader for tests (Debian 12 ships no DBC parser: no cantools, no canmatrix). It
// checks the lines against the DBC grammar (Vector "DBC File Format Documentation" 1.0.5):
// VERSION "..", NS_ :, BS_:, BU_: names, BO_ id name: dlc transmitter,
// SG_ name : start|len@order sign (factor,offset) [min|max] "unit" receivers, CM_ ... ;,
// SIG_VALTYPE_ id name : 1|2 ; and decodes payloads with its own bit walk.

#include <QByteArray>
#include <QRegularExpression>
#include <QString>
#include <QStringList>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <optional>
#include <vector>

namespace dbc {

struct Signal {
    QString name;
    int start = 0, length = 0;
    bool intel = true, isSigned = false;
    int valType = 0;  // 0 integer, 1 float, 2 double
    double factor = 1, offset = 0, min = 0, max = 0;
    QString unit, comment;
    QStringList receivers;
};
struct Message {
    uint32_t id = 0;
    QString name, transmitter, comment;
    int dlc = 0;
    std::vector<Signal> sigs;
    const Signal* find(const QString& n) const {
        for (const Signal& s : sigs)
            if (s.name == n) return &s;
        return nullptr;
    }
};
struct File {
    QStringList nodes;
    std::map<uint32_t, Message> messages;
    QStringList errors;  // grammar violations, "line N: ..."
};

inline File parse(const QByteArray& text) {
    File f;
    const QString ident = QStringLiteral("[A-Za-z_][A-Za-z0-9_]*");
    const QString numRe = QStringLiteral("[-+]?[0-9.]+(?:[eE][-+]?[0-9]+)?");
    const QRegularExpression bo(QStringLiteral("^BO_ ([0-9]+) (%1): ([0-9]+) (%1)$").arg(ident));
    const QRegularExpression sg(QStringLiteral("^ SG_ (%1) : ([0-9]+)\\|([0-9]+)@([01])([+-]) \\((%2),(%2)\\) "
                                               "\\[(%2)\\|(%2)\\] \"([^\"]*)\" (%1(?:,%1)*)$")
                                    .arg(ident, numRe));
    const QRegularExpression cmBo(QStringLiteral("^CM_ BO_ ([0-9]+) \"([^\"]*)\";$"));
    const QRegularExpression cmSg(QStringLiteral("^CM_ SG_ ([0-9]+) (%1) \"([^\"]*)\";$").arg(ident));
    const QRegularExpression valType(QStringLiteral("^SIG_VALTYPE_ ([0-9]+) (%1) : ([12]);$").arg(ident));
    const QRegularExpression bu(QStringLiteral("^BU_:((?: %1)*)$").arg(ident));
    const QList<QByteArray> lines = text.split('\n');
    Message* current = nullptr;
    bool version = false, ns = false, bs = false, buSeen = false;
    bool inNs = false;
    for (int i = 0; i < lines.size(); ++i) {
        const QString l = QString::fromUtf8(lines[i]);
        auto err = [&](const QString& what) { f.errors << QStringLiteral("line %1: %2: %3").arg(i + 1).arg(what, l); };
        if (inNs) {
            if (l.startsWith(u'\t')) continue;
            inNs = false;
        }
        if (l.trimmed().isEmpty()) {
            current = nullptr;
            continue;
        }
        QRegularExpressionMatch m;
        if (l.startsWith(QStringLiteral("VERSION "))) {
            version = QRegularExpression(QStringLiteral("^VERSION \"[^\"]*\"$")).match(l).hasMatch();
            if (!version) err(QStringLiteral("bad VERSION"));
        } else if (l == QStringLiteral("NS_ :")) {
            ns = inNs = true;
        } else if (l == QStringLiteral("BS_:")) {
            bs = true;
        } else if ((m = bu.match(l)).hasMatch()) {
            buSeen = true;
            f.nodes = m.captured(1).split(u' ', Qt::SkipEmptyParts);
        } else if ((m = bo.match(l)).hasMatch()) {
            Message msg;
            msg.id = m.captured(1).toUInt();
            msg.name = m.captured(2);
            msg.dlc = m.captured(3).toInt();
            msg.transmitter = m.captured(4);
            if (msg.transmitter != QStringLiteral("Vector__XXX") && !f.nodes.contains(msg.transmitter))
                err(QStringLiteral("transmitter not in BU_"));
            if (f.messages.count(msg.id)) err(QStringLiteral("duplicate message id"));
            current = &(f.messages[msg.id] = msg);
        } else if ((m = sg.match(l)).hasMatch()) {
            if (!current) {
                err(QStringLiteral("SG_ outside a BO_"));
                continue;
            }
            Signal s;
            s.name = m.captured(1);
            s.start = m.captured(2).toInt();
            s.length = m.captured(3).toInt();
            s.intel = m.captured(4) == u"1";
            s.isSigned = m.captured(5) == u"-";
            s.factor = m.captured(6).toDouble();
            s.offset = m.captured(7).toDouble();
            s.min = m.captured(8).toDouble();
            s.max = m.captured(9).toDouble();
            s.unit = m.captured(10);
            s.receivers = m.captured(11).split(u',');
            if (current->find(s.name)) err(QStringLiteral("duplicate signal name"));
            if (s.length < 1 || s.length > 64) err(QStringLiteral("bad length"));
            current->sigs.push_back(s);
        } else if ((m = cmBo.match(l)).hasMatch()) {
            if (!f.messages.count(m.captured(1).toUInt())) err(QStringLiteral("comment of an unknown message"));
            else f.messages[m.captured(1).toUInt()].comment = m.captured(2);
        } else if ((m = cmSg.match(l)).hasMatch() || (m = valType.match(l)).hasMatch()) {
            auto it = f.messages.find(m.captured(1).toUInt());
            Signal* s = nullptr;
            if (it != f.messages.end())
                for (Signal& x : it->second.sigs)
                    if (x.name == m.captured(2)) s = &x;
            if (!s) err(QStringLiteral("refers to an unknown signal"));
            else if (l.startsWith(QStringLiteral("CM_"))) s->comment = m.captured(3);
            else s->valType = m.captured(3).toInt();
        } else {
            err(QStringLiteral("not DBC"));
        }
    }
    if (!version || !ns || !bs || !buSeen) f.errors << QStringLiteral("missing VERSION, NS_, BS_ or BU_");
    return f;
}

// The physical value of `s` in `data` (DBC semantics: Intel LSB first from the start bit;
// Motorola from the start bit = MSB, 7..0 within a byte, then the next byte's bit 7).
inline std::optional<double> decode(const Signal& s, const QByteArray& data) {
    auto bit = [&](int pos) -> std::optional<int> {
        if (pos / 8 >= data.size()) return std::nullopt;
        return (uint8_t(data[pos / 8]) >> (pos % 8)) & 1;
    };
    uint64_t raw = 0;
    if (s.intel) {
        for (int k = 0; k < s.length; ++k) {
            const auto b = bit(s.start + k);
            if (!b) return std::nullopt;
            raw |= uint64_t(*b) << k;
        }
    } else {
        int pos = s.start;
        for (int k = 0; k < s.length; ++k) {
            const auto b = bit(pos);
            if (!b) return std::nullopt;
            raw = raw << 1 | uint64_t(*b);
            pos = pos % 8 == 0 ? pos + 15 : pos - 1;
        }
    }
    double v;
    if (s.valType == 1) {
        float x;
        const auto u = uint32_t(raw);
        std::memcpy(&x, &u, 4);
        v = x;
    } else if (s.valType == 2) {
        std::memcpy(&v, &raw, 8);
    } else if (s.isSigned && s.length < 64 && (raw >> (s.length - 1)) & 1) {
        v = double(int64_t(raw) - (int64_t(1) << s.length));
    } else {
        v = s.isSigned ? double(int64_t(raw)) : double(raw);
    }
    return v * s.factor + s.offset;
}

}  // namespace dbc
