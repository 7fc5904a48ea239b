// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/events/EventLog.h"
#include "core/trace/TimeBase.h"

#include <QAbstractTableModel>

#include <deque>
#include <map>
#include <set>
#include <vector>

namespace coscope::gui {

// Rows of the event log; refresh() appends the events logged since the last call. Bounded
// (issue 38): the newest EventLog::kInRam rows are held here, older ones are read back from the
// log (its spill file) in blocks of kBlock rows as the view shows them, a few blocks kept.
class EventsModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Time, Node, Kind, Severity, Text, Frame, ColumnCount };
    // What a column sorts by (time in ns, node, kind, severity, frame as numbers).
    enum Role { SortRole = Qt::UserRole + 1 };

    explicit EventsModel(QObject* parent = nullptr);

    void setLog(EventLog* log);
    void refresh();
    // The trace's first timestamp, so event times read like the trace's relative time. Until the
    // trace has a frame (0), times count from the first event: an event before the first frame
    // (a bus that would not open) reads 0.000000, not seconds since 1970.
    void setOrigin(int64_t originNs);
    // Relative seconds or the wall clock (Workspace::timeMode()).
    void setTimeMode(TimeBase::Mode mode);

    TraceEvent eventAt(int row) const;
    static constexpr size_t kBlock = 256;
    static constexpr size_t kBlocksKept = 8;
    size_t rowsInRam() const;  // the newest rows and the blocks of older ones kept
    // The nodes the events name, ascending (for the Events dock's node filter).
    const std::set<int>& nodes() const { return nodes_; }
    // The Time column's text of an event: seconds since the trace's first frame, or its wall clock.
    QString timeText(const TraceEvent& e) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    EventLog* log_ = nullptr;
    uint64_t generation_ = 0;
    const TraceEvent& rowAt(size_t row) const;
    size_t rows_ = 0;
    std::deque<TraceEvent> tail_;  // rows [rows_ - tail_.size(), rows_)
    int64_t firstTime_ = 0;        // of row 0
    mutable std::map<size_t, std::pair<std::vector<TraceEvent>, uint64_t>> blocks_;  // block -> rows, last use
    mutable uint64_t useClock_ = 0;
    int64_t origin_ = 0;
    TimeBase::Mode timeMode_ = TimeBase::Mode::Relative;
    std::set<int> nodes_;
};

}  // namespace coscope::gui
