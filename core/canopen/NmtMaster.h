// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/MasterContext.h"
#include "core/canopen/Nmt.h"

namespace coscope::canopen {

// NMT master (CiA 301 §7.2.8.3.1): node control commands to one node or to all (node 0).
// NMT is unconfirmed: the command is on its way when send() returns; the heartbeat monitor
// shows the state the nodes report.
class NmtMaster {
public:
    explicit NmtMaster(MasterContext& context) : context_(context) {}

    // node 0 = all nodes. False with *error when the bus refused (listen-only, closed) or the
    // node-ID is out of range.
    bool send(NmtCommand command, uint8_t node, QString* error = nullptr);

    bool start(uint8_t node, QString* error = nullptr) { return send(NmtCommand::Start, node, error); }
    bool stop(uint8_t node, QString* error = nullptr) { return send(NmtCommand::Stop, node, error); }
    bool enterPreOperational(uint8_t node, QString* error = nullptr) {
        return send(NmtCommand::EnterPreOperational, node, error);
    }
    bool resetNode(uint8_t node, QString* error = nullptr) { return send(NmtCommand::ResetNode, node, error); }
    bool resetCommunication(uint8_t node, QString* error = nullptr) {
        return send(NmtCommand::ResetCommunication, node, error);
    }

private:
    MasterContext& context_;
};

}  // namespace coscope::canopen
