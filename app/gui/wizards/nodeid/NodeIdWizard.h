// SPDX-License-Identifier: GPL-3.0-or-later
// Folder app/gui/wizards/nodeid/ owns the node-ID / bit rate wizard and its pages.
#pragma once

#include "core/canopen/NodeSettingsChanger.h"

#include <QPointer>
#include <QWizard>

#include <memory>
#include <optional>

namespace coscope::sim {
class SimNetwork;
}

namespace coscope::gui {

class Workspace;
class WizardFramesPane;
class ScriptPreview;
class NodeScanner;
class NodeIdFindPage;
class NodeIdChangePage;
class NodeIdRunPage;

// Commission ▸ Baud rate and node-ID…: find the device (the node list, a scan, or LSS Fastscan
// for a device without node-ID), choose the new node-ID or bit rate and the way (LSS, CiA 305,
// or the drive's own parameter over SDO), see the exact sequence (dry run, savable as a script),
// run it through canopen::NodeSettingsChanger, reconnect at the new bit rate when needed and
// wait for the node at its new ID. Failures stop, say which step, what the device answered and
// what to check, and put back what can be put back. Nothing is sent in listen-only mode.
class NodeIdWizard : public QWizard {
    Q_OBJECT
public:
    enum PageId { FindPageId, ChangePageId, RunPageId };
    enum class Outcome { None, Succeeded, Failed };
    using Change = canopen::NodeSettingsRequest::Change;
    using Method = canopen::NodeSettingsRequest::Method;

    // `node` -1: the first node found.
    NodeIdWizard(Workspace* workspace, int node, QWidget* parent = nullptr);
    ~NodeIdWizard() override;

    Workspace* workspace() const { return workspace_; }
    // Why the wizard may not send now ("" = it may): no bus, listen-only, not open.
    QString sendRefusal() const;

    // --- the device
    void selectNode(int node);                  // a configured node (identity and dictionary from the node table)
    int node() const { return request_.node; }  // 0 none, 255 = the unconfigured device from Fastscan
    void scan();                                // SDO scan of nodes 1..127 (identifies them)
    bool isScanning() const;
    void findUnconfigured();  // LSS Fastscan: the device stays in LSS configuration state
    QString dictionary() const { return request_.dictionary; }
    void setDictionary(const QString& name);
    std::vector<int> knownNodes() const;  // nodes in the node table, ascending

    // --- the change
    void setChange(Change c);
    void setMethod(Method m);
    void setNewNodeId(int id);
    // A node-ID the node table still lists but no device answers on any more (a project
    // comparison found it missing: the drive was taken off the bus): free to give to another.
    void setVacated(int id) { vacated_ = id; }
    void setNewBitRate(int bitRate);
    int busBitRate() const;  // the rate the bus is open at now
    const canopen::NodeSettingsRequest& request() const { return request_; }
    bool vendorMethodAvailable() const;
    QString vendorParameterName() const;
    // Plain words: what will be sent, when it takes effect, warnings (other nodes, ID in use).
    QString explanation() const;
    QString blockingProblem() const;  // "" when the change may go ahead

    // --- dry run and run
    void prepareDryRun();  // reads what the plan needs (identity) if not known; then dryRunReady
    const std::optional<canopen::NodeSettingsPlan>& plan() const { return plan_; }
    QString planError() const { return planError_; }
    bool start(QString* why = nullptr);
    bool isRunning() const { return running_; }
    Outcome outcome() const { return outcome_; }
    QString outcomeText() const { return outcomeText_; }

    WizardFramesPane* framesPane() const { return frames_; }
    ScriptPreview* preview() const;
    NodeIdFindPage* findPage() const { return find_; }
    NodeIdChangePage* changePage() const { return change_; }
    NodeIdRunPage* runPage() const { return run_; }

signals:
    void targetChanged();
    void scanFinished();
    void fastscanFinished(bool found, const QString& message);
    void dryRunReady(bool ok);
    void progress(const QString& text);
    void finished(bool ok);

private:
    canopen::NodeSettingsChanger* changer();
    void dropServices();
    void runPart(int part);
    void reconnect();
    void finish(bool ok, const QString& text);
    // After a successful change: the node table (Nodes dock, decoder, events) follows the
    // device from node-ID `from` to `to`, and its identity is read at `to`.
    void followChange(int from, int to);
    void movePaneTo(int pageId);

    Workspace* workspace_;
    canopen::NodeSettingsRequest request_;
    bool identityKnown_ = false;
    std::unique_ptr<canopen::NodeSettingsChanger> changer_;
    const void* changerFor_ = nullptr;
    std::unique_ptr<canopen::LssMaster> fastscanLss_;
    NodeScanner* scanner_ = nullptr;
    std::optional<canopen::NodeSettingsPlan> plan_;
    QString planError_;
    uint64_t dryRunGeneration_ = 0;
    bool running_ = false;
    bool reconnecting_ = false;
    Outcome outcome_ = Outcome::None;
    QString outcomeText_;
    std::shared_ptr<sim::SimNetwork> keepNetwork_;
    WizardFramesPane* frames_ = nullptr;
    NodeIdFindPage* find_ = nullptr;
    NodeIdChangePage* change_ = nullptr;
    NodeIdRunPage* run_ = nullptr;
    int vacated_ = 0;
};

}  // namespace coscope::gui
