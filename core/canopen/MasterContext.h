// SPDX-License-Identifier: GPL-3.0-or-later
// Folder core/canopen/ owns CiA 301/402 protocol: codecs (NMT, SDO, PDO, EMCY, LSS, CiA 402) and
// the master services over a bus (SDO client, NMT master, SYNC, heartbeat monitor, LSS master,
// network scan, PDO configurator, CiA 402 controller, node settings), the node table and command
// scripts with their runner.
#pragma once

#include "core/can/CanBus.h"
#include "core/canopen/FrameDispatcher.h"
#include "core/canopen/SdoAbortTexts.h"

#include <QString>

#include <map>
#include <memory>
#include <mutex>

namespace coscope::canopen {

// What the master services share for one bus: the bus they send on, the dispatcher that brings
// them the frames they wait for (fed by the bus's one CaptureSession), and per-node facts the
// services need to word their results (the node's dictionary, hence its vendor abort texts).
// The owner keeps the bus, session and context alive longer than the services.
class MasterContext {
public:
    explicit MasterContext(CanBus* bus);

    CanBus* bus() const { return bus_; }
    FrameDispatcher& dispatcher() { return dispatcher_; }

    // Sends through CanBus::send (which enforces listen-only). On failure *error names the bus.
    bool send(const CanFrame& frame, QString* error);

    // The dictionary a node matched (e.g. "delta-asda-a2"); loads its vendor abort table.
    void setNodeDictionary(uint8_t node, const QString& name);
    QString nodeDictionary(uint8_t node) const;
    // describeSdoAbort() with the node's vendor table.
    QString abortText(uint8_t node, uint32_t code) const;

private:
    CanBus* bus_;
    FrameDispatcher dispatcher_;
    mutable std::mutex mutex_;
    std::map<uint8_t, QString> dictionaries_;
    std::map<QString, std::shared_ptr<VendorAbortTable>> tables_;
};

}  // namespace coscope::canopen
