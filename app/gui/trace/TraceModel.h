// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/trace/TraceStore.h"

#include <QAbstractTableModel>

#include <memory>

namespace coscope::gui {

// Table model straight over the trace store: rows are frame numbers, nothing is copied.
// refresh() (called by a timer, ≤ 30 Hz) announces the rows appended since the last call.
class TraceModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Number, Time, Bus, CobId, Direction, Length, Data, ColumnCount };

    explicit TraceModel(QObject* parent = nullptr);

    void setStore(std::shared_ptr<const TraceStore> store);
    const std::shared_ptr<const TraceStore>& store() const { return store_; }
    void refresh();

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    std::shared_ptr<const TraceStore> store_;
    int rows_ = 0;
    int64_t t0_ = 0;
};

}  // namespace coscope::gui
