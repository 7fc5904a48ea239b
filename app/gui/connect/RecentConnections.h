// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QStringList>

namespace coscope::gui {

// The bus URLs connected to most recently (newest first, at most 10), kept in QSettings.
namespace RecentConnections {
QStringList list();
void add(const QString& url);
void clear();
}  // namespace RecentConnections

}  // namespace coscope::gui
