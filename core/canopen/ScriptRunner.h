// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/CommandScript.h"
#include "core/canopen/MasterContext.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <functional>
#include <map>
#include <memory>
#include <vector>

class QTimer;

namespace coscope::canopen {

class SdoClient;
class NmtMaster;
class LssMaster;

// The outcome of one run. `error` is one line naming the step, e.g.
// "step 3 (sdo write 5 0x1600:00 0x00): node 5 aborted 1600:00: ... (0x06010002)".
struct ScriptRunResult {
    bool ok = false;
    bool cancelled = false;
    int failedStep = -1;           // index of the step that failed (or was running when cancelled)
    int stepsDone = 0;             // steps that finished ok
    std::vector<QString> details;  // per finished step: what the device answered / the value read
    QString error;
};
using ScriptRunCallback = std::function<void(const ScriptRunResult&)>;

// Runs a CommandScript through the master services, one step after the other, on the thread
// that created it (never blocking it). Stops at the first failure and says which step and what
// the device answered (the SDO abort text from SdoClient, the value read for a failed expect,
// the LSS error code). Writes are never retried.
//
// WaitForNode is satisfied by a boot-up (700h + node, data 00) or a heartbeat of the node that
// arrived after the previous step started; when the previous step was an NMT reset (node or
// communication) addressed to that node or to all, only a boot-up counts. The runner listens to
// 700h + node for every waited-for node from the start of the run, so a boot-up that comes
// before the wait step begins is not missed.
//
// Reconnect closes the adapter and opens it again at the step's bit rate through the owner's
// reconnector (the owner has the bus); the run goes on with the new bus's services. Without a
// reconnector the step fails.
//
// cancel() stops at once: no further step is sent; an SDO transfer already on the bus runs to
// its end in the SdoClient (which shares the node's queue with other users) and its result is
// ignored.
class ScriptRunner : public QObject {
    Q_OBJECT
public:
    // Creates its own NMT and LSS masters on `context`.
    ScriptRunner(MasterContext& context, SdoClient& sdo, QObject* parent = nullptr);
    // Uses the given masters (either may be null: then the runner creates its own).
    ScriptRunner(MasterContext& context, SdoClient& sdo, NmtMaster* nmt, LssMaster* lss, QObject* parent = nullptr);
    ~ScriptRunner() override;

    // Reopens the bus at `bitRate` bit/s; calls `opened` once, on this thread, with the new bus's
    // context and SDO client (both null and a one-line error when it could not). The old
    // context is no longer used once the reconnector is called.
    using Opened = std::function<void(MasterContext* context, SdoClient* sdo, const QString& error)>;
    using Reconnector = std::function<void(int bitRate, Opened opened)>;
    void setReconnector(Reconnector reconnector) { reconnector_ = std::move(reconnector); }

    // Starts the run; false (and `done` not called) when a run is in progress. `done` runs once,
    // later, on this thread (also for an empty script).
    bool run(const CommandScript& script, ScriptRunCallback done);
    void cancel();
    bool isRunning() const { return running_; }
    int currentStep() const { return running_ ? step_ : -1; }

signals:
    void stepStarted(int step);
    void stepFinished(int step, bool ok, const QString& detail);
    void finished(bool ok);

private:
    void startStep();
    void stepDone(bool ok, const QString& detail);
    void finish(bool ok, bool cancelled);
    void onHeartbeats(const std::vector<CanFrame>& frames);
    void checkWaitForNode();
    bool previousStepResets(uint8_t node) const;
    void listenForNodes();
    void reconnect(int bitRate);

    MasterContext* context_;
    SdoClient* sdo_;
    Reconnector reconnector_;
    NmtMaster* nmt_ = nullptr;
    LssMaster* lss_ = nullptr;
    std::unique_ptr<NmtMaster> ownNmt_;
    std::unique_ptr<LssMaster> ownLss_;

    CommandScript script_;
    ScriptRunCallback done_;
    ScriptRunResult result_;
    bool running_ = false;
    int step_ = 0;
    quint64 generation_ = 0;  // bumps on every step start / cancel: late callbacks are ignored
    QTimer* timer_;           // Wait and WaitForNode
    int subscription_ = 0;
    struct NodeSeen {
        int bootUpStep = -1;     // step running when the latest boot-up arrived
        int heartbeatStep = -1;  // ... the latest heartbeat (any state)
        uint8_t state = 0;
    };
    std::map<uint8_t, NodeSeen> seen_;
};

}  // namespace coscope::canopen
