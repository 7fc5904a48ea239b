// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/project/CompareModel.h"

#include "core/project/ProjectSoftware.h"

#include <QBrush>
#include <QColor>

namespace coscope::gui {

using project::NodeMatch;
using project::RowState;

CompareModel::CompareModel(QObject* parent) : QAbstractTableModel(parent) {}

QString CompareModel::matchText(NodeMatch m) {
    switch (m) {
    case NodeMatch::Same: return tr("same");
    case NodeMatch::Replaced: return tr("replaced (another serial number)");
    case NodeMatch::DifferentDevice: return tr("different device");
    case NodeMatch::Missing: return tr("missing");
    case NodeMatch::NotInProject: return tr("not in project");
    }
    return {};
}

QString CompareModel::stateText(RowState s) {
    switch (s) {
    case RowState::Same: return tr("same");
    case RowState::Differs: return tr("differs");
    case RowState::Unreadable: return tr("unreadable");
    }
    return {};
}

void CompareModel::setReport(const project::CompareReport& report) {
    beginResetModel();
    report_ = report;
    rebuild();
    endResetModel();
}

void CompareModel::setOnlyDifferences(bool only) {
    if (only == only_) return;
    beginResetModel();
    only_ = only;
    rebuild();
    endResetModel();
}

void CompareModel::rebuild() {
    rows_.clear();
    for (int n = 0; n < static_cast<int>(report_.nodes.size()); ++n) {
        const auto& node = report_.nodes[static_cast<size_t>(n)];
        if (node.match != NodeMatch::Same) rows_.push_back({n, -1});
        for (int r = 0; r < static_cast<int>(report_.rows.size()); ++r) {
            const auto& row = report_.rows[static_cast<size_t>(r)];
            if (row.node == node.node && (!only_ || row.state != RowState::Same)) rows_.push_back({-1, r});
        }
    }
}

uint8_t CompareModel::nodeAt(int row) const {
    if (row < 0 || row >= static_cast<int>(rows_.size())) return 0;
    const Row& r = rows_[static_cast<size_t>(row)];
    return r.node >= 0 ? report_.nodes[static_cast<size_t>(r.node)].node
                       : report_.rows[static_cast<size_t>(r.object)].node;
}

std::optional<NodeMatch> CompareModel::nodeMatchAt(int row) const {
    if (row < 0 || row >= static_cast<int>(rows_.size()) || rows_[static_cast<size_t>(row)].node < 0)
        return std::nullopt;
    return report_.nodes[static_cast<size_t>(rows_[static_cast<size_t>(row)].node)].match;
}

int CompareModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(rows_.size());
}
int CompareModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant CompareModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= static_cast<int>(rows_.size())) return {};
    const Row& r = rows_[static_cast<size_t>(index.row())];
    if (r.node >= 0) {
        const auto& n = report_.nodes[static_cast<size_t>(r.node)];
        if (role == Qt::BackgroundRole) return QBrush(QColor(0xF8, 0xD7, 0xD0));
        if (role != Qt::DisplayRole) return {};
        switch (index.column()) {
        case Node: return n.node;
        case Name: return n.name;
        case ProjectValue: return n.detail;
        case State: return matchText(n.match);
        default: return {};
        }
    }
    const auto& o = report_.rows[static_cast<size_t>(r.object)];
    if (role == Qt::BackgroundRole) {
        if (o.state == RowState::Differs) return QBrush(QColor(0xFD, 0xE2, 0xC8));
        if (o.state == RowState::Unreadable) return QBrush(QColor(0xEE, 0xEE, 0xEE));
        return {};
    }
    if (role == Qt::ToolTipRole) return o.error.isEmpty() ? QVariant() : QVariant(o.error);
    if (role != Qt::DisplayRole) return {};
    switch (index.column()) {
    case Node: return o.node;
    case Object: return project::objectKey(o.index, o.sub);
    case Name:
        // The node's program (CiA 302-3 §4 1F56h, CiA 301 100Ah) against the project's.
        if (project::isSoftwareRow(o))
            return o.index == 0x100A ? tr("Software version") : tr("Software identification");
        return o.name;
    case ProjectValue: return o.projectValue;
    case DriveValue: return o.state == RowState::Unreadable ? o.error : o.driveValue;
    case DefaultValue: return o.defaultValue;
    case State: return stateText(o.state);
    default: return {};
    }
}

QVariant CompareModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case Node: return tr("Node");
    case Object: return tr("Object");
    case Name: return tr("Name");
    case ProjectValue: return tr("Project");
    case DriveValue: return tr("Drive");
    case DefaultValue: return tr("Default");
    case State: return tr("State");
    default: return {};
    }
}

}  // namespace coscope::gui
