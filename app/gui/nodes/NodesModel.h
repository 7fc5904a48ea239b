// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/canopen/NodeTable.h"

#include <QAbstractTableModel>

#include <functional>
#include <vector>

namespace coscope::gui {

// The node table as rows, one per node seen or scanned. refresh() takes a new snapshot when
// the table's revision moved and updates heartbeat ages.
class NodesModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        Node,
        State,
        StateSource,
        HeartbeatAge,
        ErrorControl,
        DeviceName,
        Dictionary,
        Emcy,
        Identity,
        SeenBy,
        ColumnCount
    };
    enum Role { NodeIdRole = Qt::UserRole + 1 };

    explicit NodesModel(QObject* parent = nullptr);

    void setTable(canopen::NodeTable* table);
    // The time heartbeat ages are measured against: now for live buses, the last frame offline.
    void setClock(std::function<int64_t()> now) { now_ = std::move(now); }
    void refresh();

    int nodeAt(int row) const { return nodes_[static_cast<size_t>(row)].node; }
    const canopen::NodeInfo& infoAt(int row) const { return nodes_[static_cast<size_t>(row)]; }
    int rowOfNode(int node) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    canopen::NodeTable* table_ = nullptr;
    std::function<int64_t()> now_;
    std::vector<canopen::NodeInfo> nodes_;
    uint64_t revision_ = ~uint64_t(0);
};

}  // namespace coscope::gui
