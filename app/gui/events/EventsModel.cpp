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
    generation_ = log ? log->generation() : 0;
    endResetModel();
    refresh();
}

void EventsModel::refresh() {
    if (!log_) return;
    if (log_->generation() != generation_) {
        beginResetModel();
        events_.clear();
        generation_ = log_->generation();
        endResetModel();
    }
    auto fresh = log_->since(events_.size());
    if (fresh.empty()) return;
    // In the UI language of now: a view built after View ▸ Language shows every event in it.
    for (TraceEvent& e : fresh)
        if (e.render) e.text = e.render();
    beginInsertRows({}, rowCount(), rowCount() + static_cast<int>(fresh.size()) - 1);
    events_.insert(events_.end(), std::make_move_iterator(fresh.begin()), std::make_move_iterator(fresh.end()));
    endInsertRows();
}

void EventsModel::setOrigin(int64_t originNs) {
    if (originNs == origin_) return;
    origin_ = originNs;
    if (!events_.empty()) emit dataChanged(index(0, Time), index(rowCount() - 1, Time));
}

int EventsModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(events_.size());
}
int EventsModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant EventsModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const TraceEvent& e = events_[static_cast<size_t>(index.row())];
    using K = TraceEvent::Kind;
    const bool severe = e.kind == K::Emcy || e.kind == K::SdoAbort || e.kind == K::HeartbeatTimeout ||
                        e.kind == K::BusError || e.kind == K::Dropped;
    if (role == Qt::DecorationRole && index.column() == Kind) {
        QStyle* st = QApplication::style();
        return st->standardIcon(severe ? QStyle::SP_MessageBoxWarning : QStyle::SP_MessageBoxInformation);
    }
    if (role == Qt::ForegroundRole && severe) return QBrush(QColor(176, 0, 32));
    if (role == Qt::TextAlignmentRole && (index.column() == Time || index.column() == Node || index.column() == Frame))
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole) return {};
    switch (index.column()) {
    case Time: {
        const int64_t origin = origin_ ? origin_ : events_.front().timeNs;
        return QString::number(double(e.timeNs - origin) / 1e9, 'f', 6);
    }
    case Node: return e.node >= 0 ? QVariant(e.node) : QVariant(QString());
    case Kind: return eventKindName(e.kind);
    case Text: return e.text;
    case Frame: return e.frame == kNoFrame ? QVariant(QString()) : QVariant(static_cast<qulonglong>(e.frame) + 1);
    default: return {};
    }
}

QVariant EventsModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case Time: return tr("Time (s)");
    case Node: return tr("Node");
    case Kind: return tr("Event");
    case Text: return tr("Details");
    case Frame: return tr("Frame");
    default: return {};
    }
}

}  // namespace coscope::gui
