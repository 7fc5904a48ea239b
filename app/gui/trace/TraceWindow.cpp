// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/trace/TraceWindow.h"

#include "app/gui/trace/TraceModel.h"

#include <QSettings>

#include <algorithm>

namespace coscope::gui {

int TraceWindow::configuredRows() {
    const int rows = QSettings().value(QStringLiteral("trace/windowRows"), kDefaultRows).toInt();
    return std::max(rows, 200);  // a few pages at least
}

TraceWindow::TraceWindow(TraceModel* source, QObject* parent)
    : QAbstractTableModel(parent), source_(source), capacity_(configuredRows()) {
    count_ = std::min(source_->rowCount(), maxRows());
    connect(source_, &QAbstractItemModel::modelAboutToBeReset, this, [this] { beginResetModel(); });
    connect(source_, &QAbstractItemModel::modelReset, this, [this] {
        base_ = 0;
        count_ = std::min(total(), capacity_);
        endResetModel();
    });
    connect(source_, &QAbstractItemModel::rowsAboutToBeInserted, this,
            [this](const QModelIndex&, int f, int l) { onAboutToInsert(f, l); });
    connect(source_, &QAbstractItemModel::rowsInserted, this, [this] { onInserted(); });
    connect(source_, &QAbstractItemModel::rowsAboutToBeRemoved, this,
            [this](const QModelIndex&, int f, int l) { onAboutToRemove(f, l); });
    connect(source_, &QAbstractItemModel::rowsRemoved, this, [this] { onRemoved(); });
    connect(source_, &QAbstractItemModel::dataChanged, this, &TraceWindow::onDataChanged);
    connect(source_, &QAbstractItemModel::headerDataChanged, this, [this](Qt::Orientation o, int first, int last) {
        if (o == Qt::Horizontal) emit headerDataChanged(o, first, last);
    });
}

int TraceWindow::total() const { return source_->rowCount(); }

void TraceWindow::moveTo(int first) {
    const int rows = total();
    first = std::clamp(first, 0, std::max(0, rows - capacity_));
    beginResetModel();
    base_ = first;
    count_ = std::min(rows - first, capacity_);
    endResetModel();
}

void TraceWindow::onAboutToInsert(int first, int last) {
    const int n = last - first + 1;
    pending_ = {};
    if (first < base_) {
        pending_.shift = n;
        return;
    }
    const int end = base_ + count_;
    if (first > end) return;
    // Rows appended at the window's end join it while it has room (live frames at the tail).
    const int take = first == end ? std::min(n, std::max(0, maxRows() - count_)) : n;
    if (take == 0) return;
    beginInsertRows({}, first - base_, first - base_ + take - 1);
    pending_.rows = take;
}

void TraceWindow::onInserted() {
    base_ += pending_.shift;
    if (pending_.rows > 0) {
        count_ += pending_.rows;
        endInsertRows();
    }
    pending_ = {};
}

void TraceWindow::onAboutToRemove(int first, int last) {
    pending_ = {};
    const int end = base_ + count_;
    pending_.shift = -std::max(0, std::min(last + 1, base_) - first);
    const int lo = std::max(first, base_), hi = std::min(last, end - 1);
    if (lo > hi) return;
    beginRemoveRows({}, lo - base_, hi - base_);
    pending_.rows = -(hi - lo + 1);
}

void TraceWindow::onRemoved() {
    base_ += pending_.shift;
    if (pending_.rows < 0) {
        count_ += pending_.rows;
        endRemoveRows();
    }
    pending_ = {};
}

void TraceWindow::onDataChanged(const QModelIndex& topLeft, const QModelIndex& bottomRight, const QList<int>& roles) {
    const int lo = std::max(topLeft.row(), base_), hi = std::min(bottomRight.row(), base_ + count_ - 1);
    if (lo > hi) return;
    emit dataChanged(index(lo - base_, topLeft.column()), index(hi - base_, bottomRight.column()), roles);
}

int TraceWindow::rowCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : count_; }
int TraceWindow::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : source_->columnCount(); }

QVariant TraceWindow::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= count_) return {};
    return source_->data(source_->index(base_ + index.row(), index.column()), role);
}

QVariant TraceWindow::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation == Qt::Vertical) return role == Qt::DisplayRole ? QVariant(base_ + section + 1) : QVariant();
    return source_->headerData(section, orientation, role);
}

Qt::ItemFlags TraceWindow::flags(const QModelIndex& index) const {
    if (!index.isValid() || index.row() >= count_) return Qt::NoItemFlags;
    return source_->flags(source_->index(base_ + index.row(), index.column()));
}

}  // namespace coscope::gui
