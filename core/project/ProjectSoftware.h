// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/ProgramDownload.h"
#include "core/project/ProjectCompare.h"

#include <functional>
#include <vector>

namespace coscope::project {

// The "software" rows of a node whose project names the program it runs (ProjectFirmware): 1F56h
// program software identification (CiA 302-3 §4) and 100Ah manufacturer software version (CiA 301
// 7.5.2.8), the project's value against what the node answered; a value the node did not answer
// is unreadable. Only the fields the project gives are compared.
std::vector<CompareRow> softwareRows(const ProjectNode& node, const canopen::ProgramState& state);
bool isSoftwareRow(const CompareRow& row);

// The image file of `firmware`, relative to `projectFolder` unless absolute ("" when none).
QString firmwareFile(const ProjectFirmware& firmware, const QString& projectFolder);

// What a node's program stands at against the project's, for `project program`.
struct SoftwareCheck {
    uint8_t node = 0;
    canopen::ProgramState state;
    std::vector<CompareRow> rows;
    bool differs() const;  // a row differs or is unreadable: the project's program is to be loaded
};

// Reads 1F56h/1F57h/100Ah of each project node that names a program (`only` empty) or of the
// nodes in `only`, one after the other, and hands back how each stands.
void checkSoftware(canopen::SdoClient& sdo, const Project& project, const std::vector<uint8_t>& only,
                   std::function<void(std::vector<SoftwareCheck>)> done);

}  // namespace coscope::project
