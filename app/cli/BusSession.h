// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanBus.h"
#include "core/canopen/BusMaster.h"
#include "core/canopen/MasterContext.h"
#include "core/canopen/SdoClient.h"
#include "core/od/ObjectDictionary.h"
#include "core/trace/CaptureSession.h"

#include <QString>

#include <memory>
#include <optional>

namespace coscope::cli {

// What the service verbs (sdo, nmt, scan, lss, pdo, ds402) share: opens a bus, runs its one
// reader (a CaptureSession) feeding the master services' dispatcher, and owns an SDO client.
// The verbs then wait for results with canopen::waitUntil (the CLI may wait; the GUI never does).
class BusSession {
public:
    BusSession();
    ~BusSession();

    // Opens `url` and waits until it is open. sim:// gets the bundled dictionaries installed.
    bool open(const QString& url, QString* error, int timeoutMs = 5000);

    CanBus* bus() const { return bus_.get(); }
    canopen::MasterContext& context() { return *context_; }
    canopen::SdoClient& sdo() { return *sdo_; }
    // The bus's periodic master services (SYNC, heartbeat, transmit list); stopped before the
    // bus closes.
    canopen::BusMaster& master() { return *master_; }

    // The dictionary of a node: `dictOption` (a file or a library name) when given, otherwise
    // the library's match for the node's 1018h identity (read over SDO). nullopt when none;
    // *name gets the dictionary name, *error why nothing matched (not fatal for callers).
    std::optional<od::ObjectDictionary> nodeDictionary(uint8_t node, const QString& dictOption, QString* name,
                                                       QString* error);

private:
    std::unique_ptr<CanBus> bus_;
    std::unique_ptr<CaptureSession> session_;
    std::unique_ptr<canopen::MasterContext> context_;
    std::unique_ptr<canopen::SdoClient> sdo_;
    std::unique_ptr<canopen::BusMaster> master_;
};

// "5" / "0x05" -> 1..127; with allowAll "all" -> 0.
std::optional<uint8_t> parseNodeId(const QString& text, bool allowAll = false);
// "6041:00", "0x6041:0", "6041sub0", "6041" (sub 0).
bool parseObjectRef(const QString& text, uint16_t* index, uint8_t* sub);

}  // namespace coscope::cli
