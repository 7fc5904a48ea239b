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
    {Service::Nmt, "NMT"},           {Service::Sync, "SYNC"},       {Service::Time, "TIME"},
    {Service::Emcy, "EMCY"},         {Service::Tpdo1, "TPDO1"},     {Service::Rpdo1, "RPDO1"},
    {Service::Tpdo2, "TPDO2"},       {Service::Rpdo2, "RPDO2"},     {Service::Tpdo3, "TPDO3"},
    {Service::Rpdo3, "RPDO3"},       {Service::Tpdo4, "TPDO4"},     {Service::Rpdo4, "RPDO4"},
    {Service::SdoRequest, "SDO_REQ"}, {Service::SdoResponse, "SDO_RESP"}, {Service::NmtErrorControl, "NMT_EC"},
    {Service::LssRequest, "LSS_REQ"}, {Service::LssResponse, "LSS_RESP"}, {Service::Unknown, "UNKNOWN"},
    {Service::Unknown, "UNKNOWN"},
}};

// Function code (bits 10..7) -> service for node-addressed objects (CiA 301 Table 43).
constexpr Service kByFunction[16] = {
    Service::Unknown,      // 0000: NMT (id 0) only
    Service::Emcy,         // 0001: SYNC at 080h, EMCY at 081h..0FFh
    Service::Time,         // 0010: TIME at 100h
    Service::Tpdo1, Service::Rpdo1, Service::Tpdo2, Service::Rpdo2, Service::Tpdo3, Service::Rpdo3,
    Service::Tpdo4, Service::Rpdo4,
    Service::SdoResponse,  // 1011: 580h + node
    Service::SdoRequest,   // 1100: 600h + node
    Service::Unknown,      // 1101
    Service::NmtErrorControl,  // 1110: 700h + node
    Service::Unknown,      // 1111: LSS 7E4h/7E5h handled before
};
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

bool isTpdo(Service s) { return s == Service::Tpdo1 || s == Service::Tpdo2 || s == Service::Tpdo3 || s == Service::Tpdo4; }
bool isRpdo(Service s) { return s == Service::Rpdo1 || s == Service::Rpdo2 || s == Service::Rpdo3 || s == Service::Rpdo4; }

int pdoNumber(Service s) {
    switch (s) {
    case Service::Tpdo1: case Service::Rpdo1: return 0;
    case Service::Tpdo2: case Service::Rpdo2: return 1;
    case Service::Tpdo3: case Service::Rpdo3: return 2;
    case Service::Tpdo4: case Service::Rpdo4: return 3;
    default: return -1;
    }
}

CobIdInfo classifyCobId(uint32_t id, bool extended) {
    if (extended || id > 0x7FF) return {};
    if (id == 0x000) return {Service::Nmt, -1};
    if (id == 0x080) return {Service::Sync, -1};
    if (id == 0x100) return {Service::Time, -1};
    if (id == 0x7E5) return {Service::LssRequest, -1};
    if (id == 0x7E4) return {Service::LssResponse, -1};
    const int node = static_cast<int>(id & 0x7F);
    const Service s = kByFunction[(id >> 7) & 0xF];
    if (s == Service::Unknown || s == Service::Time || node == 0) return {};
    return {s, node};
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
