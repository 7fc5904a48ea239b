// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/trace/TimeBase.h"
#include "dissectors/HealthReport.h"

#include <QAbstractTableModel>

namespace coscope::gui {

// One table of the network health report: the findings, the per-node figures or the PDOs.
// setReport() keeps rows in place (rows added or removed at the end, the rest dataChanged), so
// a selection and the scroll position survive the refresh.
class HealthModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum class Table { Findings, Nodes, Pdos };
    enum FindingColumn { Severity, Time, Node, Text, FindingColumns };
    enum NodeColumn {
        NodeId,
        State,
        ErrorControl,
        Beats,
        Period,
        Late,
        Timeouts,
        BootUps,
        Resets,
        SdoTransfers,
        SdoP99,
        SdoAborts,
        SdoTimeouts,
        Emcys,
        NodeColumns
    };
    enum PdoColumn { CobId, Pdo, PdoNode, Frames, Rate, PdoPeriod, Jitter, PdoColumns };
    // Qt::UserRole on a finding row: its severity (HealthFinding::Severity); on a node row the node-ID.
    static constexpr int RawRole = Qt::UserRole;

    explicit HealthModel(Table table, QObject* parent = nullptr);

    void setReport(const dissect::HealthReport& report);
    // Relative seconds or the wall clock (Workspace::timeMode()) in the Time column.
    void setTimeMode(TimeBase::Mode mode);
    TimeBase timeBase() const { return {report_.startNs, timeMode_}; }
    const dissect::HealthReport& report() const { return report_; }

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    QVariant findingData(int row, int column, int role) const;
    QVariant nodeData(int row, int column, int role) const;
    QVariant pdoData(int row, int column, int role) const;
    int rowsOf(const dissect::HealthReport& r) const;

    Table table_;
    dissect::HealthReport report_;
    TimeBase::Mode timeMode_ = TimeBase::Mode::Relative;
};

}  // namespace coscope::gui
