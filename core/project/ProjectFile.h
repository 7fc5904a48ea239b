// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/project/Project.h"

#include <QByteArray>
#include <QString>

#include <optional>

namespace coscope::project {

struct ProjectReadResult {
    std::optional<Project> project;
    // One line naming the file and the line (JSON syntax) or the key (content):
    // "machine.coscope:12: error: ..." / "machine.coscope: nodes[1].id: must be 1-127".
    QString error;
};

// The project file (README "Project file"): JSON, UTF-8, format version in "format". Files of a
// newer format are refused; unknown keys are kept and written back.
class ProjectFile {
public:
    static ProjectReadResult read(const QString& path);
    static ProjectReadResult parse(const QByteArray& json, const QString& fileName);
    static QByteArray serialize(const Project& project);
    // Written through a temporary file and renamed, so a failed write leaves the old file.
    static bool write(const Project& project, const QString& path, QString* error);
};

}  // namespace coscope::project
