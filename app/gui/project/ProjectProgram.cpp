// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/project/ProjectProgram.h"

#include "app/gui/program/ProgramDownloadDialog.h"
#include "app/gui/project/ProjectSession.h"
#include "core/project/ProjectSoftware.h"

#include <QFileInfo>
#include <QMessageBox>

namespace coscope::gui {

QString ProjectProgram::imageFile(const ProjectSession& session, int node) {
    if (!session.isOpen() || node < 1 || node > 127) return {};
    const project::ProjectNode* n = session.project().node(static_cast<uint8_t>(node));
    if (!n || !n->firmware) return {};
    return project::firmwareFile(*n->firmware, QFileInfo(session.path()).absolutePath());
}

bool ProjectProgram::preset(ProgramDownloadDialog* dialog, const ProjectSession& session, int node, QWidget* parent) {
    const QString file = imageFile(session, node);
    if (file.isEmpty() || !dialog) return false;
    if (!QFileInfo::exists(file)) {
        QMessageBox::warning(parent, tr("Download the project's program"),
                             tr("The project's program of node %1 is not there: %2").arg(node).arg(file));
        return false;
    }
    dialog->setProgramNumber(session.project().node(static_cast<uint8_t>(node))->firmware->program);
    dialog->setImageFile(file);
    return true;
}

}  // namespace coscope::gui
