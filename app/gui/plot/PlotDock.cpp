// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/plot/PlotDock.h"

#include "app/gui/session/Workspace.h"

#include <QLabel>

namespace coscope::gui {

PlotDock::PlotDock(Workspace* workspace, QWidget* parent) : QDockWidget(tr("Plot"), parent), workspace_(workspace) {
    setObjectName(QStringLiteral("PlotDock"));
    setWidget(new QLabel(tr("Pick signals to plot"), this));
}

void PlotDock::rebind() {}
void PlotDock::refresh() {}
bool PlotDock::hasContent() const { return false; }

}  // namespace coscope::gui
