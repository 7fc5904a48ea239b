// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/events/EventLog.h"

#include <QSortFilterProxyModel>

#include <optional>

namespace coscope::gui {

// The Events dock's rows as the technician narrows them: one node, one kind, a least severity;
// sorted by the column clicked (EventsModel::SortRole), else in the order the events came.
class EventsFilterModel : public QSortFilterProxyModel {
    Q_OBJECT
public:
    explicit EventsFilterModel(QObject* parent = nullptr);

    void setNode(std::optional<int> node);               // nullopt: every node
    void setKind(std::optional<TraceEvent::Kind> kind);  // nullopt: every kind
    void setLeastSeverity(EventSeverity severity);       // Info: all
    bool isNarrowed() const { return node_ || kind_ || least_ != EventSeverity::Info; }

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex& sourceParent) const override;

private:
    std::optional<int> node_;
    std::optional<TraceEvent::Kind> kind_;
    EventSeverity least_ = EventSeverity::Info;
};

}  // namespace coscope::gui
