// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/trace/TraceView.h"

#include "app/gui/trace/TraceModel.h"
#include "app/gui/trace/TraceWindow.h"

#include <QScrollBar>
#include <QSignalBlocker>

#include <algorithm>

namespace coscope::gui {

TraceView::TraceView(TraceModel* model, QWidget* parent)
    : QTableView(parent), source_(model), window_(new TraceWindow(model, this)),
      bar_(new QScrollBar(Qt::Vertical, this)) {
    setModel(window_);
    setVerticalScrollBarPolicy(Qt::ScrollBarAlwaysOff);  // bar_ stands for it, over the whole trace
    bar_->setObjectName(QStringLiteral("traceScrollBar"));
    QScrollBar* inner = verticalScrollBar();
    connect(inner, &QScrollBar::valueChanged, this, &TraceView::onInnerScrolled);
    connect(bar_, &QScrollBar::valueChanged, this, &TraceView::onBarMoved);
    connect(inner, &QScrollBar::actionTriggered, this, [this, inner](int action) {
        if (action != QAbstractSlider::SliderNoAction)
            emit userScrolled(window_->atEnd() && inner->sliderPosition() >= inner->maximum());
    });
    connect(bar_, &QScrollBar::actionTriggered, this, [this](int action) {
        if (action != QAbstractSlider::SliderNoAction) emit userScrolled(bar_->sliderPosition() >= bar_->maximum());
    });
    // Rows come and go outside the window too: the bar spans them.
    connect(model, &QAbstractItemModel::rowsInserted, this, &TraceView::syncBar);
    connect(model, &QAbstractItemModel::rowsRemoved, this, &TraceView::syncBar);
    connect(model, &QAbstractItemModel::modelReset, this, &TraceView::syncBar);
}

int TraceView::logicalRow(const QModelIndex& index) const {
    return index.isValid() ? window_->toSource(index.row()) : -1;
}

int TraceView::currentRow() const { return current_.isValid() ? current_.row() : -1; }

int TraceView::pageRows() const { return std::max(1, verticalScrollBar()->pageStep()); }

int TraceView::topRow() const { return window_->base() + verticalScrollBar()->value(); }

void TraceView::setCurrentRow(int row, bool center) {
    if (row < 0 || row >= window_->total()) return;
    ensureWindowAround(row);
    const QModelIndex idx = window_->index(window_->fromSource(row), 0);
    setCurrentIndex(idx);
    scrollTo(idx, center ? PositionAtCenter : EnsureVisible);
}

void TraceView::scrollToEnd() {
    const int rows = window_->total();
    if (rows == 0) return;
    if (!window_->atEnd() || window_->rowCount() >= window_->maxRows())
        moveWindow(rows - window_->capacity(), rows - 1);
    scrollToBottom();
    syncBar();
}

void TraceView::scrollToStart() {
    if (window_->base() > 0) moveWindow(0, 0);
    scrollToTop();
    syncBar();
}

void TraceView::ensureWindowAround(int row) {
    const int margin = window_->capacity() / 4;
    const int b = window_->base(), e = b + window_->rowCount();
    const bool roomAbove = b == 0 || row - b >= margin;
    const bool roomBelow = window_->atEnd() || e - row >= margin;
    if (row >= b && row < e && roomAbove && roomBelow) return;
    moveWindow(row - window_->capacity() / 2, topRow());
}

void TraceView::moveWindow(int first, int top) {
    const int col = std::max(0, currentIndex().column());
    syncing_ = true;
    window_->moveTo(first);  // a reset: the selection model forgets the current row, silently
    executeDelayedItemsLayout();
    updateGeometries();
    const int row = current_.isValid() ? window_->fromSource(current_.row()) : -1;
    if (row >= 0)
        selectionModel()->setCurrentIndex(window_->index(row, col),
                                          QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    verticalScrollBar()->setValue(top - window_->base());
    syncing_ = false;
    syncBar();
}

void TraceView::onInnerScrolled(int value) {
    if (syncing_) return;
    const int margin = window_->capacity() / 4;
    const QScrollBar* inner = verticalScrollBar();
    const bool nearTop = value < margin && window_->base() > 0;
    const bool nearBottom = inner->maximum() - value < margin && !window_->atEnd();
    if (nearTop || nearBottom) moveWindow(window_->base() + value - window_->capacity() / 2, window_->base() + value);
    else syncBar();
}

void TraceView::onBarMoved(int top) {
    if (syncing_) return;
    const int margin = window_->capacity() / 4;
    const int b = window_->base(), e = b + window_->rowCount();
    const int page = pageRows();
    if (top < b || top + page > e || (top - b < margin && b > 0) || (e - top - page < margin && !window_->atEnd())) {
        moveWindow(top - window_->capacity() / 2, top);
        return;
    }
    syncing_ = true;
    verticalScrollBar()->setValue(top - b);
    syncing_ = false;
}

void TraceView::syncBar() {
    const QScrollBar* inner = verticalScrollBar();
    // Rows that fit below the last scroll position: what the view's own bar leaves out.
    const int fit = std::max(0, window_->rowCount() - inner->maximum());
    const QSignalBlocker block(bar_);
    bar_->setRange(0, std::max(0, window_->total() - fit));
    bar_->setPageStep(std::max(1, inner->pageStep()));
    bar_->setSingleStep(1);
    bar_->setValue(window_->base() + inner->value());
    const bool needed = bar_->maximum() > 0;  // shown as needed, as the view's own would be
    if (needed == bar_->isHidden()) bar_->setVisible(needed);
}

void TraceView::updateGeometries() {
    QTableView::updateGeometries();
    if (!syncing_) syncBar();
}

void TraceView::currentChanged(const QModelIndex& current, const QModelIndex& previous) {
    if (current.isValid()) current_ = source_->index(window_->toSource(current.row()), 0);
    else if (!syncing_) current_ = QPersistentModelIndex();
    QTableView::currentChanged(current, previous);
}

QModelIndex TraceView::moveCursor(CursorAction action, Qt::KeyboardModifiers modifiers) {
    const int rows = window_->total();
    if (rows == 0) return {};
    const int cur = currentRow();
    const int from = cur >= 0 ? cur : topRow();
    int target = 0;
    switch (action) {
    case MoveHome: target = 0; break;  // the first frame (with or without Ctrl: rows are selected whole)
    case MoveEnd: target = rows - 1; break;
    case MoveUp: target = cur >= 0 ? cur - 1 : from; break;
    case MoveDown: target = cur >= 0 ? cur + 1 : from; break;
    case MovePageUp: target = from - pageRows(); break;
    case MovePageDown: target = from + pageRows(); break;
    default: return QTableView::moveCursor(action, modifiers);  // left, right, tab
    }
    target = std::clamp(target, 0, rows - 1);
    emit userScrolled(target == rows - 1);  // moving away from the newest frame pauses following
    ensureWindowAround(target);
    return window_->index(window_->fromSource(target), std::max(0, currentIndex().column()));
}

}  // namespace coscope::gui
