// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/events/EventsModel.h"

#include <QApplication>
#include <QBrush>
#include <QColor>
#include <QStyle>

#include <algorithm>

namespace coscope::gui {

EventsModel::EventsModel(QObject* parent) : QAbstractTableModel(parent) {}

void EventsModel::setLog(EventLog* log) {
    beginResetModel();
    log_ = log;
    rows_ = 0;
    tail_.clear();
    blocks_.clear();
    nodes_.clear();
    generation_ = log ? log->generation() : 0;
    endResetModel();
    refresh();
}

void EventsModel::refresh() {
    if (!log_) return;
    if (log_->generation() != generation_) {
        beginResetModel();
        rows_ = 0;
        tail_.clear();
        blocks_.clear();
        nodes_.clear();
        generation_ = log_->generation();
        endResetModel();
    }
    // Only the newest rows are read here; older ones when the view shows them (rowAt()).
    const size_t total = log_->size();
    if (total == rows_) return;
    const size_t from = std::max(rows_, total > EventLog::kInRam ? total - EventLog::kInRam : size_t(0));
    auto fresh = log_->events(from, total);
    if (rows_ == 0 && total > 0) {
        const auto first = log_->events(0, 1);
        firstTime_ = first.empty() ? 0 : first.front().timeNs;
    }
    // In the UI language of now: a view built after View ▸ Language shows every event in it.
    for (TraceEvent& e : fresh) {
        if (e.render) e.text = e.render();
        if (e.node >= 0) nodes_.insert(e.node);
    }
    beginInsertRows({}, rowCount(), static_cast<int>(from + fresh.size()) - 1);
    if (from > rows_) tail_.clear();
    tail_.insert(tail_.end(), std::make_move_iterator(fresh.begin()), std::make_move_iterator(fresh.end()));
    rows_ = from + fresh.size();
    while (tail_.size() > EventLog::kInRam) tail_.pop_front();
    endInsertRows();
}

size_t EventsModel::rowsInRam() const {
    size_t n = tail_.size();
    for (const auto& [b, rows] : blocks_) n += rows.first.size();
    return n;
}

TraceEvent EventsModel::eventAt(int row) const { return rowAt(static_cast<size_t>(row)); }

const TraceEvent& EventsModel::rowAt(size_t row) const {
    if (row + tail_.size() >= rows_) return tail_[row + tail_.size() - rows_];
    const size_t b = row / kBlock;
    auto it = blocks_.find(b);
    if (it == blocks_.end()) {
        if (blocks_.size() >= kBlocksKept) {
            auto oldest = blocks_.begin();
            for (auto i = blocks_.begin(); i != blocks_.end(); ++i)
                if (i->second.second < oldest->second.second) oldest = i;
            blocks_.erase(oldest);
        }
        std::vector<TraceEvent> rows = log_ ? log_->events(b * kBlock, (b + 1) * kBlock) : std::vector<TraceEvent>{};
        for (TraceEvent& e : rows)
            if (e.render) e.text = e.render();
        it = blocks_.emplace(b, std::pair{std::move(rows), uint64_t(0)}).first;
    }
    it->second.second = ++useClock_;
    static const TraceEvent none;
    const size_t i = row - b * kBlock;
    return i < it->second.first.size() ? it->second.first[i] : none;
}

void EventsModel::setOrigin(int64_t originNs) {
    if (originNs == origin_) return;
    origin_ = originNs;
    if (rows_ > 0) emit dataChanged(index(0, Time), index(rowCount() - 1, Time));
}

QString EventsModel::timeText(const TraceEvent& e) const {
    const int64_t origin = origin_ ? origin_ : (rows_ ? firstTime_ : e.timeNs);
    return TimeBase{origin, timeMode_}.text(e.timeNs);
}

void EventsModel::setTimeMode(TimeBase::Mode mode) {
    if (mode == timeMode_) return;
    timeMode_ = mode;
    emit headerDataChanged(Qt::Horizontal, Time, Time);
    if (rows_ > 0) emit dataChanged(index(0, Time), index(rowCount() - 1, Time));
}

int EventsModel::rowCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : static_cast<int>(rows_); }
int EventsModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant EventsModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const TraceEvent& e = rowAt(static_cast<size_t>(index.row()));
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
        const int64_t origin = origin_ ? origin_ : (rows_ ? firstTime_ : 0);
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
