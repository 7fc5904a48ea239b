// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstdint>
#include <optional>

namespace coscope::canopen {

// CANopen services as the decode JSON names them (DESIGN.md "Contracts").
enum class Service : uint8_t {
    Unknown,
    Nmt,
    Sync,
    Time,
    Emcy,
    Tpdo1,
    Rpdo1,
    Tpdo2,
    Rpdo2,
    Tpdo3,
    Rpdo3,
    Tpdo4,
    Rpdo4,
    SdoRequest,       // client -> server (600h + node)
    SdoResponse,      // server -> client (580h + node)
    NmtErrorControl,  // boot-up, heartbeat, node guarding (700h + node)
    LssRequest,       // master -> slave, 7E5h
    LssResponse,      // slave -> master, 7E4h
};

// "NMT", "SYNC", "TPDO1", "SDO_REQ", "NMT_EC", "LSS_RESP", "UNKNOWN", ...
QString serviceName(Service s);
std::optional<Service> serviceFromName(const QString& name);

constexpr bool isTpdo(Service s) {
    return s == Service::Tpdo1 || s == Service::Tpdo2 || s == Service::Tpdo3 || s == Service::Tpdo4;
}
constexpr bool isRpdo(Service s) {
    return s == Service::Rpdo1 || s == Service::Rpdo2 || s == Service::Rpdo3 || s == Service::Rpdo4;
}
// 0..3 for TPDO1..4 / RPDO1..4, -1 otherwise.
constexpr int pdoNumber(Service s) {
    switch (s) {
    case Service::Tpdo1:
    case Service::Rpdo1: return 0;
    case Service::Tpdo2:
    case Service::Rpdo2: return 1;
    case Service::Tpdo3:
    case Service::Rpdo3: return 2;
    case Service::Tpdo4:
    case Service::Rpdo4: return 3;
    default: return -1;
    }
}

struct CobIdInfo {
    Service service = Service::Unknown;
    int node = -1;  // 1..127 where the service carries a node-ID, else -1
};

namespace detail {
// The pre-defined connection set (CiA 301 §7.3.5, Table 43) of one 11-bit identifier.
constexpr CobIdInfo classifyStandard(uint32_t id) {
    if (id == 0x000) return {Service::Nmt, -1};
    if (id == 0x080) return {Service::Sync, -1};
    if (id == 0x100) return {Service::Time, -1};
    if (id == 0x7E5) return {Service::LssRequest, -1};  // CiA 305 §4
    if (id == 0x7E4) return {Service::LssResponse, -1};
    // Function code (bits 10..7) -> service of the node-addressed objects.
    constexpr Service kByFunction[16] = {
        Service::Unknown,  // 0000: NMT (id 0) only
        Service::Emcy,     // 0001: SYNC at 080h, EMCY at 081h..0FFh
        Service::Unknown,  // 0010: TIME at 100h only
        Service::Tpdo1,
        Service::Rpdo1,
        Service::Tpdo2,
        Service::Rpdo2,
        Service::Tpdo3,
        Service::Rpdo3,
        Service::Tpdo4,
        Service::Rpdo4,
        Service::SdoResponse,      // 1011: 580h + node
        Service::SdoRequest,       // 1100: 600h + node
        Service::Unknown,          // 1101
        Service::NmtErrorControl,  // 1110: 700h + node
        Service::Unknown,          // 1111: LSS 7E4h/7E5h above
    };
    const int node = static_cast<int>(id & 0x7F);
    const Service s = kByFunction[(id >> 7) & 0xF];
    if (s == Service::Unknown || node == 0) return {};
    return {s, node};
}
struct StandardCobIds {
    CobIdInfo info[0x800];
    constexpr StandardCobIds() : info() {
        for (uint32_t id = 0; id < 0x800; ++id) info[id] = classifyStandard(id);
    }
};
inline constexpr StandardCobIds kStandardCobIds;  // one table read per frame
}  // namespace detail

// Classifies an 11-bit identifier by the CiA 301 pre-defined connection set (CiA 301 §7.3.5,
// Table 43) plus LSS (CiA 305 §4: 7E4h/7E5h). Extended ids are Unknown. The PDO mapping in
// force may move PDOs elsewhere; the network context handles that.
inline CobIdInfo classifyCobId(uint32_t id, bool extended = false) {
    return extended || id > 0x7FF ? CobIdInfo{} : detail::kStandardCobIds.info[id];
}

// Default COB-ID of a service for a node (e.g. TPDO1 of node 5 -> 185h).
uint32_t defaultCobId(Service s, int node);

}  // namespace coscope::canopen
