// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/project/ProjectApply.h"

#include "core/canopen/SdoClient.h"

#include <QPointer>
#include <QTextStream>

#include <algorithm>
#include <set>

namespace coscope::project {

using canopen::ConfigEntryResult;
using canopen::DeviceConfiguration;

QString nodeApplyStateName(NodeApplyState s) {
    switch (s) {
    case NodeApplyState::Written: return QStringLiteral("written");
    case NodeApplyState::NothingToWrite: return QStringLiteral("nothing to write");
    case NodeApplyState::RefusedRolledBack: return QStringLiteral("refused, old values put back");
    case NodeApplyState::RefusedRollbackFailed: return QStringLiteral("refused, old values NOT all put back");
    case NodeApplyState::NotReached: return QStringLiteral("not written (stopped before)");
    case NodeApplyState::Skipped: return QStringLiteral("skipped");
    }
    return {};
}

bool ApplyReport::ok() const {
    return std::all_of(nodes.begin(), nodes.end(), [](const NodeApplyResult& n) {
        return n.state == NodeApplyState::Written || n.state == NodeApplyState::NothingToWrite ||
               n.state == NodeApplyState::Skipped;
    });
}

struct ProjectApply::Prep {
    Project project;
    std::vector<MatchedNode> matches;
    size_t next = 0;
    std::vector<NodeApplyPlan> plans;
    Progress progress;
    std::function<void(std::vector<NodeApplyPlan>)> done;
    std::unique_ptr<DeviceConfiguration> config;
};

struct ProjectApply::Exec {
    std::vector<NodeApplyPlan> plans;
    size_t next = 0;
    bool stopped = false;
    ApplyReport report;
    Progress progress;
    std::function<void(ApplyReport)> done;
    std::unique_ptr<DeviceConfiguration> config;
};

ProjectApply::ProjectApply(canopen::SdoClient& sdo, DictionaryResolver resolver, QObject* parent)
    : QObject(parent), sdo_(sdo), resolver_(std::move(resolver)) {}

od::ObjectDictionary ProjectApply::projectDcf(const od::ObjectDictionary& dictionary, const ProjectNode& node) {
    od::ObjectDictionary dcf = dictionary;
    for (const auto& [index, obj] : dictionary.objects())
        for (const od::SubObject& s : obj.subs)
            if (!s.parameterValue.isEmpty()) dcf.setParameterValue(index, s.sub, {});
    for (const ExpectedValue& e : expectedValues(dictionary, node)) dcf.setParameterValue(e.index, e.sub, e.value);
    dcf.setNodeId(node.id);
    return dcf;
}

void ProjectApply::prepare(const Project& project, Progress progress,
                           std::function<void(std::vector<NodeApplyPlan>)> done) {
    auto prep = std::make_shared<Prep>();
    prep->project = project;
    prep->progress = std::move(progress);
    prep->done = std::move(done);
    prep->config = std::make_unique<DeviceConfiguration>(sdo_);
    uint8_t first = 127, last = 1;
    for (const ProjectNode& n : project.nodes) {
        first = std::min(first, n.id);
        last = std::max(last, n.id);
    }
    if (project.nodes.empty()) first = last = 1;
    if (prep->progress) prep->progress(QStringLiteral("scanning nodes %1-%2").arg(first).arg(last), 0, 0);
    QPointer<ProjectApply> self(this);
    scanMachine(
        sdo_, prep->project, first, last, scanTimeoutMs_, matcher_,
        [self, prep](std::vector<MatchedNode> matches) {
            if (!self) return;
            for (MatchedNode& m : matches)
                if (m.project && (self->only_.empty() ||
                                  std::find(self->only_.begin(), self->only_.end(), m.node) != self->only_.end()))
                    prep->matches.push_back(std::move(m));
            self->prepareNext(prep);
        },
        this);
}

void ProjectApply::prepareNext(std::shared_ptr<Prep> prep) {
    if (prep->next >= prep->matches.size()) {
        if (prep->progress) prep->progress(QStringLiteral("done"), 1, 1);
        prep->done(prep->plans);
        return;
    }
    const size_t at = prep->next++;
    const MatchedNode& m = prep->matches[at];
    NodeApplyPlan plan;
    plan.node = m.node;
    plan.name = m.project->name;
    plan.match = m.match;
    plan.plan.node = m.node;
    if (m.found) plan.serial = m.found->serial;
    if (m.match != NodeMatch::Same && m.match != NodeMatch::Replaced) {
        plan.error = QStringLiteral("%1%2").arg(nodeMatchName(m.match),
                                                m.detail.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(m.detail));
        prep->plans.push_back(std::move(plan));
        return prepareNext(prep);
    }
    QString error;
    const auto dict = resolver_(*m.project, &error);
    if (!dict) {
        plan.error = QStringLiteral("no dictionary: %1").arg(error);
        prep->plans.push_back(std::move(plan));
        return prepareNext(prep);
    }
    const od::ObjectDictionary dcf = projectDcf(*dict, *m.project);
    const canopen::ApplyPlan all = DeviceConfiguration::plan(m.node, dcf, nullptr, canopen::ApplyScope::AllValues);
    if (prep->progress)
        prep->progress(QStringLiteral("reading node %1").arg(m.node), static_cast<int>(at),
                       static_cast<int>(prep->matches.size()));
    QPointer<ProjectApply> self(this);
    prep->config->read(m.node, dcf, DeviceConfiguration::planEntries(all), {},
                       [self, prep, plan = std::move(plan), dcf](const canopen::ConfigReadResult& read) mutable {
                           if (!self) return;
                           plan.current = read.values;
                           plan.plan = DeviceConfiguration::plan(plan.node, dcf, &read.values,
                                                                 canopen::ApplyScope::OnlyDifferent);
                           prep->plans.push_back(std::move(plan));
                           self->prepareNext(prep);
                       });
}

canopen::ApplyPlan ProjectApply::rollbackPlan(const NodeApplyPlan& plan,
                                              const std::vector<ConfigEntryResult>& written) {
    od::ObjectDictionary old = plan.current;
    std::set<std::pair<uint16_t, uint8_t>> changed;
    for (const ConfigEntryResult& e : written)
        if (e.ok) changed.emplace(e.index, e.sub);
    for (const auto& [index, obj] : plan.current.objects())
        for (const od::SubObject& s : obj.subs)
            if (!changed.count({index, s.sub})) old.setParameterValue(index, s.sub, {});
    return DeviceConfiguration::plan(plan.node, old, nullptr, canopen::ApplyScope::AllValues);
}

void ProjectApply::run(const std::vector<NodeApplyPlan>& plans, Progress progress,
                       std::function<void(ApplyReport)> done) {
    auto exec = std::make_shared<Exec>();
    exec->plans = plans;
    exec->progress = std::move(progress);
    exec->done = std::move(done);
    exec->config = std::make_unique<DeviceConfiguration>(sdo_);
    runNext(exec);
}

void ProjectApply::runNext(std::shared_ptr<Exec> exec) {
    if (exec->next >= exec->plans.size()) {
        if (exec->progress) exec->progress(QStringLiteral("done"), 1, 1);
        exec->done(exec->report);
        return;
    }
    const size_t at = exec->next++;
    const NodeApplyPlan& plan = exec->plans[at];
    NodeApplyResult result;
    result.node = plan.node;
    result.name = plan.name;
    if (plan.match == NodeMatch::Replaced) result.newSerial = plan.serial;
    if (!plan.writable()) {
        result.state = NodeApplyState::Skipped;
        result.message = plan.error;
    } else if (exec->stopped) {
        result.newSerial.reset();
        result.state = NodeApplyState::NotReached;
        result.message = QStringLiteral("not written: a node before refused");
    } else if (plan.plan.writes.empty()) {
        result.state = NodeApplyState::NothingToWrite;
        result.message = QStringLiteral("already as in the project");
    } else {
        if (exec->progress)
            exec->progress(QStringLiteral("writing node %1").arg(plan.node), static_cast<int>(at),
                           static_cast<int>(exec->plans.size()));
        QPointer<ProjectApply> self(this);
        exec->config->setStopOnRefusal(true);
        exec->config->apply(
            plan.plan, {}, [self, exec, at, result](const std::vector<ConfigEntryResult>& writes, bool) mutable {
                if (!self) return;
                result.writes = writes;
                const bool refused = !writes.empty() && !writes.back().ok;
                if (!refused) {
                    result.state = NodeApplyState::Written;
                    result.message = QStringLiteral("%1 object(s) written").arg(writes.size());
                    exec->report.nodes.push_back(result);
                    return self->runNext(exec);
                }
                exec->stopped = true;
                result.newSerial.reset();
                const canopen::ApplyPlan back = rollbackPlan(exec->plans[at], writes);
                exec->config->setStopOnRefusal(false);
                exec->config->apply(
                    back, {}, [self, exec, result](const std::vector<ConfigEntryResult>& rollback, bool) mutable {
                        if (!self) return;
                        result.rollback = rollback;
                        const bool allBack = std::all_of(rollback.begin(), rollback.end(),
                                                         [](const ConfigEntryResult& e) { return e.ok; });
                        result.state =
                            allBack ? NodeApplyState::RefusedRolledBack : NodeApplyState::RefusedRollbackFailed;
                        result.message = QStringLiteral("%1 refused: %2")
                                             .arg(objectKey(result.writes.back().index, result.writes.back().sub),
                                                  result.writes.back().error);
                        exec->report.nodes.push_back(result);
                        self->runNext(exec);
                    });
            });
        return;
    }
    exec->report.nodes.push_back(result);
    runNext(exec);
}

void ProjectApply::store(const std::vector<uint8_t>& nodes, std::function<void(std::vector<ConfigEntryResult>)> done) {
    auto results = std::make_shared<std::vector<ConfigEntryResult>>();
    auto remaining = std::make_shared<std::vector<uint8_t>>(nodes.rbegin(), nodes.rend());
    auto step = std::make_shared<std::function<void()>>();
    QPointer<ProjectApply> self(this);
    *step = [self, results, remaining, step, done] {
        if (!self) return;
        if (remaining->empty()) {
            done(*results);
            *step = nullptr;  // breaks the cycle
            return;
        }
        const uint8_t node = remaining->back();
        remaining->pop_back();
        // CiA 301 7.5.2.13: "save" signature, little-endian 's' 'a' 'v' 'e'.
        const QByteArray save("save", 4);
        self->sdo_.download(node, 0x1010, 1, save, [node, results, step, save](const canopen::SdoResult& r) {
            ConfigEntryResult e;
            e.index = 0x1010;
            e.sub = 1;
            e.name = QStringLiteral("Store parameters: save all (node %1)").arg(node);
            e.type = od::DataType::Unsigned32;
            e.data = save;
            e.valueText = QStringLiteral("0x65766173");
            e.ok = r.ok;
            e.abortCode = r.ok ? 0 : r.abortCode;
            e.error = r.error;
            results->push_back(e);
            if (*step) (*step)();
        });
    };
    (*step)();
}

bool acceptReplacedDrives(Project& project, const ApplyReport& report) {
    bool changed = false;
    for (const NodeApplyResult& n : report.nodes) {
        if (!n.newSerial || (n.state != NodeApplyState::Written && n.state != NodeApplyState::NothingToWrite)) continue;
        if (ProjectNode* node = project.node(n.node); node && node->identity.serial != n.newSerial) {
            node->identity.serial = n.newSerial;
            changed = true;
        }
    }
    return changed;
}

QString applyPlanText(const std::vector<NodeApplyPlan>& plans) {
    QString text;
    QTextStream out(&text);
    for (const NodeApplyPlan& p : plans) {
        out << "node " << p.node << (p.name.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(p.name)) << ": ";
        if (!p.writable()) {
            out << "not written: " << p.error << "\n";
            continue;
        }
        out << p.plan.writes.size() << " SDO write(s)\n";
        for (const canopen::PlannedWrite& w : p.plan.writes) {
            out << "  write " << objectKey(w.index, w.sub) << " " << w.name << " = " << w.valueText;
            if (!w.currentText.isEmpty()) out << "  (now " << w.currentText << ")";
            out << "\n";
        }
    }
    return text;
}

QString applyReportText(const ApplyReport& report) {
    QString text;
    QTextStream out(&text);
    for (const NodeApplyResult& n : report.nodes) {
        out << "node " << n.node << (n.name.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(n.name)) << ": "
            << nodeApplyStateName(n.state);
        if (!n.message.isEmpty()) out << " - " << n.message;
        out << "\n";
        for (const ConfigEntryResult& e : n.writes)
            out << "  " << (e.ok ? "ok     " : "FAILED ") << objectKey(e.index, e.sub) << " " << e.name << " = "
                << e.valueText << (e.ok ? QString() : QStringLiteral(": ") + e.error) << "\n";
        for (const ConfigEntryResult& e : n.rollback)
            out << "  " << (e.ok ? "back   " : "NOT BACK ") << objectKey(e.index, e.sub) << " " << e.name << " = "
                << e.valueText << (e.ok ? QString() : QStringLiteral(": ") + e.error) << "\n";
    }
    return text;
}

}  // namespace coscope::project
