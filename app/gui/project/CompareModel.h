// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/project/ProjectCompare.h"

#include <QAbstractTableModel>

namespace coscope::gui {

// The comparison of the machine with the project as a table: a row per node that is not as in the
// project (replaced, missing, ...), then a row per configured object. "Only differences" hides the
// objects and nodes that are the same.
class CompareModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Node, Object, Name, ProjectValue, DriveValue, DefaultValue, State, ColumnCount };
    explicit CompareModel(QObject* parent = nullptr);

    void setReport(const project::CompareReport& report);
    const project::CompareReport& report() const { return report_; }
    void setOnlyDifferences(bool only);
    bool onlyDifferences() const { return only_; }

    // The node of a row, and its state when the row is a node's ("replaced"...; nullopt for objects).
    uint8_t nodeAt(int row) const;
    std::optional<project::NodeMatch> nodeMatchAt(int row) const;

    static QString matchText(project::NodeMatch m);
    static QString stateText(project::RowState s);

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    void rebuild();
    struct Row {
        int node = -1;    // index into report_.nodes for a node row
        int object = -1;  // index into report_.rows for an object row
    };
    project::CompareReport report_;
    std::vector<Row> rows_;
    bool only_ = true;
};

}  // namespace coscope::gui
