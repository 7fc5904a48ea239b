// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/DeviceConfiguration.h"
#include "core/project/ProjectMatch.h"

#include <QObject>

#include <memory>

namespace coscope::project {

// What applying the project does to one node (the dry run).
struct NodeApplyPlan {
    uint8_t node = 0;
    QString name;
    NodeMatch match = NodeMatch::Missing;
    canopen::ApplyPlan plan;         // only the objects whose value differs from the node's
    od::ObjectDictionary current;    // the node's values before (ParameterValue), to put them back
    std::optional<uint32_t> serial;  // the serial number the node answered (1018h:04)
    QString error;                   // why the node is not written (missing, other device, ...)
    bool writable() const { return error.isEmpty(); }
};

enum class NodeApplyState : uint8_t {
    Written,
    NothingToWrite,
    RefusedRolledBack,
    RefusedRollbackFailed,
    NotReached,
    Skipped
};
QString nodeApplyStateName(NodeApplyState s);

struct NodeApplyResult {
    uint8_t node = 0;
    QString name;
    NodeApplyState state = NodeApplyState::NotReached;
    std::vector<canopen::ConfigEntryResult> writes;    // in order; a refusal ends them
    std::vector<canopen::ConfigEntryResult> rollback;  // the old values written back
    QString message;
    // A replaced drive (same type, another serial) that now holds the project's values: its
    // serial number, for the project to expect it from now on (acceptReplacedDrives).
    std::optional<uint32_t> newSerial;
};

struct ApplyReport {
    std::vector<NodeApplyResult> nodes;
    bool ok() const;  // every node written or nothing to write
};

// "Apply the project" (README "Projects"): a dry run first (prepare: scan, then each project
// node of the project's type has the objects read that the project configures, and the plan keeps
// those that differ: DeviceConfiguration::plan, PDOs framed by CiA 301 7.5.2.35-38), then run():
// the nodes one after the other; the first refused write stops it, that node's objects already
// written get their old values back and the nodes after it are not written. store() then asks
// each written node to save its parameters (1010h:01 = 65766173h "save", CiA 301 7.5.2.13).
class ProjectApply : public QObject {
    Q_OBJECT
public:
    using Progress = std::function<void(const QString& what, int done, int total)>;

    ProjectApply(canopen::SdoClient& sdo, DictionaryResolver resolver, QObject* parent = nullptr);
    void setScanTimeout(int ms) { scanTimeoutMs_ = ms; }
    // Names the dictionaries the scan writes into the node table (eds::scanMatcher()).
    void setMatcher(canopen::NetworkScan::Matcher m) { matcher_ = std::move(m); }
    // Only these nodes (empty: all of the project's).
    void setNodes(std::vector<uint8_t> nodes) { only_ = std::move(nodes); }

    void prepare(const Project& project, Progress progress, std::function<void(std::vector<NodeApplyPlan>)> done);
    void run(const std::vector<NodeApplyPlan>& plans, Progress progress, std::function<void(ApplyReport)> done);
    void store(const std::vector<uint8_t>& nodes, std::function<void(std::vector<canopen::ConfigEntryResult>)> done);

    // The writes that put back `current`'s values of the entries `written` changed.
    static canopen::ApplyPlan rollbackPlan(const NodeApplyPlan& plan,
                                           const std::vector<canopen::ConfigEntryResult>& written);
    // The dictionary with what the project expects of `node` as ParameterValue (expectedValues).
    static od::ObjectDictionary projectDcf(const od::ObjectDictionary& dictionary, const ProjectNode& node);

private:
    struct Prep;
    struct Exec;
    void prepareNext(std::shared_ptr<Prep> prep);
    void runNext(std::shared_ptr<Exec> exec);

    canopen::SdoClient& sdo_;
    DictionaryResolver resolver_;
    std::vector<uint8_t> only_;
    int scanTimeoutMs_ = 0;
    canopen::NetworkScan::Matcher matcher_;
};

// The project expects the drives that replaced its own and now hold its values (their serial
// numbers); true when one changed.
bool acceptReplacedDrives(Project& project, const ApplyReport& report);

// The report as plain text (for the CLI and the file the GUI saves).
QString applyPlanText(const std::vector<NodeApplyPlan>& plans);
QString applyReportText(const ApplyReport& report);

}  // namespace coscope::project
