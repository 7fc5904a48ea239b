// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/connect/RecentConnections.h"

#include "app/gui/files/RecentFiles.h"

namespace coscope::gui::RecentConnections {

namespace {
// The same list model as recent logs and projects, under the key it always had.
RecentList recent() { return RecentList(QStringLiteral("connect/recent"), 10); }
}  // namespace

QStringList list() { return recent().list(); }

void add(const QString& url) { recent().add(url); }

void clear() { recent().clear(); }

}  // namespace coscope::gui::RecentConnections
