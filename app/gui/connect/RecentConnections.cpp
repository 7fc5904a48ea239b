// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/connect/RecentConnections.h"

#include <QSettings>

namespace coscope::gui::RecentConnections {

namespace {
constexpr int kMax = 10;
const char* const kKey = "connect/recent";
}  // namespace

QStringList list() { return QSettings().value(QLatin1String(kKey)).toStringList(); }

void add(const QString& url) {
    QStringList l = list();
    l.removeAll(url);
    l.prepend(url);
    while (l.size() > kMax) l.removeLast();
    QSettings().setValue(QLatin1String(kKey), l);
}

void clear() { QSettings().remove(QLatin1String(kKey)); }

}  // namespace coscope::gui::RecentConnections
