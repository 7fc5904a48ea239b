// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/events/EventsModel.h"

#include <QApplication>
#include <QBrush>
#include <QColor>
#include <QStyle>

namespace coscope::gui {

EventsModel::EventsModel(QObject* parent) : QAbstractTableModel(parent) {}

void EventsModel::setLog(EventLog* log) {
    beginResetModel();
    log_ = log;
    events_.clear();
    nodes_.clear();
    generation_ = log ? log->generation() : 0;
    endResetModel();
    refresh();
}

void EventsModel::refresh() {
    if (!log_) return;
    if (log_->generation() != generation_) {
        beginResetModel();
        events_.clear();
        nodes_.clear();
        generation_ = log_->generation();
        endResetModel();
    }
    auto fresh = log_->since(events_.size());
    if (fresh.empty()) return;
    // In the UI language of now: a view built after View ▸ Language shows every event in it.
    for (TraceEvent& e : fresh) {
        if (e.render) e.text = e.render();
        if (e.node >= 0) nodes_.insert(e.node);
    }
    beginInsertRows({}, rowCount(), rowCount() + static_cast<int>(fresh.size()) - 1);
    events_.insert(events_.end(), std::make_move_iterator(fresh.begin()), std::make_move_iterator(fresh.end()));
    endInsertRows();
}

void EventsModel::setOrigin(int64_t originNs) {
    if (originNs == origin_) return;
    origin_ = originNs;
    if (!events_.empty()) emit dataChanged(index(0, Time), index(rowCount() - 1, Time));
}

QString EventsModel::timeText(const TraceEvent& e) const {
    const int64_t origin = origin_ ? origin_ : (events_.empty() ? e.timeNs : events_.front().timeNs);
    return TimeBase{origin, timeMode_}.text(e.timeNs);
}

void EventsModel::setTimeMode(TimeBase::Mode mode) {
    if (mode == timeMode_) return;
    timeMode_ = mode;
    emit headerDataChanged(Qt::Horizontal, Time, Time);
    if (!events_.empty()) emit dataChanged(index(0, Time), index(rowCount() - 1, Time));
}

int EventsModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(events_.size());
}
int EventsModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant EventsModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const TraceEvent& e = events_[static_cast<size_t>(index.row())];
    const EventSeverity severity = eventSeverity(e.kind);
    const bool severe = severity != EventSeverity::Info;
    if (role == SortRole) {
        switch (index.column()) {
        case Time: return QVariant::fromValue<qlonglong>(e.timeNs);
        case Node: return e.node;
        case Kind: return static_cast<int>(e.kind);
        case Severity: return static_cast<int>(severity);
        case Frame: return e.frame == kNoFrame ? QVariant(-1) : QVariant::fromValue<qlonglong>(e.frame);
        default: return e.text;
        }
    }
    if (role == Qt::DecorationRole && index.column() == Kind) {
        QStyle* st = QApplication::style();
        return st->standardIcon(severity == EventSeverity::Error     ? QStyle::SP_MessageBoxCritical
                                : severity == EventSeverity::Warning ? QStyle::SP_MessageBoxWarning
                                                                     : QStyle::SP_MessageBoxInformation);
    }
    if (role == Qt::ForegroundRole && severe) return QBrush(QColor(176, 0, 32));
    if (role == Qt::TextAlignmentRole && (index.column() == Time || index.column() == Node || index.column() == Frame))
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole) return {};
    switch (index.column()) {
    case Time: return timeText(e);
    case Node: return e.node >= 0 ? QVariant(e.node) : QVariant(QString());
    case Kind: return eventKindName(e.kind);
    case Severity: return eventSeverityName(severity);
    case Text: return e.text;
    case Frame: return e.frame == kNoFrame ? QVariant(QString()) : QVariant(static_cast<qulonglong>(e.frame) + 1);
    default: return {};
    }
}

QVariant EventsModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case Time: {
        const int64_t origin = origin_ ? origin_ : (events_.empty() ? 0 : events_.front().timeNs);
        return TimeBase{origin, timeMode_}.shown() == TimeBase::Mode::WallClock ? tr("Time") : tr("Time (s)");
    }
    case Node: return tr("Node");
    case Kind: return tr("Event");
    case Severity: return tr("Severity");
    case Text: return tr("Details");
    case Frame: return tr("Frame");
    default: return {};
    }
}

}  // namespace coscope::gui
