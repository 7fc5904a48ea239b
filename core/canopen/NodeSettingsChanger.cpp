// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/NodeSettingsChanger.h"

#include "core/canopen/Lss.h"
#include "core/canopen/LssMaster.h"
#include "core/canopen/NmtMaster.h"

#include <QTimer>

#include <spdlog/spdlog.h>

namespace coscope::canopen {

namespace {
constexpr uint32_t kSaveSignature = 0x65766173;  // "save", CiA 301 §7.5.2.13
constexpr uint16_t kSwitchDelayMs = 100;         // LSS activate bit timing switch delay

QString nodeText(uint8_t node) {
    return node == 0xFF ? QStringLiteral("the unconfigured device") : QStringLiteral("node %1").arg(node);
}

uint32_t le(const QByteArray& b) {
    uint32_t v = 0;
    for (int i = 0; i < b.size() && i < 4; ++i) v |= uint32_t(uint8_t(b[i])) << (8 * i);
    return v;
}
}  // namespace

CommandScript NodeSettingsPlan::whole() const {
    CommandScript s = beforeReconnect;
    if (reconnect)
        s.steps.push_back(ScriptStep::reconnect(
            static_cast<uint32_t>(reconnectBitRate),
            QStringLiteral("Reopen the adapter at %1, the device's new bit rate").arg(bitRateText(reconnectBitRate))));
    s.steps.insert(s.steps.end(), afterReconnect.steps.begin(), afterReconnect.steps.end());
    return s;
}

std::optional<NodeSettingsPlan> planNodeSettings(const NodeSettingsRequest& r, QString* error) {
    auto fail = [error](const QString& why) -> std::optional<NodeSettingsPlan> {
        if (error) *error = why;
        return std::nullopt;
    };
    const bool unconfigured = r.node == 0xFF;
    if (!unconfigured && (r.node < 1 || r.node > 127))
        return fail(QStringLiteral("node-ID %1 is not 1-127").arg(r.node));
    const auto vendor = vendorNodeSettings(r.dictionary);
    NodeSettingsPlan p;
    p.request = r;
    p.finalNodeId = r.node;
    using K = NodeSettingsRequest;
    if (r.change == K::Change::NodeId) {
        if (r.newNodeId < 1 || r.newNodeId > 127) return fail(QStringLiteral("the new node-ID must be 1-127"));
        if (r.newNodeId == r.node) return fail(QStringLiteral("node %1 already has this node-ID").arg(r.node));
        if (vendor && r.newNodeId > vendor->maxNodeId)
            return fail(QStringLiteral("%1 allows node-IDs %2-%3 only")
                            .arg(r.dictionary)
                            .arg(vendor->minNodeId)
                            .arg(vendor->maxNodeId));
        p.finalNodeId = r.newNodeId;
        p.beforeReconnect.title = QStringLiteral("Change node-ID %1 → %2")
                                      .arg(unconfigured ? QStringLiteral("(unconfigured)") : QString::number(r.node))
                                      .arg(r.newNodeId);
        auto& s = p.beforeReconnect.steps;
        if (r.method == K::Method::Lss) {
            if (!unconfigured)
                s.push_back(ScriptStep::lssSwitchSelective(
                    r.identity, QStringLiteral("Pick this one device by its identity so only it listens to the next "
                                               "commands (LSS switch state selective)")));
            s.push_back(ScriptStep::lssConfigureNodeId(
                r.newNodeId,
                QStringLiteral("Give it node-ID %1; not used yet (LSS configure node-ID)").arg(r.newNodeId)));
            s.push_back(ScriptStep::lssStore(
                QStringLiteral("Make the device keep the new node-ID after power-off (LSS store configuration)")));
            s.push_back(ScriptStep::lssSwitchGlobal(
                false, QStringLiteral("End the setting mode (LSS switch state global: waiting)")));
            if (!unconfigured)
                s.push_back(ScriptStep::nmtCommand(
                    NmtCommand::ResetCommunication, r.node,
                    QStringLiteral("Restart its communication so it uses node-ID %1 (NMT reset communication)")
                        .arg(r.newNodeId)));
            s.push_back(ScriptStep::waitForNode(
                r.newNodeId, r.waitMs,
                QStringLiteral("Wait until it reports at node-ID %1 (boot-up / heartbeat)").arg(r.newNodeId)));
            p.takesEffect =
                unconfigured
                    ? QStringLiteral("at once when the setting mode ends (the device starts with its new node-ID)")
                    : QStringLiteral("after NMT reset communication (sent by this wizard) or a power cycle");
            p.recovery =
                QStringLiteral(
                    "Look for the device at node-ID %1 (scan). If it is not there: switch it off and on; "
                    "if it still does not answer, find it with LSS Fastscan / inquiry and set the node-ID again.")
                    .arg(r.node == 0xFF ? QStringLiteral("255") : QString::number(r.node));
        } else {
            if (!vendor || !vendor->nodeId)
                return fail(QStringLiteral("%1 has no documented node-ID parameter; use LSS")
                                .arg(r.dictionary.isEmpty() ? QStringLiteral("this device") : r.dictionary));
            if (unconfigured) return fail(QStringLiteral("an LSS-unconfigured device has no node-ID for SDO; use LSS"));
            const VendorSettingObject& o = *vendor->nodeId;
            s.push_back(ScriptStep::sdoWrite(
                r.node, o.index, o.sub, r.newNodeId, o.size,
                QStringLiteral("Write the new node-ID %1 into %2%3 (SDO download)")
                    .arg(r.newNodeId)
                    .arg(o.parameter, o.inferred ? QStringLiteral(" [object inferred]") : QString())));
            if (!o.storedOnWrite)
                s.push_back(ScriptStep::sdoWrite(
                    r.node, 0x1010, 0x01, kSaveSignature, 4,
                    QStringLiteral(
                        "Save the parameters so the node-ID survives power-off (store parameters, 1010h \"save\")")));
            s.push_back(ScriptStep::nmtCommand(
                NmtCommand::ResetNode, r.node,
                QStringLiteral("Restart the device so it takes node-ID %1 (NMT reset node)").arg(r.newNodeId)));
            s.push_back(ScriptStep::waitForNode(
                r.newNodeId, r.waitMs,
                QStringLiteral("Wait until it reports at node-ID %1 (boot-up / heartbeat)").arg(r.newNodeId)));
            p.takesEffect =
                o.takesEffect == TakesEffect::PowerCycle
                    ? QStringLiteral(
                          "after a power cycle (%1). The wizard also sends NMT reset node, which many drives accept; "
                          "if the drive does not come back, switch it off and on while the wizard waits.")
                          .arg(o.source)
                    : QStringLiteral("after NMT reset node (sent by this wizard) or a power cycle (%1)").arg(o.source);
            p.recovery = QStringLiteral(
                             "Switch the drive off and on and look for it at node-ID %1, then at %2. If it answers at "
                             "%2, the change is stored; "
                             "if it answers at %1, write %3 again or use LSS.")
                             .arg(r.newNodeId)
                             .arg(r.node)
                             .arg(o.parameter);
        }
        return p;
    }
    // Bit rate.
    if (r.newBitRate <= 0) return fail(QStringLiteral("choose the new bit rate"));
    if (r.newBitRate == r.bitRate)
        return fail(QStringLiteral("the bus already runs at %1").arg(bitRateText(r.bitRate)));
    if (unconfigured) return fail(QStringLiteral("give the device a node-ID first; then change its bit rate"));
    p.reconnect = true;
    p.reconnectBitRate = r.newBitRate;
    p.beforeReconnect.title = QStringLiteral("Change bit rate of node %1: %2 → %3")
                                  .arg(r.node)
                                  .arg(bitRateText(r.bitRate), bitRateText(r.newBitRate));
    p.afterReconnect.title = QStringLiteral("Find node %1 at %2").arg(r.node).arg(bitRateText(r.newBitRate));
    auto& s = p.beforeReconnect.steps;
    auto& a = p.afterReconnect.steps;
    if (r.method == K::Method::Lss) {
        if (lssTableIndexForBitRate(r.newBitRate) < 0)
            return fail(
                QStringLiteral("%1 is not in the LSS bit-rate table (CiA 305 Table 1)").arg(bitRateText(r.newBitRate)));
        s.push_back(ScriptStep::lssSwitchSelective(
            r.identity,
            QStringLiteral("Pick this one device by its identity so only it listens (LSS switch state selective)")));
        s.push_back(ScriptStep::lssConfigureBitRate(
            static_cast<uint32_t>(r.newBitRate),
            QStringLiteral("Give it the new bit rate %1; not used yet (LSS configure bit timing)")
                .arg(bitRateText(r.newBitRate))));
        s.push_back(ScriptStep::lssStore(
            QStringLiteral("Make it keep the new bit rate after power-off (LSS store configuration)")));
        s.push_back(ScriptStep::lssActivateBitTiming(
            kSwitchDelayMs,
            QStringLiteral("Switch to the new bit rate now; it goes silent on this bus (LSS activate bit timing)")));
        a.push_back(ScriptStep::lssSwitchGlobal(
            false, QStringLiteral("End the setting mode (LSS switch state global: waiting)")));
        p.takesEffect = QStringLiteral("at once with LSS activate bit timing (and at every power-on after the store)");
    } else {
        if (!vendor || !vendor->bitRate)
            return fail(QStringLiteral("%1 has no documented bit-rate parameter; use LSS")
                            .arg(r.dictionary.isEmpty() ? QStringLiteral("this device") : r.dictionary));
        const VendorSettingObject& o = *vendor->bitRate;
        const auto value = encodeVendorBitRate(o, r.newBitRate, r.vendorBitRateValue);
        if (!value) return fail(QStringLiteral("%1 cannot be set to %2").arg(o.parameter, bitRateText(r.newBitRate)));
        s.push_back(ScriptStep::sdoWrite(r.node, o.index, o.sub, *value, o.size,
                                         QStringLiteral("Write %1 = %2h: bit rate %3 (SDO download)")
                                             .arg(o.parameter)
                                             .arg(*value, 4, 16, QChar(u'0'))
                                             .arg(bitRateText(r.newBitRate))));
        if (!o.storedOnWrite)
            s.push_back(ScriptStep::sdoWrite(r.node, 0x1010, 0x01, kSaveSignature, 4,
                                             QStringLiteral("Save the parameters (store parameters, 1010h \"save\")")));
        s.push_back(ScriptStep::nmtCommand(
            NmtCommand::ResetNode, r.node,
            QStringLiteral("Restart the device so it runs at %1; it goes silent on this bus (NMT reset node)")
                .arg(bitRateText(r.newBitRate))));
        s.push_back(ScriptStep::wait(
            300, QStringLiteral("Let the reset leave the adapter and the device restart before reconnecting")));
        p.takesEffect =
            o.takesEffect == TakesEffect::PowerCycle
                ? QStringLiteral("after a power cycle (%1); the wizard also sends NMT reset node").arg(o.source)
                : QStringLiteral("after NMT reset node (%1)").arg(o.source);
    }
    a.push_back(ScriptStep::nmtCommand(
        NmtCommand::ResetCommunication, r.node,
        QStringLiteral("Ask it to announce itself at the new bit rate (NMT reset communication)")));
    a.push_back(ScriptStep::waitForNode(r.node, r.waitMs,
                                        QStringLiteral("Wait until node %1 reports at %2 (boot-up / heartbeat)")
                                            .arg(r.node)
                                            .arg(bitRateText(r.newBitRate))));
    p.recovery = QStringLiteral(
                     "Reconnect at %1 (the old rate) and scan: if node %2 is there, the change did not take effect — "
                     "switch it off and on and "
                     "try again at %3. If it answers at neither rate, try the other standard rates, or use LSS with "
                     "this device alone on the bus.")
                     .arg(bitRateText(r.bitRate))
                     .arg(r.node)
                     .arg(bitRateText(r.newBitRate));
    return p;
}

NodeSettingsChanger::NodeSettingsChanger(MasterContext& context, SdoClient& sdo, QObject* parent)
    : QObject(parent), context_(context), sdo_(sdo) {}

NodeSettingsChanger::~NodeSettingsChanger() = default;

void NodeSettingsChanger::prepare(NodeSettingsRequest request,
                                  std::function<void(std::optional<NodeSettingsPlan>, QString)> done) {
    auto plan = [done](const NodeSettingsRequest& r) {
        QString error;
        auto p = planNodeSettings(r, &error);
        done(p, error);
    };
    const bool needIdentity = request.method == NodeSettingsRequest::Method::Lss && request.node != 0xFF;
    const bool needVendorValue =
        request.method == NodeSettingsRequest::Method::Vendor && request.change == NodeSettingsRequest::Change::BitRate;
    if (!needIdentity && !needVendorValue) return plan(request);
    if (needVendorValue) {
        const auto vendor = vendorNodeSettings(request.dictionary);
        if (!vendor || !vendor->bitRate) return plan(request);  // planner says why
        QPointer<NodeSettingsChanger> self(this);
        sdo_.upload(request.node, vendor->bitRate->index, vendor->bitRate->sub,
                    [self, request, plan, done](const SdoResult& res) mutable {
                        if (!self) return;
                        if (!res.ok)
                            return done(std::nullopt,
                                        QStringLiteral("cannot read the bit-rate parameter: %1").arg(res.error));
                        request.vendorBitRateValue = le(res.data);
                        plan(request);
                    });
        return;
    }
    // LSS selects a configured node by its identity: read 1018h:01..04 (CiA 301 §7.5.2.23).
    auto req = std::make_shared<NodeSettingsRequest>(request);
    auto readSub = std::make_shared<std::function<void(uint8_t)>>();
    QPointer<NodeSettingsChanger> self(this);
    *readSub = [self, req, readSub, plan, done](uint8_t sub) {
        if (!self) return;
        if (sub > 4) {
            plan(*req);
            *readSub = nullptr;  // break the cycle
            return;
        }
        self->sdo_.upload(req->node, 0x1018, sub, [self, req, readSub, done, sub](const SdoResult& res) {
            if (!self || !*readSub) return;
            // Revision and serial may be missing (not LSS-capable then, strictly): take 0.
            if (!res.ok && !(sub >= 3 && res.serverAborted)) {
                done(std::nullopt,
                     QStringLiteral("cannot read the identity (1018h) that LSS needs to pick this device: %1")
                         .arg(res.error));
                *readSub = nullptr;
                return;
            }
            const uint32_t v = res.ok ? le(res.data) : 0;
            if (sub == 1) req->identity.vendorId = v;
            else if (sub == 2) req->identity.productCode = v;
            else if (sub == 3) req->identity.revision = v;
            else req->identity.serial = v;
            (*readSub)(static_cast<uint8_t>(sub + 1));
        });
    };
    (*readSub)(1);
}

void NodeSettingsChanger::runScript(const CommandScript& script, StartCallback started, StepCallback stepDone,
                                    std::function<void(bool, int, const QString&)> done) {
    // A new runner per script: this may be called from the previous one's callback.
    if (runner_) runner_->deleteLater();
    runner_ = new ScriptRunner(context_, sdo_, this);
    if (started) connect(runner_, &ScriptRunner::stepStarted, this, [started](int step) { started(step); });
    auto answer = std::make_shared<QString>();
    connect(runner_, &ScriptRunner::stepFinished, this, [stepDone, answer](int step, bool ok, const QString& detail) {
        if (!ok) *answer = detail;
        if (stepDone) stepDone(step, ok, detail);
    });
    running_ = true;
    QPointer<NodeSettingsChanger> self(this);
    runner_->run(script, [self, done, answer](const ScriptRunResult& r) {
        if (!self) return;
        self->running_ = false;
        if (done) done(r.ok, r.failedStep, *answer);
    });
}

CommandScript NodeSettingsChanger::restoreFor(const NodeSettingsPlan& plan, int part, int failedStep) const {
    CommandScript undo;
    undo.title = QStringLiteral("Put back what was changed");
    if (part != 0) return undo;
    const NodeSettingsRequest& r = plan.request;
    bool selected = false, stored = false, configured = false, saved = false;
    std::optional<ScriptStep> vendorWrite;
    for (int i = 0; i < failedStep && i < static_cast<int>(plan.beforeReconnect.steps.size()); ++i) {
        const ScriptStep& s = plan.beforeReconnect.steps[static_cast<size_t>(i)];
        switch (s.kind) {
        case ScriptStep::Kind::LssSwitchSelective: selected = true; break;
        case ScriptStep::Kind::LssSwitchGlobal: selected = s.number != 0; break;
        case ScriptStep::Kind::LssConfigureNodeId:
        case ScriptStep::Kind::LssConfigureBitRate: configured = true; break;
        case ScriptStep::Kind::LssStore: stored = true; break;
        case ScriptStep::Kind::SdoWrite:
            if (s.index == 0x1010) saved = true;
            else vendorWrite = s;
            break;
        case ScriptStep::Kind::Nmt:
        case ScriptStep::Kind::LssActivateBitTiming: return undo;  // in effect: nothing to put back here
        default: break;
        }
    }
    if (configured) {
        if (r.change == NodeSettingsRequest::Change::NodeId)
            undo.steps.push_back(ScriptStep::lssConfigureNodeId(
                r.node, QStringLiteral("Put the old node-ID %1 back (LSS configure node-ID)").arg(r.node)));
        else if (lssTableIndexForBitRate(r.bitRate) >= 0)
            undo.steps.push_back(ScriptStep::lssConfigureBitRate(
                static_cast<uint32_t>(r.bitRate),
                QStringLiteral("Put the old bit rate %1 back (LSS configure bit timing)").arg(bitRateText(r.bitRate))));
        if (stored)
            undo.steps.push_back(
                ScriptStep::lssStore(QStringLiteral("Store the old setting again (LSS store configuration)")));
    }
    if (selected)
        undo.steps.push_back(ScriptStep::lssSwitchGlobal(
            false, QStringLiteral("End the setting mode (LSS switch state global: waiting)")));
    if (vendorWrite) {
        const auto vendor = vendorNodeSettings(r.dictionary);
        uint32_t old = 0;
        if (r.change == NodeSettingsRequest::Change::NodeId) old = r.node;
        else old = r.vendorBitRateValue;
        ScriptStep w = *vendorWrite;
        w.data = QByteArray();
        for (int b = 0; b < vendorWrite->data.size(); ++b) w.data.append(char((old >> (8 * b)) & 0xFF));
        w.why = QStringLiteral("Write the old value back");
        undo.steps.push_back(w);
        if (saved)
            undo.steps.push_back(ScriptStep::sdoWrite(r.node, 0x1010, 0x01, kSaveSignature, 4,
                                                      QStringLiteral("Save the old value again")));
    }
    return undo;
}

void NodeSettingsChanger::run(const NodeSettingsPlan& plan, int part, StartCallback started, StepCallback stepDone,
                              Done done) {
    const CommandScript& script = part == 0 ? plan.beforeReconnect : plan.afterReconnect;
    QPointer<NodeSettingsChanger> self(this);
    runScript(
        script, std::move(started), std::move(stepDone),
        [self, plan, part, script, done](bool ok, int failed, const QString& answer) {
            if (!self) return;
            NodeSettingsOutcome out;
            out.ok = ok;
            if (ok) return done(out);
            out.failedStep = failed;
            const ScriptStep& s = script.steps[static_cast<size_t>(failed)];
            out.step = QStringLiteral("step %1: %2").arg(failed + 1).arg(s.describe());
            out.answer = answer;
            switch (s.kind) {
            case ScriptStep::Kind::WaitForNode: out.advice = plan.recovery; break;
            case ScriptStep::Kind::LssSwitchSelective:
                out.advice = QStringLiteral(
                    "No device answered LSS with this identity. Check that the drive supports LSS (CiA 305); if not, "
                    "use its own parameter "
                    "(vendor method) or the vendor's tool.");
                break;
            case ScriptStep::Kind::LssConfigureNodeId:
            case ScriptStep::Kind::LssConfigureBitRate:
                out.advice = QStringLiteral(
                    "The device refused the value. Check that it supports it (its manual's node-ID range / bit "
                    "rates).");
                break;
            case ScriptStep::Kind::LssStore:
                out.advice = QStringLiteral(
                    "The device could not save the setting, so it would be lost at power-off. Check that it supports "
                    "LSS store (some keep the setting only until power-off); try its own parameter instead.");
                break;
            case ScriptStep::Kind::SdoWrite:
                out.advice = QStringLiteral(
                                 "Check that %1 is powered and answers at this node-ID, that the parameter can be "
                                 "written now (some drives refuse "
                                 "parameter writes while the servo is on or in another control mode) and that the "
                                 "value is in range.")
                                 .arg(nodeText(s.node));
                break;
            default:
                out.advice =
                    QStringLiteral("Check the connection to %1 and try again.").arg(nodeText(plan.request.node));
                break;
            }
            const CommandScript undo = self->restoreFor(plan, part, failed);
            if (undo.steps.empty()) return done(out);
            self->runScript(
                undo, {}, {}, [self, out, undo, done](bool undoOk, int undoFailed, const QString& undoAnswer) mutable {
                    if (!self) return;
                    QStringList what;
                    for (const auto& st : undo.steps) what << st.describe();
                    out.restored = undoOk ? QStringLiteral("Put back: %1.").arg(what.join(QStringLiteral("; ")))
                                          : QStringLiteral("Could not put everything back (%1: %2).")
                                                .arg(undo.steps[size_t(undoFailed)].describe(), undoAnswer);
                    done(out);
                });
        });
}

}  // namespace coscope::canopen
