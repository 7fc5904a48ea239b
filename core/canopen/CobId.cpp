// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/CobId.h"

#include <array>

namespace coscope::canopen {

namespace {
struct Entry {
    Service service;
    const char* name;
};
constexpr std::array<Entry, 19> kNames{{
    {Service::Nmt, "NMT"},
    {Service::Sync, "SYNC"},
    {Service::Time, "TIME"},
    {Service::Emcy, "EMCY"},
    {Service::Tpdo1, "TPDO1"},
    {Service::Rpdo1, "RPDO1"},
    {Service::Tpdo2, "TPDO2"},
    {Service::Rpdo2, "RPDO2"},
    {Service::Tpdo3, "TPDO3"},
    {Service::Rpdo3, "RPDO3"},
    {Service::Tpdo4, "TPDO4"},
    {Service::Rpdo4, "RPDO4"},
    {Service::SdoRequest, "SDO_REQ"},
    {Service::SdoResponse, "SDO_RESP"},
    {Service::NmtErrorControl, "NMT_EC"},
    {Service::LssRequest, "LSS_REQ"},
    {Service::LssResponse, "LSS_RESP"},
    {Service::Unknown, "UNKNOWN"},
    {Service::Unknown, "UNKNOWN"},
}};

}  // namespace

QString serviceName(Service s) {
    for (const auto& e : kNames)
        if (e.service == s) return QString::fromLatin1(e.name);
    return QStringLiteral("UNKNOWN");
}

std::optional<Service> serviceFromName(const QString& name) {
    const QString up = name.trimmed().toUpper();
    for (const auto& e : kNames)
        if (up == QLatin1String(e.name)) return e.service;
    return std::nullopt;
}

uint32_t defaultCobId(Service s, int node) {
    const auto n = static_cast<uint32_t>(node & 0x7F);
    switch (s) {
    case Service::Nmt: return 0x000;
    case Service::Sync: return 0x080;
    case Service::Time: return 0x100;
    case Service::Emcy: return 0x080 + n;
    case Service::Tpdo1: return 0x180 + n;
    case Service::Rpdo1: return 0x200 + n;
    case Service::Tpdo2: return 0x280 + n;
    case Service::Rpdo2: return 0x300 + n;
    case Service::Tpdo3: return 0x380 + n;
    case Service::Rpdo3: return 0x400 + n;
    case Service::Tpdo4: return 0x480 + n;
    case Service::Rpdo4: return 0x500 + n;
    case Service::SdoResponse: return 0x580 + n;
    case Service::SdoRequest: return 0x600 + n;
    case Service::NmtErrorControl: return 0x700 + n;
    case Service::LssRequest: return 0x7E5;
    case Service::LssResponse: return 0x7E4;
    case Service::Unknown: break;
    }
    return 0;
}

}  // namespace coscope::canopen
