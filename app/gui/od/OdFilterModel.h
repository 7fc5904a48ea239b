// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QSortFilterProxyModel>

namespace coscope::gui {

// The search box and the "only changed" switch over an OdTreeModel: an entry is shown when its
// index ("6060", "6060h", "0x6060", "6060:00") or name contains the search text, and, with
// onlyChanged, when its value read from the node differs from the default. Objects with a
// matching sub-object stay visible.
class OdFilterModel : public QSortFilterProxyModel {
    Q_OBJECT
public:
    explicit OdFilterModel(QObject* parent = nullptr);

    void setSearch(const QString& text);
    void setOnlyChanged(bool on);
    bool onlyChanged() const { return onlyChanged_; }

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const override;

private:
    QString search_;
    bool onlyChanged_ = false;
};

}  // namespace coscope::gui
