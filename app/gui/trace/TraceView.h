// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QPersistentModelIndex>
#include <QTableView>

#include <utility>

class QScrollBar;

namespace coscope::gui {

class TraceModel;
class TraceWindow;

// The trace's table: a QTableView over a TraceWindow (a window of the trace model's rows, so
// what Qt keeps per row stays bounded however long the capture runs) with a scroll bar of its own
// that spans the whole trace. Scrolling (wheel, that bar) and the keys (arrows, PgUp/PgDn,
// Home/End) move the window when they come near its edge; the current row stays on its frame.
// Rows in this class's API are rows of the trace model ("logical" rows), not of the window.
class TraceView : public QTableView {
    Q_OBJECT
public:
    explicit TraceView(TraceModel* model, QWidget* parent = nullptr);

    TraceModel* traceModel() const { return source_; }
    TraceWindow* traceWindow() const { return window_; }
    // The bar spanning the whole trace; the dock lays it out to the right of the view.
    QScrollBar* traceScrollBar() const { return bar_; }

    int logicalRow(const QModelIndex& index) const;  // -1 for an invalid index
    // The current row (kept while the window has moved away from it), -1 when none.
    int currentRow() const;
    // Makes `row` current; `center` scrolls it to the middle, else just into view.
    void setCurrentRow(int row, bool center);
    void scrollToEnd();    // the newest row at the bottom (following a live capture)
    void scrollToStart();  // the first row at the top
    // The logical rows in the viewport now: [first, last] (last may be past the end).
    std::pair<int, int> visibleRows() const { return {topRow(), topRow() + pageRows()}; }

signals:
    // The user scrolled (wheel, scroll bar); `atEnd`: the last row is in view.
    void userScrolled(bool atEnd);

protected:
    QModelIndex moveCursor(CursorAction action, Qt::KeyboardModifiers modifiers) override;
    void updateGeometries() override;
    void currentChanged(const QModelIndex& current, const QModelIndex& previous) override;

private:
    int pageRows() const;
    int topRow() const;  // logical row at the top of the viewport
    // Moves the window to start at `first`, keeping logical row `top` at the top of the view.
    void moveWindow(int first, int top);
    // Makes sure logical rows [top, top + page) are in the window, away from its edges.
    void ensureWindowAround(int row);
    void onInnerScrolled(int value);
    void onBarMoved(int top);
    void syncBar();

    TraceModel* source_;
    TraceWindow* window_;
    QScrollBar* bar_;
    QPersistentModelIndex current_;  // in the trace model
    bool syncing_ = false;
};

}  // namespace coscope::gui
