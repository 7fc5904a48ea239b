// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/od/ObjectDictionaryDock.h"

#include "app/gui/session/Workspace.h"

#include <QLabel>

namespace coscope::gui {

ObjectDictionaryDock::ObjectDictionaryDock(Workspace* workspace, QWidget* parent)
    : QDockWidget(tr("Object Dictionary"), parent), workspace_(workspace) {
    setObjectName(QStringLiteral("ObjectDictionaryDock"));
    setWidget(new QLabel(tr("Select a node"), this));
}

void ObjectDictionaryDock::rebind() {}
void ObjectDictionaryDock::refresh() {}
void ObjectDictionaryDock::setNode(int node) { node_ = node; }
bool ObjectDictionaryDock::hasContent() const { return node_ >= 0; }

}  // namespace coscope::gui
