// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/PdoMapping.h"

#include "core/od/DataType.h"

#include <QRegularExpression>

namespace coscope::canopen {

uint32_t PdoId::defaultCobId(uint8_t node) const {
    if (number < 1 || number > 4) return 0x80000000u;
    return static_cast<uint32_t>((transmit ? 0x180 : 0x200) + 0x100 * (number - 1) + node);
}

std::optional<PdoId> parsePdoName(const QString& text) {
    static const QRegularExpression re(QStringLiteral("^([tr])pdo([0-9]{1,3})$"),
                                       QRegularExpression::CaseInsensitiveOption);
    const auto m = re.match(text.trimmed());
    if (!m.hasMatch()) return std::nullopt;
    const int n = m.captured(2).toInt();
    if (n < 1 || n > 512) return std::nullopt;
    return PdoId{m.captured(1).toLower() == u"t", n};
}

std::optional<std::vector<PdoMapEntry>> parsePdoEntries(const QString& text, QString* error) {
    static const QRegularExpression re(
        QStringLiteral("^(?:0x)?([0-9a-f]{1,4})(?::|sub)(?:0x)?([0-9a-f]{1,2})(?:/([0-9]{1,2}))?$"),
        QRegularExpression::CaseInsensitiveOption);
    std::vector<PdoMapEntry> out;
    for (const QString& part : text.split(u',', Qt::SkipEmptyParts)) {
        const auto m = re.match(part.trimmed());
        if (!m.hasMatch()) {
            if (error)
                *error =
                    QStringLiteral("'%1' is not an object reference IIII:SS (optionally /BITS)").arg(part.trimmed());
            return std::nullopt;
        }
        PdoMapEntry e;
        e.index = static_cast<uint16_t>(m.captured(1).toUInt(nullptr, 16));
        e.sub = static_cast<uint8_t>(m.captured(2).toUInt(nullptr, 16));
        e.bits = static_cast<uint8_t>(m.captured(3).isEmpty() ? 0 : m.captured(3).toUInt());
        out.push_back(e);
    }
    if (out.empty()) {
        if (error) *error = QStringLiteral("no objects to map");
        return std::nullopt;
    }
    return out;
}

int PdoConfig::totalBits() const {
    int bits = 0;
    for (const auto& e : entries) bits += e.bits;
    return bits;
}

bool validatePdoMapping(std::vector<PdoMapEntry>& entries, const PdoId& pdo, const od::ObjectDictionary* dict,
                        QString* error) {
    auto fail = [&](const QString& why) {
        if (error) *error = why;
        return false;
    };
    if (entries.size() > 64) return fail(QStringLiteral("%1 entries; a PDO maps at most 64").arg(entries.size()));
    int total = 0;
    for (auto& e : entries) {
        const QString ref =
            QStringLiteral("%1:%2").arg(e.index, 4, 16, QChar(u'0')).arg(e.sub, 2, 16, QChar(u'0')).toUpper();
        const bool dummy = e.index >= 0x0001 && e.index <= 0x0007 && e.sub == 0;  // CiA 301 §7.5.2.36 dummy mapping
        if (dummy) {
            if (!e.bits) e.bits = static_cast<uint8_t>(od::bitSize(static_cast<od::DataType>(e.index)));
        } else if (dict) {
            const od::SubObject* s = dict->entry(e.index, e.sub);
            if (!s) return fail(QStringLiteral("%1 does not exist in the dictionary").arg(ref));
            if (!s->pdoMappable)
                return fail(QStringLiteral("%1 (%2) is not PDO-mappable").arg(ref, dict->displayName(e.index, e.sub)));
            if (pdo.transmit && !od::isReadable(s->access))
                return fail(QStringLiteral("%1 is write-only and cannot go in a TPDO").arg(ref));
            if (!pdo.transmit && !od::isWritable(s->access))
                return fail(QStringLiteral("%1 is read-only and cannot go in an RPDO").arg(ref));
            const int typeBits = od::bitSize(s->dataType);
            if (typeBits == 0 && !e.bits)
                return fail(QStringLiteral("%1 has a variable-size type; give its length as %1/BITS").arg(ref));
            if (!e.bits) e.bits = static_cast<uint8_t>(typeBits);
        } else if (!e.bits) {
            return fail(QStringLiteral("no dictionary for this node: give the length of %1 as %1/BITS").arg(ref));
        }
        total += e.bits;
    }
    if (total > 64) return fail(QStringLiteral("the mapping has %1 bits; a PDO carries at most 64").arg(total));
    return true;
}

}  // namespace coscope::canopen
