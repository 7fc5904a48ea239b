// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/project/ProjectSoftware.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <memory>

namespace coscope::project {

namespace {
constexpr uint16_t kSoftwareId = 0x1F56;  // program software identification (CiA 302-3 §4)
constexpr uint16_t kVersion = 0x100A;     // manufacturer software version (CiA 301 7.5.2.8)

CompareRow softwareRow(uint8_t node, uint16_t index, uint8_t sub, const QString& name, const QString& project,
                       const std::optional<QString>& drive) {
    CompareRow r{node, index, sub, name, project, drive.value_or(QString()), {}, RowState::Same, {}};
    if (!drive) {
        r.state = RowState::Unreadable;
        r.error = QStringLiteral("%1 not answered").arg(objectKey(index, sub));
    } else if (drive->trimmed() != project.trimmed()) {
        r.state = RowState::Differs;
    }
    return r;
}
}  // namespace

std::vector<CompareRow> softwareRows(const ProjectNode& node, const canopen::ProgramState& state) {
    std::vector<CompareRow> out;
    if (!node.firmware) return out;
    const ProjectFirmware& f = *node.firmware;
    if (f.softwareId) {
        const std::optional<QString> drive =
            state.softwareId ? std::optional<QString>(hex32Text(*state.softwareId)) : std::nullopt;
        out.push_back(softwareRow(node.id, kSoftwareId, f.program, QStringLiteral("software identification"),
                                  hex32Text(*f.softwareId), drive));
    }
    if (!f.version.isEmpty())
        out.push_back(softwareRow(node.id, kVersion, 0, QStringLiteral("software version"), f.version, state.version));
    return out;
}

bool isSoftwareRow(const CompareRow& r) { return (r.index == kSoftwareId) || (r.index == kVersion && r.sub == 0); }

QString firmwareFile(const ProjectFirmware& f, const QString& projectFolder) {
    if (f.file.isEmpty()) return {};
    if (QFileInfo(f.file).isAbsolute()) return f.file;
    return QDir(projectFolder).absoluteFilePath(f.file);
}

bool SoftwareCheck::differs() const {
    return std::any_of(rows.begin(), rows.end(), [](const CompareRow& r) { return r.state != RowState::Same; });
}

namespace {
struct SoftwareRun {
    canopen::SdoClient* sdo = nullptr;
    std::vector<ProjectNode> nodes;
    std::vector<SoftwareCheck> out;
    std::function<void(std::vector<SoftwareCheck>)> done;
};

// One node after the other.
void checkNext(const std::shared_ptr<SoftwareRun>& run) {
    if (run->out.size() >= run->nodes.size()) {
        run->done(std::move(run->out));
        return;
    }
    const ProjectNode& n = run->nodes[run->out.size()];
    canopen::readProgramState(*run->sdo, n.id, n.firmware ? n.firmware->program : 1,
                              [run](const canopen::ProgramState& s) {
                                  const ProjectNode& node = run->nodes[run->out.size()];
                                  run->out.push_back({node.id, s, softwareRows(node, s)});
                                  checkNext(run);
                              });
}
}  // namespace

void checkSoftware(canopen::SdoClient& sdo, const Project& project, const std::vector<uint8_t>& only,
                   std::function<void(std::vector<SoftwareCheck>)> done) {
    auto run = std::make_shared<SoftwareRun>();
    run->sdo = &sdo;
    run->done = std::move(done);
    for (const ProjectNode& n : project.nodes) {
        const bool wanted = only.empty() ? (n.firmware && n.firmware->expectsSomething())
                                         : std::find(only.begin(), only.end(), n.id) != only.end();
        if (wanted) run->nodes.push_back(n);
    }
    checkNext(run);
}

}  // namespace coscope::project
