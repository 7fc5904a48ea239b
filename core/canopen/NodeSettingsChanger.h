// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/CommandScript.h"
#include "core/canopen/MasterContext.h"
#include "core/canopen/NodeSettingsObjects.h"
#include "core/canopen/ScriptRunner.h"
#include "core/canopen/SdoClient.h"

#include <QObject>
#include <QPointer>

#include <functional>
#include <memory>
#include <optional>

namespace coscope::canopen {

// What to change on one device: its node-ID or its CAN bit rate, through LSS (CiA 305) or the
// vendor's own parameter over SDO (NodeSettingsObjects.h).
struct NodeSettingsRequest {
    enum class Change : uint8_t { NodeId, BitRate };
    enum class Method : uint8_t { Lss, Vendor };
    Change change = Change::NodeId;
    Method method = Method::Lss;
    uint8_t node = 0;  // current node-ID; 0xFF = an LSS-unconfigured device left in LSS
                       // configuration state by Fastscan
    uint8_t newNodeId = 0;
    int bitRate = 500000;  // the bus's bit rate now
    int newBitRate = 0;
    QString dictionary;               // the device's bundled dictionary (vendor method)
    LssIdentity identity;             // LSS on a configured node: selects it (1018h:01..04)
    uint32_t vendorBitRateValue = 0;  // vendor bit rate: the parameter's value now (digits kept)
    uint32_t waitMs = 5000;           // how long to wait for the node afterwards
};

// The exact sequence. Changing the bit rate ends the first part with the device at the new
// rate: the master reconnects at `reconnectBitRate`, then runs the second part. whole() has a
// Reconnect step between the parts, so a saved script reopens the adapter when replayed.
struct NodeSettingsPlan {
    NodeSettingsRequest request;
    CommandScript beforeReconnect;
    CommandScript afterReconnect;
    bool reconnect = false;
    int reconnectBitRate = 0;
    uint8_t finalNodeId = 0;
    QString takesEffect;  // when the device uses the new value, in plain words
    QString recovery;     // what to do when the node does not come back
    // Everything as one script (the reconnect as a step) for saving / `script run`.
    CommandScript whole() const;
};

// Builds the plan; nullopt with *error (one line, plain words) when the request cannot work.
std::optional<NodeSettingsPlan> planNodeSettings(const NodeSettingsRequest& request, QString* error);

// What went wrong, for a technician: which step, what the device answered, what to check, and
// what was put back.
struct NodeSettingsOutcome {
    bool ok = false;
    int failedStep = -1;  // index in the part that ran
    QString step;         // the step's description
    QString answer;       // the device's answer (abort text, LSS error) or "no answer"
    QString advice;       // what to check / how to recover
    QString restored;     // what was undone, empty when nothing needed or could be undone
};

// Runs a plan's parts through a ScriptRunner (the one every wizard uses) on one bus. Never
// blocks: run() returns at once, progress and the result come as callbacks on this thread.
// Nothing is retried. On a failure it stops, undoes what it can (a pending node-ID or bit rate
// configured by LSS is configured back; a vendor parameter is written back) and says so.
class NodeSettingsChanger : public QObject {
    Q_OBJECT
public:
    using StepCallback = std::function<void(int step, bool ok, const QString& detail)>;
    using StartCallback = std::function<void(int step)>;
    using Done = std::function<void(const NodeSettingsOutcome&)>;

    NodeSettingsChanger(MasterContext& context, SdoClient& sdo, QObject* parent = nullptr);
    ~NodeSettingsChanger() override;

    // Reads what the plan needs from the device (LSS: identity 1018h:01..04; vendor bit rate:
    // the parameter's value), then plans. done(plan, error).
    void prepare(NodeSettingsRequest request, std::function<void(std::optional<NodeSettingsPlan>, QString)> done);

    // part 0 = beforeReconnect, 1 = afterReconnect.
    void run(const NodeSettingsPlan& plan, int part, StartCallback started, StepCallback stepDone, Done done);
    bool isRunning() const { return running_; }

    // Runs any script (no restore). Same callbacks.
    void runScript(const CommandScript& script, StartCallback started, StepCallback stepDone,
                   std::function<void(bool ok, int failedStep, const QString& answer)> done);

private:
    CommandScript restoreFor(const NodeSettingsPlan& plan, int part, int failedStep) const;

    MasterContext& context_;
    SdoClient& sdo_;
    ScriptRunner* runner_ = nullptr;
    bool running_ = false;
};

}  // namespace coscope::canopen
