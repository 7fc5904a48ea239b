// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QAbstractTableModel>

namespace coscope::gui {

class TraceModel;

// A sliding window over the trace model's rows, the model the trace's table view shows (issue 16
// "Bounded memory"): Qt's views keep a few bytes per row (header sections, geometry), so a view
// over every frame grows with the capture however little of it the trace store keeps in RAM.
// The window holds at most about capacity() rows, [base(), base() + rowCount()) of the trace
// model; the view (TraceView) moves it with moveTo() as the user scrolls, and a scroll bar of its
// own spans the whole trace. Rows appended while the window is at the end of the trace join it
// until it holds capacity() * 3 / 2 rows; changes to the trace model's rows inside the window
// (filter, grouped transfers opening and closing) are passed on as row changes, elsewhere they
// only shift base().
class TraceWindow : public QAbstractTableModel {
    Q_OBJECT
public:
    explicit TraceWindow(TraceModel* source, QObject* parent = nullptr);

    // Rows of the window: the setting trace/windowRows, else kDefaultRows.
    static constexpr int kDefaultRows = 50000;
    static int configuredRows();

    TraceModel* source() const { return source_; }
    int capacity() const { return capacity_; }
    int maxRows() const { return capacity_ + capacity_ / 2; }
    int base() const { return base_; }
    int total() const;  // rows of the trace model
    bool atEnd() const { return base_ + count_ >= total(); }
    // The trace model row of window row `row`, and back (-1 outside the window).
    int toSource(int row) const { return base_ + row; }
    int fromSource(int sourceRow) const {
        return sourceRow >= base_ && sourceRow < base_ + count_ ? sourceRow - base_ : -1;
    }

    // Shows trace model rows [first, first + capacity()) (clamped to the trace): a model reset.
    void moveTo(int first);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;
    Qt::ItemFlags flags(const QModelIndex& index) const override;

private:
    void onAboutToInsert(int first, int last);
    void onInserted();
    void onAboutToRemove(int first, int last);
    void onRemoved();
    void onDataChanged(const QModelIndex& topLeft, const QModelIndex& bottomRight, const QList<int>& roles);

    TraceModel* source_;
    int capacity_;
    int base_ = 0;
    int count_ = 0;
    // A row change of the trace model between its "about to" and its "done" signals.
    struct Pending {
        int shift = 0;  // rows added (+) or taken (-) before the window
        int rows = 0;   // rows added (+) or taken (-) inside it
    } pending_;
};

}  // namespace coscope::gui
