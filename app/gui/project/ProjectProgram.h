// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QString>

#include <cstdint>

class QWidget;

namespace coscope::gui {

class ProgramDownloadDialog;
class ProjectSession;

// The program a project names for a node (nodes[].firmware, CiA 302-3 program download), loaded
// through the program download dialog and its confirmations: from the comparison and from the
// Nodes dock's context menu.
class ProjectProgram {
    Q_DECLARE_TR_FUNCTIONS(ProjectProgram)
public:
    // The image file the open project names for `node` ("" = none).
    static QString imageFile(const ProjectSession& session, int node);
    // Fills `dialog` with the project's image and program number; false (and a message box on
    // `parent`) when the file is not there.
    static bool preset(ProgramDownloadDialog* dialog, const ProjectSession& session, int node, QWidget* parent);
};

}  // namespace coscope::gui
