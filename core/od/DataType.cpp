// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/od/DataType.h"

#include <array>

namespace coscope::od {

namespace {

struct TypeInfo {
    DataType type;
    const char* name;
    int bits;
    TypeClass cls;
};

// CiA 301 v4.2, 7.1.4 (basic data types) and 7.4.7.1 (data type entry indices).
constexpr std::array<TypeInfo, 25> kTypes{{
    {DataType::Boolean, "BOOLEAN", 1, TypeClass::Boolean},
    {DataType::Integer8, "INTEGER8", 8, TypeClass::Signed},
    {DataType::Integer16, "INTEGER16", 16, TypeClass::Signed},
    {DataType::Integer32, "INTEGER32", 32, TypeClass::Signed},
    {DataType::Unsigned8, "UNSIGNED8", 8, TypeClass::Unsigned},
    {DataType::Unsigned16, "UNSIGNED16", 16, TypeClass::Unsigned},
    {DataType::Unsigned32, "UNSIGNED32", 32, TypeClass::Unsigned},
    {DataType::Real32, "REAL32", 32, TypeClass::Real},
    {DataType::VisibleString, "VISIBLE_STRING", 0, TypeClass::VisibleString},
    {DataType::OctetString, "OCTET_STRING", 0, TypeClass::OctetString},
    {DataType::UnicodeString, "UNICODE_STRING", 0, TypeClass::UnicodeString},
    {DataType::TimeOfDay, "TIME_OF_DAY", 48, TypeClass::Time},
    {DataType::TimeDifference, "TIME_DIFFERENCE", 48, TypeClass::Time},
    {DataType::Domain, "DOMAIN", 0, TypeClass::Domain},
    {DataType::Integer24, "INTEGER24", 24, TypeClass::Signed},
    {DataType::Real64, "REAL64", 64, TypeClass::Real},
    {DataType::Integer40, "INTEGER40", 40, TypeClass::Signed},
    {DataType::Integer48, "INTEGER48", 48, TypeClass::Signed},
    {DataType::Integer56, "INTEGER56", 56, TypeClass::Signed},
    {DataType::Integer64, "INTEGER64", 64, TypeClass::Signed},
    {DataType::Unsigned24, "UNSIGNED24", 24, TypeClass::Unsigned},
    {DataType::Unsigned40, "UNSIGNED40", 40, TypeClass::Unsigned},
    {DataType::Unsigned48, "UNSIGNED48", 48, TypeClass::Unsigned},
    {DataType::Unsigned56, "UNSIGNED56", 56, TypeClass::Unsigned},
    {DataType::Unsigned64, "UNSIGNED64", 64, TypeClass::Unsigned},
}};

const TypeInfo* find(DataType t) {
    for (const auto& i : kTypes)
        if (i.type == t) return &i;
    return nullptr;
}

}  // namespace

TypeClass typeClass(DataType t) {
    const TypeInfo* i = find(t);
    return i ? i->cls : TypeClass::Domain;
}

int bitSize(DataType t) {
    const TypeInfo* i = find(t);
    return i ? i->bits : 0;
}

int byteSize(DataType t) {
    if (t == DataType::Boolean) return 1;
    return (bitSize(t) + 7) / 8;
}

QString dataTypeName(DataType t) {
    if (const TypeInfo* i = find(t)) return QString::fromLatin1(i->name);
    switch (t) {
    case DataType::PdoCommunicationParameter: return QStringLiteral("PDO_COMMUNICATION_PARAMETER");
    case DataType::PdoMapping: return QStringLiteral("PDO_MAPPING");
    case DataType::SdoParameter: return QStringLiteral("SDO_PARAMETER");
    case DataType::Identity: return QStringLiteral("IDENTITY");
    default: break;
    }
    return QStringLiteral("DATATYPE_") +
           QString::number(static_cast<unsigned>(t), 16).rightJustified(4, QLatin1Char('0')).toUpper();
}

std::optional<DataType> dataTypeFromString(const QString& text) {
    const QString s = text.trimmed();
    for (const auto& i : kTypes)
        if (s.compare(QLatin1String(i.name), Qt::CaseInsensitive) == 0) return i.type;
    bool ok = false;
    uint v = 0;
    if (s.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)) v = s.mid(2).toUInt(&ok, 16);
    else v = s.toUInt(&ok, 10);
    if (!ok || v > 0xFFFF) return std::nullopt;
    return static_cast<DataType>(v);
}

bool isKnownBasicType(DataType t) { return find(t) != nullptr; }
bool isInteger(DataType t) {
    const auto c = typeClass(t);
    return c == TypeClass::Signed || c == TypeClass::Unsigned;
}
bool isSigned(DataType t) { return typeClass(t) == TypeClass::Signed; }
bool isString(DataType t) {
    const auto c = typeClass(t);
    return c == TypeClass::VisibleString || c == TypeClass::UnicodeString;
}

}  // namespace coscope::od
