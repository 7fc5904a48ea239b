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
    Tpdo1, Rpdo1, Tpdo2, Rpdo2, Tpdo3, Rpdo3, Tpdo4, Rpdo4,
    SdoRequest,   // client -> server (600h + node)
    SdoResponse,  // server -> client (580h + node)
    NmtErrorControl,  // boot-up, heartbeat, node guarding (700h + node)
    LssRequest,   // master -> slave, 7E5h
    LssResponse,  // slave -> master, 7E4h
};

// "NMT", "SYNC", "TPDO1", "SDO_REQ", "NMT_EC", "LSS_RESP", "UNKNOWN", ...
QString serviceName(Service s);
std::optional<Service> serviceFromName(const QString& name);

bool isTpdo(Service s);
bool isRpdo(Service s);
// 0..3 for TPDO1..4 / RPDO1..4, -1 otherwise.
int pdoNumber(Service s);

struct CobIdInfo {
    Service service = Service::Unknown;
    int node = -1;  // 1..127 where the service carries a node-ID, else -1
};

// Classifies an 11-bit identifier by the CiA 301 pre-defined connection set (CiA 301 §7.3.5,
// Table 43) plus LSS (CiA 305 §4: 7E4h/7E5h). Extended ids are Unknown. The PDO mapping in
// force may move PDOs elsewhere; the network context handles that.
CobIdInfo classifyCobId(uint32_t id, bool extended = false);

// Default COB-ID of a service for a node (e.g. TPDO1 of node 5 -> 185h).
uint32_t defaultCobId(Service s, int node);

}  // namespace coscope::canopen
