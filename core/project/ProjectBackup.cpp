// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/project/ProjectBackup.h"

#include "core/canopen/DeviceConfiguration.h"
#include "core/canopen/ProgramDownload.h"

#include <QPointer>

#include <algorithm>

namespace coscope::project {

struct ProjectBackup::Run {
    Project project;
    Project scanned;  // the project as it was when the scan matched (matches point into it)
    std::vector<MatchedNode> matches;
    size_t next = 0;
    std::vector<BackupNodeResult> results;
    Progress progress;
    Done done;
    std::unique_ptr<canopen::DeviceConfiguration> config;
};

ProjectBackup::ProjectBackup(canopen::SdoClient& sdo, DictionaryResolver resolver, QObject* parent)
    : QObject(parent), sdo_(sdo), resolver_(std::move(resolver)) {}

std::vector<ProjectParameter> ProjectBackup::configuredParameters(const od::ObjectDictionary& values, uint8_t node) {
    std::vector<ProjectParameter> out;
    for (const auto& [index, obj] : values.objects()) {
        for (const od::SubObject& s : obj.subs) {
            if (s.parameterValue.isEmpty() || !isConfigurationEntry(s)) continue;
            const QString def = defaultText(s, node);
            if (!def.isEmpty() && sameValue(s, def, s.parameterValue, node)) continue;
            out.push_back({index, s.sub, values.displayName(index, s.sub), s.parameterValue});
        }
    }
    return out;
}

void ProjectBackup::start(const Project& project, Progress progress, Done done) {
    auto run = std::make_shared<Run>();
    run->project = project;
    run->scanned = project;
    run->progress = std::move(progress);
    run->done = std::move(done);
    run->config = std::make_unique<canopen::DeviceConfiguration>(sdo_);
    if (run->progress) run->progress(QStringLiteral("scanning nodes %1-%2").arg(first_).arg(last_), 0, 0);
    QPointer<ProjectBackup> self(this);
    scanMachine(
        sdo_, run->scanned, first_, last_, scanTimeoutMs_, matcher_,
        [self, run](std::vector<MatchedNode> matches) {
            if (!self) return;
            run->matches = std::move(matches);
            self->backupNext(run);
        },
        this);
}

void ProjectBackup::backupNext(std::shared_ptr<Run> run) {
    if (run->next >= run->matches.size()) {
        std::sort(run->project.nodes.begin(), run->project.nodes.end(),
                  [](const auto& a, const auto& b) { return a.id < b.id; });
        if (run->progress) run->progress(QStringLiteral("done"), 1, 1);
        run->done(run->project, run->results);
        return;
    }
    const size_t at = run->next++;
    const MatchedNode& m = run->matches[at];
    BackupNodeResult result;
    result.node = m.node;
    if (!m.found) {
        result.name = m.project ? m.project->name : QString();
        result.message = QStringLiteral("missing: kept as it was");
        run->results.push_back(result);
        return backupNext(run);
    }
    ProjectNode* node = run->project.node(m.node);
    if (!node) {
        ProjectNode added;
        added.id = m.node;
        added.dictionary = matcher_ ? matcher_(*m.found) : m.found->dictionary;
        added.name = m.found->deviceName.value_or(added.dictionary);
        run->project.nodes.push_back(added);
        node = &run->project.nodes.back();
    }
    result.name = node->name;
    QString error;
    const auto dict = resolver_(*node, &error);
    if (!dict) {
        result.message = QStringLiteral("no dictionary: %1").arg(error);
        run->results.push_back(result);
        return backupNext(run);
    }
    if (run->progress)
        run->progress(QStringLiteral("reading node %1").arg(m.node), static_cast<int>(at),
                      static_cast<int>(run->matches.size()));
    QPointer<ProjectBackup> self(this);
    const uint8_t id = m.node;
    run->config->read(id, *dict, {}, [self, run, id, result](const canopen::ConfigReadResult& read) mutable {
        if (!self) return;
        ProjectNode* node = run->project.node(id);
        const auto& f = *std::find_if(run->matches.begin(), run->matches.end(), [id](const MatchedNode& m) {
                             return m.node == id;
                         })->found;
        node->identity = {f.vendorId, f.productCode, f.revision, f.serial};
        node->parameters = configuredParameters(read.values, id);
        result.read = static_cast<int>(read.entries.size()) - read.failed;
        result.failed = read.failed;
        result.parameters = static_cast<int>(node->parameters.size());
        result.ok = result.read > 0;
        result.message =
            result.ok ? QStringLiteral("%1 configured object(s) of %2 read%3")
                            .arg(result.parameters)
                            .arg(result.read)
                            .arg(result.failed ? QStringLiteral(", %1 unreadable").arg(result.failed) : QString())
                      : QStringLiteral("no object could be read");
        self->backupSoftware(run, id, result);
    });
}

// The program the node runs: 1F56h program software identification (CiA 302-3 §4) and 100Ah
// manufacturer software version (CiA 301 7.5.2.8), kept in nodes[].firmware beside the image file
// and program number the project names; a node that answers neither keeps what the project had.
void ProjectBackup::backupSoftware(std::shared_ptr<Run> run, uint8_t id, BackupNodeResult result) {
    ProjectNode* node = run->project.node(id);
    const uint8_t program = node && node->firmware ? node->firmware->program : 1;
    QPointer<ProjectBackup> self(this);
    canopen::readProgramState(sdo_, id, program, [self, run, id, result](const canopen::ProgramState& s) mutable {
        if (!self) return;
        ProjectNode* node = run->project.node(id);
        if (node && (s.softwareId || s.version)) {
            ProjectFirmware f = node->firmware.value_or(ProjectFirmware{});
            f.softwareId = s.softwareId;
            f.version = s.version.value_or(QString());
            node->firmware = f;
            result.message += s.version ? QStringLiteral("; software version %1").arg(*s.version)
                                        : QStringLiteral("; software identification %1").arg(hex32Text(*s.softwareId));
        }
        run->results.push_back(result);
        self->backupNext(run);
    });
}

}  // namespace coscope::project
