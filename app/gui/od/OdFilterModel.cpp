// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/od/OdFilterModel.h"

#include "app/gui/od/OdTreeModel.h"

namespace coscope::gui {

OdFilterModel::OdFilterModel(QObject* parent) : QSortFilterProxyModel(parent) {
    setRecursiveFilteringEnabled(true);
    setAutoAcceptChildRows(true);
}

void OdFilterModel::setSearch(const QString& text) {
    QString s = text.trimmed();
    // "0x6060" and "6060h" name the same object as "6060".
    if (s.startsWith(QLatin1String("0x"), Qt::CaseInsensitive)) s = s.mid(2);
    if (s.size() == 5 && s.endsWith(u'h', Qt::CaseInsensitive)) {
        bool hex = false;
        s.left(4).toUInt(&hex, 16);
        if (hex) s.chop(1);
    }
    if (s == search_) return;
    search_ = s;
    invalidateRowsFilter();
}

void OdFilterModel::setOnlyChanged(bool on) {
    if (on == onlyChanged_) return;
    onlyChanged_ = on;
    invalidateRowsFilter();
}

bool OdFilterModel::filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const {
    const QModelIndex idx = sourceModel()->index(sourceRow, 0, sourceParent);
    const bool composite = idx.data(OdTreeModel::SubRole).toInt() < 0;
    if (onlyChanged_) {
        if (composite) return false;  // shown through its changed sub-objects
        if (!idx.data(OdTreeModel::ChangedRole).toBool()) return false;
    }
    if (search_.isEmpty()) return true;
    return idx.data(OdTreeModel::SearchRole).toString().contains(search_, Qt::CaseInsensitive);
}

}  // namespace coscope::gui
