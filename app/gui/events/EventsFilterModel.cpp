// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/events/EventsFilterModel.h"

#include "app/gui/events/EventsModel.h"

namespace coscope::gui {

EventsFilterModel::EventsFilterModel(QObject* parent) : QSortFilterProxyModel(parent) {
    setSortRole(EventsModel::SortRole);
    setDynamicSortFilter(true);
}

void EventsFilterModel::setNode(std::optional<int> node) {
    if (node == node_) return;
    node_ = node;
    invalidateRowsFilter();
}

void EventsFilterModel::setKind(std::optional<TraceEvent::Kind> kind) {
    if (kind == kind_) return;
    kind_ = kind;
    invalidateRowsFilter();
}

void EventsFilterModel::setLeastSeverity(EventSeverity severity) {
    if (severity == least_) return;
    least_ = severity;
    invalidateRowsFilter();
}

bool EventsFilterModel::filterAcceptsRow(int sourceRow, const QModelIndex&) const {
    const auto* events = static_cast<const EventsModel*>(sourceModel());
    const TraceEvent& e = events->eventAt(sourceRow);
    if (node_ && e.node != *node_) return false;
    if (kind_ && e.kind != *kind_) return false;
    return static_cast<int>(eventSeverity(e.kind)) >= static_cast<int>(least_);
}

}  // namespace coscope::gui
