// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/trace/TraceModel.h"

#include <QFontDatabase>

namespace coscope::gui {

TraceModel::TraceModel(QObject* parent) : QAbstractTableModel(parent) {}

void TraceModel::setStore(std::shared_ptr<const TraceStore> store) {
    beginResetModel();
    store_ = std::move(store);
    rows_ = 0;
    t0_ = 0;
    endResetModel();
    refresh();
}

void TraceModel::refresh() {
    if (!store_) return;
    const int n = static_cast<int>(std::min<size_t>(store_->size(), static_cast<size_t>(INT_MAX)));
    if (n <= rows_) return;
    if (rows_ == 0) t0_ = store_->record(0).timestampNs;
    beginInsertRows({}, rows_, n - 1);
    rows_ = n;
    endInsertRows();
}

int TraceModel::rowCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : rows_; }
int TraceModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant TraceModel::data(const QModelIndex& index, int role) const {
    if (!store_ || !index.isValid() || index.row() >= rows_) return {};
    const auto n = static_cast<FrameNo>(index.row());
    if (role == Qt::FontRole && (index.column() == CobId || index.column() == Data))
        return QFontDatabase::systemFont(QFontDatabase::FixedFont);
    if (role == Qt::TextAlignmentRole && index.column() <= Length && index.column() != Direction)
        return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
    if (role != Qt::DisplayRole) return {};
    const TraceRecord& r = store_->record(n);
    switch (index.column()) {
    case Number: return static_cast<qulonglong>(n) + 1;
    case Time: return QString::number(static_cast<double>(r.timestampNs - t0_) / 1e9, 'f', 6);
    case Bus: return r.bus;
    case CobId:
        return (r.flags & CanFrame::Extended) ? QStringLiteral("%1").arg(r.id, 8, 16, QLatin1Char('0')).toUpper()
                                              : QStringLiteral("%1").arg(r.id, 3, 16, QLatin1Char('0')).toUpper();
    case Direction: return (r.flags & CanFrame::Tx) ? QStringLiteral("Tx") : QStringLiteral("Rx");
    case Length: return r.len;
    case Data: {
        if (r.flags & CanFrame::Remote) return QStringLiteral("remote request");
        const auto p = store_->payload(n);
        return QByteArray(reinterpret_cast<const char*>(p.data()), static_cast<qsizetype>(p.size())).toHex(' ').toUpper();
    }
    default: return {};
    }
}

QVariant TraceModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    static const char* names[] = {"No.", "Time (s)", "Bus", "COB-ID", "Dir", "Len", "Data"};
    return section < ColumnCount ? QString::fromLatin1(names[section]) : QVariant();
}

}  // namespace coscope::gui
