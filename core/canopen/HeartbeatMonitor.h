// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/MasterContext.h"
#include "core/canopen/NodeTable.h"
#include "core/canopen/PeriodicSender.h"

#include <QObject>
#include <QString>

#include <atomic>
#include <map>
#include <memory>

class QTimer;

namespace coscope::canopen {

// Heartbeat consumer and node-guarding master (CiA 301 §7.2.8.3.2) over one bus, writing what
// it finds into the context's NodeTable (NodeInfo::watch, heartbeatLost, guardingErrors).
//  - Heartbeat consumer: a node is lost when no heartbeat came within its consumer time (as
//    1016h would hold it). The time runs from when it was set, so a node that never sends is
//    lost too (CiA 301 starts at the first heartbeat; a tool wants to see a silent node). It is
//    late when a heartbeat is overdue by half its measured period.
//  - Node guarding: an RTR on 700h + node every guard time (100Ch), sent by the bus's
//    PeriodicSender (off the owner's thread); the node answers with its state and a toggle bit
//    7 that alternates, starting with 0 after boot-up (CiA 301 §7.2.8.3.2.1). A request not
//    answered before the next, or an answer with the wrong toggle, makes the node late and
//    counts as a guarding error; no right answer within the node life time (guard time x life
//    time factor, 100Dh) makes it lost. Guarding transmits: refused on a listen-only bus.
// Receives 701h..77Fh and 81h..FFh through the dispatcher. Unless the node table is fed by the
// trace (setTableFedByTrace: the app's NodeConsumer does state, boot-ups and EMCY), it also
// writes the node's NMT state, boot-ups and EMCY there. Signals fire on changes only, never
// per frame. Lives on the owner's thread (a 20 ms check timer).
class HeartbeatMonitor : public QObject {
    Q_OBJECT
public:
    explicit HeartbeatMonitor(MasterContext& context, QObject* parent = nullptr);
    ~HeartbeatMonitor() override;  // removes its guarding requests from the PeriodicSender

    const NodeTable& table() const { return context_.nodes(); }
    NodeTable& table() { return context_.nodes(); }

    // The app feeds the node table from the trace (NodeTable::consume): then only the watch's
    // findings are written, nothing the trace already gives (state, boot-ups, EMCY).
    void setTableFedByTrace(bool fed) { fedByTrace_ = fed; }

    // Heartbeat consumer: the node is lost when no heartbeat came within `timeMs`. 0 = off.
    // Replaces node guarding of the node.
    void setConsumerTime(uint8_t node, int timeMs);
    // Node guarding: RTR on 700h + node every guardTimeMs; lost after lifeTimeFactor periods
    // without a right answer. guardTimeMs 0 = off. Replaces the heartbeat consumer of the node.
    // False with *error when the request cannot be sent (listen-only, no bus).
    bool setGuarding(uint8_t node, int guardTimeMs, int lifeTimeFactor, QString* error = nullptr);
    // Ends the watch of `node`.
    void unwatch(uint8_t node);
    // The watch of a node as last written to the table (status Off when not watched).
    ErrorControlWatch watch(uint8_t node) const;
    // Guarding requests sent to `node` so far.
    uint64_t guardRequests(uint8_t node) const;

signals:
    void nodeChanged(int node);
    // The watch found the node lost / back (a heartbeat or a right guarding answer again).
    void nodeLost(int node);
    void nodeBack(int node);
    // A guarding answer with the wrong toggle bit, or none before the next request (once until
    // the next right answer).
    void guardingError(int node, const QString& what);
    void bootUp(int node);
    void emergency(int node, quint16 code);

private:
    struct Watch {
        ErrorControlWatch shown;  // as in the table
        int64_t startNs = 0;
        int64_t periodNs = 0;  // measured between heartbeats
        PeriodicSender::JobId job = 0;
        std::shared_ptr<std::atomic<uint64_t>> requests;  // RTRs sent (sender thread)
        uint64_t answeredUpTo = 0;                        // requests answered or given up
        // Requests left unanswered until the next one, counted on the ingest thread in the
        // bus's own order (our RTR's Tx copy, then the answer or the next RTR): how late this
        // thread reads the answers does not matter.
        std::shared_ptr<std::atomic<uint64_t>> missed;
        uint64_t missedCounted = 0;
        int orderWatch = 0;  // FrameDispatcher::addWatch id
        bool expectToggle = false;
        bool firstAnswer = true;
        bool errorReported = false;
    };
    void onFrames(const std::vector<CanFrame>& frames);
    void onCheck();
    void feedTable(const CanFrame& f, uint8_t node, bool errorControl, bool guardAnswer);
    void onErrorControl(Watch& w, uint8_t node, uint8_t byte, int64_t now);
    void setStatus(uint8_t node, Watch& w, ErrorControlWatch::Status status, int addErrors = 0);
    void stopGuarding(Watch& w);

    MasterContext& context_;
    int subscription_ = 0;
    QTimer* timer_;
    bool fedByTrace_ = false;
    std::map<uint8_t, Watch> watches_;
};

}  // namespace coscope::canopen
