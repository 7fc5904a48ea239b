// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/health/HealthModel.h"

#include "app/gui/health/HealthRuleText.h"
#include "app/gui/language/CoreText.h"

#include "core/canopen/Nmt.h"
#include "dissectors/NetworkHealth.h"

#include <QBrush>
#include <QColor>

namespace coscope::gui {

HealthModel::HealthModel(Table table, QObject* parent) : QAbstractTableModel(parent), table_(table) {}

int HealthModel::rowsOf(const dissect::HealthReport& r) const {
    switch (table_) {
    case Table::Findings: return static_cast<int>(r.findings.size());
    case Table::Nodes: return static_cast<int>(r.nodes.size());
    case Table::Pdos: return static_cast<int>(r.pdos.size());
    }
    return 0;
}

void HealthModel::setReport(const dissect::HealthReport& report) {
    const int before = rowsOf(report_), after = rowsOf(report);
    if (after < before) {
        beginRemoveRows({}, after, before - 1);
        report_ = report;
        endRemoveRows();
    } else if (after > before) {
        beginInsertRows({}, before, after - 1);
        report_ = report;
        endInsertRows();
    } else {
        report_ = report;
    }
    if (after > 0) emit dataChanged(index(0, 0), index(after - 1, columnCount() - 1));
}

int HealthModel::rowCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : rowsOf(report_); }

int HealthModel::columnCount(const QModelIndex& parent) const {
    if (parent.isValid()) return 0;
    switch (table_) {
    case Table::Findings: return FindingColumns;
    case Table::Nodes: return NodeColumns;
    case Table::Pdos: return PdoColumns;
    }
    return 0;
}

QVariant HealthModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (table_) {
    case Table::Findings: {
        const QString names[] = {tr("Severity"), tr("Time"), tr("Node"), tr("Finding")};
        return section < FindingColumns ? names[section] : QVariant();
    }
    case Table::Nodes: {
        const QString names[] = {
            tr("Node"),       tr("State"),      tr("Error control"), tr("Beats"),  tr("Period min/avg/max ms"),
            tr("Late"),       tr("Timeouts"),   tr("Boot-ups"),      tr("Resets"), tr("SDO transfers"),
            tr("SDO p99 ms"), tr("SDO aborts"), tr("SDO timeouts"),  tr("EMCY")};
        return section < NodeColumns ? names[section] : QVariant();
    }
    case Table::Pdos: {
        const QString names[] = {tr("COB-ID"),   tr("PDO"),     tr("Node"),
                                 tr("Frames"),   tr("Rate Hz"), tr("Period min/avg/max ms"),
                                 tr("Jitter ms")};
        return section < PdoColumns ? names[section] : QVariant();
    }
    }
    return {};
}

QVariant HealthModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    switch (table_) {
    case Table::Findings: return findingData(index.row(), index.column(), role);
    case Table::Nodes: return nodeData(index.row(), index.column(), role);
    case Table::Pdos: return pdoData(index.row(), index.column(), role);
    }
    return {};
}

QVariant HealthModel::findingData(int row, int column, int role) const {
    const dissect::HealthFinding& f = report_.findings[static_cast<size_t>(row)];
    if (role == RawRole) return f.severity;
    if (role == Qt::ForegroundRole && column == Severity) {
        switch (f.severity) {
        case dissect::HealthFinding::Critical: return QBrush(QColor(0xb0, 0x00, 0x20));
        case dissect::HealthFinding::Error: return QBrush(QColor(0xc0, 0x39, 0x2b));
        case dissect::HealthFinding::Warning: return QBrush(QColor(0xb8, 0x86, 0x0b));
        default: return {};
        }
    }
    if (role == Qt::ToolTipRole)  // the rule's three sentences (issue 37)
        return QStringLiteral("%1\n%2 %3\n%4 %5")
            .arg(healthRuleText(f, RulePart::What), tr("Why:"), healthRuleText(f, RulePart::Why), tr("Check:"),
                 healthRuleText(f, RulePart::Check));
    if (role != Qt::DisplayRole) return {};
    switch (column) {
    case Severity:
        switch (f.severity) {
        case dissect::HealthFinding::Critical: return tr("Critical");
        case dissect::HealthFinding::Error: return tr("Error");
        case dissect::HealthFinding::Warning: return tr("Warning");
        default: return tr("Info");
        }
    case Time: return f.hasTime ? timeBase().shortText(f.timeNs) : QString();
    case Node: return f.node >= 0 ? QString::number(f.node) : tr("bus");
    // The headline built by dissectors/ in English, like the CLI report, shown in the UI language;
    // CoScope's own traffic by its rule's sentence (issue 37).
    case Text: return f.own ? healthRuleText(f, RulePart::What) : coreLines(f.text);
    }
    return {};
}

void HealthModel::setTimeMode(TimeBase::Mode mode) {
    if (mode == timeMode_) return;
    timeMode_ = mode;
    if (table_ == Table::Findings && rowCount() > 0) emit dataChanged(index(0, Time), index(rowCount() - 1, Time));
}

QVariant HealthModel::nodeData(int row, int column, int role) const {
    const dissect::NodeHealth& n = report_.nodes[static_cast<size_t>(row)];
    if (role == RawRole) return n.node;
    if (role == Qt::TextAlignmentRole)
        return column == State || column == ErrorControl ? QVariant() : QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole) return {};
    auto ms = [](double v) { return QString::number(v, 'f', v < 10 ? 1 : 0); };
    switch (column) {
    case NodeId: return n.node;
    case State: return n.state < 0 ? QString() : coreText(canopen::nmtStateName(static_cast<uint8_t>(n.state)));
    case ErrorControl:
        if (n.errorControl.isEmpty()) return tr("none");
        if (n.silentNow)
            return n.errorControl == QLatin1String("guarding") ? tr("guarding stopped") : tr("heartbeat stopped");
        return n.errorControl == QLatin1String("guarding") ? tr("guarding") : tr("heartbeat");
    case Beats: return QString::number(n.beats);
    case Period:
        return n.beats > 1 ? QStringLiteral("%1 / %2 / %3").arg(ms(n.periodMinMs), ms(n.periodAvgMs), ms(n.periodMaxMs))
                           : QString();
    case Late: return QString::number(n.late);
    case Timeouts: return QString::number(n.timeouts);
    case BootUps: return QString::number(n.bootUps);
    case Resets: return QString::number(n.resets);
    case SdoTransfers: return QString::number(n.sdoTransfers);
    case SdoP99: return n.sdoResponses ? QString::number(n.sdoRtP99Ms, 'f', 2) : QString();
    case SdoAborts: return QString::number(n.sdoAborted);
    case SdoTimeouts: return QString::number(n.sdoTimeouts);
    case Emcys: return QString::number(n.emcys - n.emcyResets);
    }
    return {};
}

QVariant HealthModel::pdoData(int row, int column, int role) const {
    const dissect::PdoHealth& p = report_.pdos[static_cast<size_t>(row)];
    if (role == Qt::TextAlignmentRole) return column == Pdo ? QVariant() : QVariant(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole) return {};
    switch (column) {
    case CobId: return QStringLiteral("%1h").arg(p.cobId, 3, 16, QLatin1Char('0')).toUpper().replace(u'H', u'h');
    case Pdo: return p.consumerSeen ? p.service : tr("%1 (no consumer)").arg(p.service);
    case PdoNode: return p.node;
    case Frames: return QString::number(p.frames);
    case Rate: return QString::number(p.rateHz, 'f', 1);
    case PdoPeriod:
        return p.frames > 1 ? QStringLiteral("%1 / %2 / %3")
                                  .arg(p.periodMinMs, 0, 'f', 2)
                                  .arg(p.periodAvgMs, 0, 'f', 2)
                                  .arg(p.periodMaxMs, 0, 'f', 2)
                            : QString();
    case Jitter: return p.cyclic ? QString::number(p.jitterMs, 'f', 3) : tr("event-driven");
    }
    return {};
}

}  // namespace coscope::gui
