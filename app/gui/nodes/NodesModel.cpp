// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/nodes/NodesModel.h"

#include "app/gui/language/CoreText.h"

#include "core/canopen/Nmt.h"

#include <QBrush>
#include <QColor>
#include <QFont>

namespace coscope::gui {

namespace {

// Where the node's NMT state comes from, short (the "State from" column).
QString sourceText(const canopen::NodeInfo& n) {
    using canopen::NmtSource;
    const QString command = coreText(canopen::nmtCommandName(n.nmtCommand));
    switch (n.nmtSource) {
    case NmtSource::BootUp: return NodesModel::tr("boot-up");
    case NmtSource::Heartbeat: return NodesModel::tr("heartbeat");
    case NmtSource::Guarding: return NodesModel::tr("node guarding");
    case NmtSource::OurCommand: return NodesModel::tr("after our NMT %1 (not confirmed)").arg(command);
    case NmtSource::OtherCommand: return NodesModel::tr("after NMT %1 by another master (not confirmed)").arg(command);
    case NmtSource::Pdo: return NodesModel::tr("its PDOs");
    case NmtSource::Sdo: return NodesModel::tr("its SDO answers");
    case NmtSource::Emcy: return NodesModel::tr("its EMCY");
    case NmtSource::Unknown: break;
    }
    return {};
}

// The same as a sentence (tooltip of the state and its source), with the rule it rests on.
QString sourceExplained(const canopen::NodeInfo& n) {
    using canopen::NmtSource;
    const QString command = coreText(canopen::nmtCommandName(n.nmtCommand));
    switch (n.nmtSource) {
    case NmtSource::BootUp:
        return NodesModel::tr("The node sent its boot-up message; after boot-up a node is Pre-operational.");
    case NmtSource::Heartbeat: return NodesModel::tr("The node's heartbeat says so.");
    case NmtSource::Guarding: return NodesModel::tr("The node's answer to node guarding says so.");
    case NmtSource::OurCommand:
        return NodesModel::tr(
                   "CoScope sent NMT %1; the node has not confirmed it yet (no heartbeat, and no frame of its own that "
                   "shows its state).")
            .arg(command);
    case NmtSource::OtherCommand:
        return NodesModel::tr(
                   "Another master sent NMT %1; the node has not confirmed it yet (no heartbeat, and no frame of its "
                   "own that shows its state).")
            .arg(command);
    case NmtSource::Pdo: return NodesModel::tr("The node sends PDOs, which CiA 301 allows only in Operational.");
    case NmtSource::Sdo:
        return NodesModel::tr(
            "The node answers SDO, which CiA 301 allows only in Pre-operational and Operational (its PDOs would show "
            "Operational).");
    case NmtSource::Emcy:
        return NodesModel::tr(
            "The node sends EMCY, which CiA 301 allows only in Pre-operational and Operational (its PDOs would show "
            "Operational).");
    case NmtSource::Unknown: break;
    }
    return NodesModel::tr("Nothing seen yet shows the node's state.");
}

// CoScope's watch over the node (HeartbeatMonitor): "heartbeat 300 ms: ok, 0.1 s ago".
QString watchText(const canopen::NodeInfo& n, int64_t now) {
    using Status = canopen::ErrorControlWatch::Status;
    const canopen::ErrorControlWatch& w = n.watch;
    if (w.status == Status::Off) return {};
    const QString what = w.guarding() ? NodesModel::tr("guarding %1 ms × %2").arg(w.guardTimeMs).arg(w.lifeTimeFactor)
                                      : NodesModel::tr("heartbeat %1 ms").arg(w.consumerTimeMs);
    QString status;
    switch (w.status) {
    case Status::Waiting: status = NodesModel::tr("waiting"); break;
    case Status::Ok: status = NodesModel::tr("ok"); break;
    case Status::Late: status = NodesModel::tr("late"); break;
    case Status::Lost: status = NodesModel::tr("lost"); break;
    case Status::Off: break;
    }
    if (w.lastNs)
        status = NodesModel::tr("%1, %2 s ago")
                     .arg(status)
                     .arg(double(std::max<int64_t>(0, now - w.lastNs)) / 1e9, 0, 'f', 1);
    return NodesModel::tr("%1: %2").arg(what, status);
}

QString watchExplained(const canopen::NodeInfo& n) {
    const canopen::ErrorControlWatch& w = n.watch;
    if (w.status == canopen::ErrorControlWatch::Status::Off)
        return NodesModel::tr("Not watched by CoScope (Heartbeat and guarding… in the context menu)");
    if (w.guarding())
        return NodesModel::tr(
                   "Node guarding (CiA 301): CoScope asks every %1 ms; the node is late when a request goes unanswered "
                   "or the toggle bit is "
                   "wrong, lost after %2 ms without a right answer. Guarding errors: %3, lost %4 time(s).")
            .arg(w.guardTimeMs)
            .arg(w.guardTimeMs * w.lifeTimeFactor)
            .arg(n.guardingErrors)
            .arg(w.lost);
    return NodesModel::tr(
               "Heartbeat consumer (CiA 301): late when a heartbeat is overdue, lost when none comes within %1 ms. "
               "Lost %2 time(s).")
        .arg(w.consumerTimeMs)
        .arg(w.lost);
}

}  // namespace

NodesModel::NodesModel(QObject* parent) : QAbstractTableModel(parent) {}

void NodesModel::setTable(canopen::NodeTable* table) {
    beginResetModel();
    table_ = table;
    nodes_.clear();
    revision_ = ~uint64_t(0);
    endResetModel();
    refresh();
}

void NodesModel::refresh() {
    if (!table_) return;
    if (table_->revision() != revision_) {
        revision_ = table_->revision();
        auto fresh = table_->snapshot();
        if (fresh.size() != nodes_.size()) {
            beginResetModel();  // nodes appear rarely; a reset keeps this simple
            nodes_ = std::move(fresh);
            endResetModel();
            return;
        }
        nodes_ = std::move(fresh);
    }
    if (!nodes_.empty()) emit dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
}

int NodesModel::rowOfNode(int node) const {
    for (size_t i = 0; i < nodes_.size(); ++i)
        if (nodes_[i].node == node) return static_cast<int>(i);
    return -1;
}

int NodesModel::rowCount(const QModelIndex& parent) const {
    return parent.isValid() ? 0 : static_cast<int>(nodes_.size());
}
int NodesModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant NodesModel::data(const QModelIndex& index, int role) const {
    if (!index.isValid() || index.row() >= rowCount()) return {};
    const canopen::NodeInfo& n = nodes_[static_cast<size_t>(index.row())];
    const int64_t now = now_ ? now_() : n.lastSeenNs;
    const bool late = n.seenHeartbeat && n.heartbeatPeriodNs > 0 &&
                      now - n.lastHeartbeatNs > std::max<int64_t>(3 * n.heartbeatPeriodNs, 1'500'000'000);
    if (role == NodeIdRole) return n.node;
    if (role == Qt::BackgroundRole && index.column() == State) {
        if (n.stateUnknownAfterGap) return QBrush(QColor(200, 200, 215));
        if (late) return QBrush(QColor(255, 205, 205));
        switch (n.nmtState) {
        case 0x05: return QBrush(QColor(200, 240, 200));
        case 0x7F: return QBrush(QColor(255, 243, 196));
        case 0x04: return QBrush(QColor(225, 225, 225));
        default: return {};
        }
    }
    if (role == Qt::FontRole && (index.column() == State || index.column() == StateSource) &&
        (n.nmtSource == canopen::NmtSource::OurCommand || n.nmtSource == canopen::NmtSource::OtherCommand)) {
        QFont italic;  // told, not confirmed by the node
        italic.setItalic(true);
        return italic;
    }
    if (role == Qt::BackgroundRole && index.column() == ErrorControl) {
        using Status = canopen::ErrorControlWatch::Status;
        switch (n.watch.status) {
        case Status::Ok: return QBrush(QColor(200, 240, 200));
        case Status::Late: return QBrush(QColor(255, 225, 170));
        case Status::Lost: return QBrush(QColor(255, 205, 205));
        default: return {};
        }
    }
    if (role == Qt::ForegroundRole && index.column() == Emcy && n.emcyCount) return QBrush(QColor(176, 0, 32));
    if (role == Qt::TextAlignmentRole &&
        (index.column() == Node || index.column() == HeartbeatAge || index.column() == Emcy))
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole && role != Qt::ToolTipRole) return {};
    switch (index.column()) {
    case Node: return n.node;
    case State:
        if (n.stateUnknownAfterGap) {  // issue 16: the bus was lost; the last state may be stale
            const QString last =
                n.nmtState < 0 ? tr("Unknown") : coreText(canopen::nmtStateName(static_cast<uint8_t>(n.nmtState)));
            return role == Qt::ToolTipRole ? tr("The bus was lost: the state is unknown until the node's heartbeat or "
                                                "its own frames show it (last known: %1)")
                                                 .arg(last)
                                           : tr("unknown (gap)");
        }
        if (late) return tr("No heartbeat");
        if (role == Qt::ToolTipRole) return sourceExplained(n);
        return n.nmtState < 0 ? tr("Unknown") : coreText(canopen::nmtStateName(static_cast<uint8_t>(n.nmtState)));
    case StateSource:
        if (role == Qt::ToolTipRole) return sourceExplained(n);
        return n.stateUnknownAfterGap ? QString() : sourceText(n);
    case HeartbeatAge:
        if (!n.seenHeartbeat) return tr("—");
        return QStringLiteral("%1 s").arg(double(std::max<int64_t>(0, now - n.lastHeartbeatNs)) / 1e9, 0, 'f', 1);
    case ErrorControl: return role == Qt::ToolTipRole ? watchExplained(n) : watchText(n, now);
    case DeviceName: {
        const QString name = n.notPresent & canopen::NodeInfo::kNoDeviceName ? tr("not present") : n.deviceName;
        if (role == Qt::DisplayRole) return name;
        // Tooltip: the three optional texts of CiA 301 §7.5.2.9-11 as the scan found them.
        auto text = [&](const QString& v, uint8_t bit) {
            return n.notPresent & bit ? tr("not present") : v.isEmpty() ? tr("—") : v;
        };
        return tr("Device name (1008h): %1\nHardware version (1009h): %2\nSoftware version (100Ah): %3")
            .arg(text(n.deviceName, canopen::NodeInfo::kNoDeviceName),
                 text(n.hardwareVersion.value_or(QString()), canopen::NodeInfo::kNoHardwareVersion),
                 text(n.softwareVersion.value_or(QString()), canopen::NodeInfo::kNoSoftwareVersion));
    }
    case Identity: {
        if (!n.vendorId) return n.identityRead ? tr("not present") : QString();
        auto hex8 = [](uint32_t v) { return QString::number(v, 16).toUpper().rightJustified(8, u'0'); };
        QString s = tr("vendor %1").arg(hex8(*n.vendorId));
        // 1018h sub 2-4 are optional (CiA 301 §7.5.2.21).
        s += n.productCode ? tr(", product %1").arg(hex8(*n.productCode)) : tr(", product not present");
        s += n.revision ? tr(", rev %1").arg(hex8(*n.revision)) : tr(", rev not present");
        s += n.serial ? tr(", s/n %1").arg(*n.serial) : tr(", s/n not present");
        return s;
    }
    case Dictionary: return n.dictionary.isEmpty() ? tr("(none)") : n.dictionary;
    case Emcy: return n.emcyCount;
    case SeenBy: {
        QStringList by;
        if (n.seenBootUp) by << tr("boot-up");
        if (n.seenHeartbeat) by << tr("heartbeat");
        if (n.seenEmcy) by << QStringLiteral("EMCY");
        if (n.seenSdo) by << QStringLiteral("SDO");
        if (n.scanned) by << tr("scan");
        return by.join(QStringLiteral(", "));
    }
    default: return {};
    }
}

QVariant NodesModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
    case Node: return tr("Node");
    case State: return tr("NMT state");
    case StateSource: return tr("State from");
    case HeartbeatAge: return tr("Heartbeat age");
    case ErrorControl: return tr("Heartbeat / guarding");
    case DeviceName: return tr("Device name");
    case Identity: return tr("Identity (1018h)");
    case Dictionary: return tr("Dictionary");
    case Emcy: return tr("EMCY");
    case SeenBy: return tr("Seen by");
    default: return {};
    }
}

}  // namespace coscope::gui
