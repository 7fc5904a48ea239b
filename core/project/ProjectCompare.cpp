// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/project/ProjectCompare.h"

#include "core/canopen/DeviceConfiguration.h"
#include "core/project/ProjectSoftware.h"

#include <QPointer>

namespace coscope::project {

QString rowStateName(RowState s) {
    switch (s) {
    case RowState::Same: return QStringLiteral("same");
    case RowState::Differs: return QStringLiteral("differs");
    case RowState::Unreadable: return QStringLiteral("unreadable");
    }
    return {};
}

bool CompareReport::clean() const { return differences() == 0; }

int CompareReport::differences() const {
    int n = 0;
    for (const CompareRow& r : rows) n += r.state == RowState::Differs ? 1 : 0;
    for (const NodeComparison& c : nodes) n += c.match == NodeMatch::Same ? 0 : 1;
    return n;
}

struct ProjectCompare::Run {
    Project project;
    std::vector<MatchedNode> matches;
    size_t next = 0;
    CompareReport report;
    Progress progress;
    Done done;
    std::unique_ptr<canopen::DeviceConfiguration> config;
};

ProjectCompare::ProjectCompare(canopen::SdoClient& sdo, DictionaryResolver resolver, QObject* parent)
    : QObject(parent), sdo_(sdo), resolver_(std::move(resolver)) {}

void ProjectCompare::start(const Project& project, Progress progress, Done done) {
    auto run = std::make_shared<Run>();
    run->project = project;
    run->progress = std::move(progress);
    run->done = std::move(done);
    run->report.projectName = project.name;
    run->report.busUrl = project.busUrl;
    run->config = std::make_unique<canopen::DeviceConfiguration>(sdo_);
    running_ = true;
    if (run->progress) run->progress(QStringLiteral("scanning nodes %1-%2").arg(first_).arg(last_), 0, 0);
    QPointer<ProjectCompare> self(this);
    scanMachine(
        sdo_, run->project, first_, last_, scanTimeoutMs_, matcher_,
        [self, run](std::vector<MatchedNode> matches) {
            if (!self) return;
            run->matches = std::move(matches);
            for (const MatchedNode& m : run->matches) {
                NodeComparison c;
                c.node = m.node;
                c.name = m.project ? m.project->name : (m.found ? m.found->dictionary : QString());
                c.match = m.match;
                c.detail = m.detail;
                run->report.nodes.push_back(c);
            }
            self->compareNext(run);
        },
        this);
}

void ProjectCompare::compareNext(std::shared_ptr<Run> run) {
    // The next project node that answered as a device of the project's type.
    while (run->next < run->matches.size()) {
        const MatchedNode& m = run->matches[run->next];
        if (m.project && (m.match == NodeMatch::Same || m.match == NodeMatch::Replaced)) break;
        ++run->next;
    }
    if (run->next >= run->matches.size()) {
        running_ = false;
        if (run->progress) run->progress(QStringLiteral("done"), 1, 1);
        run->done(run->report);
        return;
    }
    const size_t at = run->next++;
    const ProjectNode& node = *run->matches[at].project;
    NodeComparison& summary = run->report.nodes[at];
    QString error;
    const auto dict = resolver_(node, &error);
    if (!dict) {
        for (const ProjectParameter& p : node.parameters) {
            run->report.rows.push_back({node.id, p.index, p.sub, p.name, p.value, {}, {}, RowState::Unreadable, error});
            ++summary.unreadable;
        }
        compareNext(run);
        return;
    }
    const std::vector<ExpectedValue> expected = expectedValues(*dict, node);
    std::vector<std::pair<uint16_t, uint8_t>> entries;
    entries.reserve(expected.size());
    for (const ExpectedValue& e : expected) entries.emplace_back(e.index, e.sub);
    if (run->progress)
        run->progress(QStringLiteral("reading node %1").arg(node.id), static_cast<int>(at),
                      static_cast<int>(run->matches.size()));
    QPointer<ProjectCompare> self(this);
    const od::ObjectDictionary& dictionary = *dict;
    run->config->read(
        node.id, dictionary, entries, {}, [self, run, at, dictionary, expected](const canopen::ConfigReadResult& read) {
            if (!self) return;
            const ProjectNode& node = *run->matches[at].project;
            NodeComparison& summary = run->report.nodes[at];
            for (const ExpectedValue& want : expected) {
                CompareRow row{node.id, want.index, want.sub, {}, want.value, {}, {}, RowState::Same, {}};
                const od::SubObject* entry = dictionary.entry(want.index, want.sub);
                if (const ProjectParameter* p = node.parameter(want.index, want.sub)) row.name = p->name;
                if (entry) {
                    row.name = dictionary.displayName(want.index, want.sub);
                    row.defaultValue = defaultText(*entry, node.id);
                }
                const auto it = std::find_if(
                    read.entries.begin(), read.entries.end(),
                    [&](const canopen::ConfigEntryResult& e) { return e.index == want.index && e.sub == want.sub; });
                if (!entry) {
                    row.state = RowState::Unreadable;
                    row.error =
                        QStringLiteral("%1 is not in the node's dictionary").arg(objectKey(want.index, want.sub));
                } else if (it == read.entries.end() || !it->ok) {
                    row.state = RowState::Unreadable;
                    row.error = it == read.entries.end() ? QStringLiteral("not read") : it->error;
                } else {
                    row.driveValue = it->valueText;
                    row.state =
                        sameValue(*entry, want.value, it->valueText, node.id) ? RowState::Same : RowState::Differs;
                }
                if (row.state == RowState::Differs) ++summary.differences;
                if (row.state == RowState::Unreadable) ++summary.unreadable;
                run->report.rows.push_back(std::move(row));
            }
            self->compareSoftware(run, at);
        });
}

void ProjectCompare::compareSoftware(std::shared_ptr<Run> run, size_t at) {
    const ProjectNode& node = *run->matches[at].project;
    if (!node.firmware || !node.firmware->expectsSomething()) return compareNext(run);
    QPointer<ProjectCompare> self(this);
    canopen::readProgramState(sdo_, node.id, node.firmware->program,
                              [self, run, at](const canopen::ProgramState& state) {
                                  if (!self) return;
                                  NodeComparison& summary = run->report.nodes[at];
                                  for (CompareRow& row : softwareRows(*run->matches[at].project, state)) {
                                      if (row.state == RowState::Differs) ++summary.differences;
                                      if (row.state == RowState::Unreadable) ++summary.unreadable;
                                      run->report.rows.push_back(std::move(row));
                                  }
                                  self->compareNext(run);
                              });
}

}  // namespace coscope::project
