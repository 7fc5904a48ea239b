// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/trace/TraceModel.h"

#include "core/canopen/CobId.h"

#include <QBrush>
#include <QColor>
#include <QDateTime>
#include <QFontDatabase>

#include <algorithm>
#include <climits>

namespace coscope::gui {

namespace {
constexpr size_t kSummaryCacheLimit = 50000;  // a few pages of rows, decoded at most once each
constexpr int64_t kEpoch1990Ns = 631152000LL * 1'000'000'000LL;  // live/most logs: Unix time
}  // namespace

TraceModel::TraceModel(QObject* parent) : QAbstractTableModel(parent), decoder_(defaultFrameDecoder()) {}

void TraceModel::setStore(std::shared_ptr<const TraceStore> store) {
    beginResetModel();
    store_ = std::move(store);
    rows_ = 0;
    haveT0_ = false;
    filtered_.clear();
    scanned_ = 0;
    filter_.reset();
    latestRows_.clear();
    latestKeys_.clear();
    bookmarks_.clear();
    summaries_.clear();
    endResetModel();
    refresh();
}

void TraceModel::setDecoder(std::shared_ptr<const FrameDecoder> decoder) {
    decoder_ = decoder ? std::move(decoder) : defaultFrameDecoder();
    summaries_.clear();
    decoderRevision_ = decoder_->revision();
    if (rows_ > 0) emit dataChanged(index(0, Summary), index(rows_ - 1, Summary));
}

void TraceModel::setTimeMode(TimeMode mode) {
    if (mode == timeMode_) return;
    timeMode_ = mode;
    if (rows_ > 0) emit dataChanged(index(0, Time), index(rows_ - 1, Time));
    emit headerDataChanged(Qt::Horizontal, Time, Time);
}

TraceModel::Source TraceModel::source() const {
    if (latest_) return Source::Latest;
    return filter_ ? Source::Filtered : Source::All;
}

void TraceModel::resetRows() {
    beginResetModel();
    rows_ = 0;
    endResetModel();
    refresh();
}

void TraceModel::setFilter(const TraceFilter& filter, std::vector<FrameNo> rows, FrameNo scannedUpTo) {
    filter_ = filter;
    filtered_ = std::move(rows);
    scanned_ = scannedUpTo;
    resetRows();
}

void TraceModel::clearFilter() {
    filter_.reset();
    filtered_.clear();
    filtered_.shrink_to_fit();
    scanned_ = 0;
    resetRows();
}

void TraceModel::setLatestPerCobId(bool on) {
    if (on == latest_) return;
    latest_ = on;
    latestRows_.clear();
    latestKeys_.clear();
    resetRows();
}

void TraceModel::refresh() {
    if (!store_) return;
    if (decoder_->revision() != decoderRevision_) {  // dictionaries changed: decode again
        decoderRevision_ = decoder_->revision();
        summaries_.clear();
        if (rows_ > 0) emit dataChanged(index(0, Summary), index(rows_ - 1, Summary));
    }
    const size_t size = store_->size();
    if (size > 0 && !haveT0_) {
        t0_ = store_->record(0).timestampNs;
        haveT0_ = true;
    }
    switch (source()) {
    case Source::All: {
        const int n = static_cast<int>(std::min<size_t>(size, INT_MAX));
        if (n <= rows_) return;
        beginInsertRows({}, rows_, n - 1);
        rows_ = n;
        endInsertRows();
        return;
    }
    case Source::Filtered: {
        if (scanned_ < size) {
            // New frames since the filter ran: few per tick on a live bus, tested here.
            const auto more = runFilter(*store_, *filter_, *decoder_, scanned_, static_cast<FrameNo>(size));
            if (more) filtered_.insert(filtered_.end(), more->begin(), more->end());
            scanned_ = static_cast<FrameNo>(size);
        }
        const int n = static_cast<int>(std::min<size_t>(filtered_.size(), INT_MAX));
        if (n <= rows_) return;
        beginInsertRows({}, rows_, n - 1);
        rows_ = n;
        endInsertRows();
        return;
    }
    case Source::Latest: refreshLatest(); return;
    }
}

void TraceModel::refreshLatest() {
    const auto keys = store_->keys();
    if (keys.size() != latestKeys_.size()) {
        // A new COB-ID appeared: rebuild (rare; the list is short).
        beginResetModel();
        latestKeys_ = keys;
        latestRows_.assign(keys.size(), 0);
        for (size_t i = 0; i < keys.size(); ++i) latestRows_[i] = store_->frameFor(keys[i], store_->countFor(keys[i]) - 1);
        rows_ = static_cast<int>(latestRows_.size());
        endResetModel();
        return;
    }
    int firstChanged = -1, lastChanged = -1;
    for (size_t i = 0; i < latestKeys_.size(); ++i) {
        const FrameNo last = store_->frameFor(latestKeys_[i], store_->countFor(latestKeys_[i]) - 1);
        if (last != latestRows_[i]) {
            latestRows_[i] = last;
            if (firstChanged < 0) firstChanged = static_cast<int>(i);
            lastChanged = static_cast<int>(i);
        }
    }
    if (firstChanged >= 0) emit dataChanged(index(firstChanged, 0), index(lastChanged, ColumnCount - 1));
}

FrameNo TraceModel::frameAt(int row) const {
    switch (source()) {
    case Source::All: return static_cast<FrameNo>(row);
    case Source::Filtered: return filtered_[static_cast<size_t>(row)];
    case Source::Latest: return latestRows_[static_cast<size_t>(row)];
    }
    return 0;
}

int TraceModel::rowAtOrAfter(FrameNo n) const {
    switch (source()) {
    case Source::All: return static_cast<int>(n) < rows_ ? static_cast<int>(n) : -1;
    case Source::Filtered: {
        const auto end = filtered_.begin() + rows_;
        const auto it = std::lower_bound(filtered_.begin(), end, n);
        return it == end ? -1 : static_cast<int>(it - filtered_.begin());
    }
    case Source::Latest: {
        const auto it = std::find(latestRows_.begin(), latestRows_.end(), n);
        return it == latestRows_.end() ? -1 : static_cast<int>(it - latestRows_.begin());
    }
    }
    return -1;
}

int TraceModel::rowOf(FrameNo n) const {
    const int row = rowAtOrAfter(n);
    return row >= 0 && frameAt(row) == n ? row : -1;
}

void TraceModel::toggleBookmark(FrameNo n) {
    if (!bookmarks_.erase(n)) bookmarks_.insert(n);
    const int row = rowOf(n);
    if (row >= 0) emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
}

QString TraceModel::summaryOf(FrameNo n) const {
    if (!store_ || n >= store_->size()) return {};
    const auto it = summaries_.find(n);
    if (it != summaries_.end()) return it->second;
    if (summaries_.size() >= kSummaryCacheLimit) summaries_.clear();
    scratch_.reset(dissect::Dissection::Level::Flat);
    decoder_->decodeAt(*store_, n, scratch_);
    QString text = scratch_.summary;
    if (!scratch_.warnings.isEmpty()) text += QStringLiteral("  ⚠ ") + scratch_.warnings.join(QStringLiteral("; "));
    return summaries_.emplace(n, text).first->second;
}

QString TraceModel::timeText(FrameNo n, int row) const {
    const int64_t t = store_->record(n).timestampNs;
    switch (timeMode_) {
    case TimeMode::Absolute:
        if (t > kEpoch1990Ns) {
            const auto dt = QDateTime::fromMSecsSinceEpoch(t / 1'000'000);
            return dt.toString(QStringLiteral("HH:mm:ss.zzz")) + QStringLiteral("%1").arg((t / 1000) % 1000, 3, 10, QLatin1Char('0'));
        }
        return QString::number(static_cast<double>(t) / 1e9, 'f', 6);
    case TimeMode::Relative: return QString::number(static_cast<double>(t - t0_) / 1e9, 'f', 6);
    case TimeMode::Delta: {
        if (row <= 0) return QStringLiteral("0.000000");
        const int64_t prev = store_->record(frameAt(row - 1)).timestampNs;
        return QString::number(static_cast<double>(t - prev) / 1e9, 'f', 6);
    }
    }
    return {};
}

int TraceModel::rowCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : rows_; }
int TraceModel::columnCount(const QModelIndex& parent) const { return parent.isValid() ? 0 : ColumnCount; }

QVariant TraceModel::data(const QModelIndex& index, int role) const {
    if (!store_ || !index.isValid() || index.row() >= rows_) return {};
    const FrameNo n = frameAt(index.row());
    const int col = index.column();
    switch (role) {
    case FrameRole: return static_cast<qulonglong>(n);
    case BookmarkRole: return isBookmarked(n);
    case Qt::FontRole:
        if (col == CobId || col == Data) return QFontDatabase::systemFont(QFontDatabase::FixedFont);
        return {};
    case Qt::TextAlignmentRole:
        if (col == Number || col == Time || col == Length || col == Node || col == CobId || col == Bus)
            return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
        return {};
    case Qt::BackgroundRole:
        if (isBookmarked(n)) return QBrush(QColor(255, 236, 150));
        if (store_->record(n).flags & CanFrame::Error) return QBrush(QColor(255, 205, 205));
        return {};
    case Qt::ForegroundRole:
        if (col == Direction && (store_->record(n).flags & CanFrame::Tx)) return QBrush(QColor(30, 90, 200));
        return {};
    case Qt::ToolTipRole:
        if (col == Summary) return summaryOf(n);
        return {};
    case Qt::DisplayRole: break;
    default: return {};
    }
    const TraceRecord& r = store_->record(n);
    switch (col) {
    case Number: return static_cast<qulonglong>(n) + 1;
    case Time: return timeText(n, index.row());
    case Bus: return r.bus < busNames_.size() ? busNames_[r.bus] : QString::number(r.bus);
    case CobId:
        if (r.flags & CanFrame::Error) return QStringLiteral("ERR");
        return (r.flags & CanFrame::Extended) ? QStringLiteral("%1").arg(r.id, 8, 16, QLatin1Char('0')).toUpper()
                                              : QStringLiteral("%1").arg(r.id, 3, 16, QLatin1Char('0')).toUpper();
    case Node: {
        const auto info = canopen::classifyCobId(r.id, r.flags & (CanFrame::Extended | CanFrame::Error));
        return info.node >= 0 ? QVariant(info.node) : QVariant(QString());
    }
    case Service: {
        if (r.flags & CanFrame::Error) return QStringLiteral("ERROR");
        return canopen::serviceName(canopen::classifyCobId(r.id, r.flags & CanFrame::Extended).service);
    }
    case Direction: return (r.flags & CanFrame::Tx) ? QStringLiteral("Tx") : QStringLiteral("Rx");
    case Length: return r.len;
    case Data: {
        if (r.flags & CanFrame::Remote) return QStringLiteral("RTR");
        const auto p = store_->payload(n);
        return QString::fromLatin1(QByteArray(reinterpret_cast<const char*>(p.data()), static_cast<qsizetype>(p.size())).toHex(' ').toUpper());
    }
    case Summary: return summaryOf(n);
    default: return {};
    }
}

QVariant TraceModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    if (section == Time) {
        switch (timeMode_) {
        case TimeMode::Absolute: return QStringLiteral("Time");
        case TimeMode::Relative: return QStringLiteral("Time (s)");
        case TimeMode::Delta: return QStringLiteral("Δt (s)");
        }
    }
    static const char* const names[] = {"No.", "Time", "Bus", "COB-ID", "Node", "Service", "Dir", "Len", "Data", "Summary"};
    return section >= 0 && section < ColumnCount ? QString::fromLatin1(names[section]) : QVariant();
}

}  // namespace coscope::gui
