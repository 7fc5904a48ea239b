// SPDX-License-Identifier: GPL-3.0-or-later
// Folder core/canopen/ owns CiA 301/402 protocol: codecs (NMT, SDO, PDO, EMCY, LSS, CiA 402) and
// the master services over a bus (SDO client, NMT master, SYNC, heartbeat monitor, LSS master,
// network scan, PDO configurator, CiA 402 controller, node settings), the node table and command
// scripts with their runner.
#pragma once

#include "core/can/CanBus.h"
#include "core/canopen/EnabledDrives.h"
#include "core/canopen/FrameDispatcher.h"
#include "core/canopen/NodeTable.h"
#include "core/canopen/SdoAbortTexts.h"

#include <QString>

#include <map>
#include <memory>
#include <mutex>

namespace coscope::canopen {

class PeriodicSender;

// What the master services share for one bus: the bus they send on, the dispatcher that brings
// them the frames they wait for (fed by the bus's one CaptureSession), the record of the drives
// CoScope enabled on it (disabled before the bus closes: DriveDisable.h), and the bus's node table
// (the services read each node's dictionary there, hence its vendor abort texts, and write what
// they learn). The owner keeps the bus, session, table and context alive longer than the services.
class MasterContext {
public:
    // `nodes`: the bus's node table (the application's); null = the context keeps its own.
    explicit MasterContext(CanBus* bus, NodeTable* nodes = nullptr);
    ~MasterContext();  // stops the periodic sender, if any

    CanBus* bus() const { return bus_; }
    FrameDispatcher& dispatcher() { return dispatcher_; }
    EnabledDrives& enabledDrives() { return enabledDrives_; }
    NodeTable& nodes() { return *nodes_; }
    const NodeTable& nodes() const { return *nodes_; }

    // Sends through CanBus::send (which enforces listen-only). On failure *error names the bus.
    bool send(const CanFrame& frame, QString* error);

    // The bus's one scheduler of periodic frames (SYNC, heartbeat, transmit list), created on
    // first use; thread-safe. It sends until this context is destroyed or its jobs are removed.
    PeriodicSender& periodic();

    // The dictionary a node matched (e.g. "delta-asda-a2"), kept in the node table; loads its
    // vendor abort table.
    void setNodeDictionary(uint8_t node, const QString& name);
    QString nodeDictionary(uint8_t node) const { return nodes_->dictionary(node); }
    // describeSdoAbort() with the node's vendor table.
    QString abortText(uint8_t node, uint32_t code) const;

private:
    std::shared_ptr<VendorAbortTable> abortTable(const QString& dictionary) const;

    CanBus* bus_;
    FrameDispatcher dispatcher_;
    EnabledDrives enabledDrives_;
    std::unique_ptr<NodeTable> ownNodes_;
    NodeTable* nodes_;
    mutable std::mutex mutex_;
    mutable std::map<QString, std::shared_ptr<VendorAbortTable>> tables_;
    std::unique_ptr<PeriodicSender> periodic_;  // under mutex_
};

}  // namespace coscope::canopen
