// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/trace/TraceModel.h"
#include "app/gui/language/CoreText.h"

#include "core/canopen/CobId.h"
#include "dissectors/NetworkContext.h"

#include <QBrush>
#include <QColor>
#include <QDateTime>
#include <QFontDatabase>

#include <algorithm>
#include <climits>

namespace coscope::gui {

namespace {
constexpr size_t kSummaryCacheLimit = 50000;                     // a few pages of rows, decoded at most once each
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
    groups_.reset();
    grouped_ = {};
    expanded_.clear();
    expandedRows_ = 0;
    expandedDirty_ = true;
    groupTexts_.clear();
    endResetModel();
    refresh();
}

void TraceModel::setDecoder(std::shared_ptr<const FrameDecoder> decoder) {
    decoder_ = decoder ? std::move(decoder) : defaultFrameDecoder();
    summaries_.clear();
    groupTexts_.clear();
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
    rows_ = isGrouped() ? static_cast<int>(std::min<size_t>(grouped_.top.size() + expandedRows_, INT_MAX)) : 0;
    expandedDirty_ = true;
    endResetModel();
    refresh();
}

void TraceModel::setFilter(const TraceFilter& filter, std::vector<FrameNo> rows, FrameNo scannedUpTo) {
    setView(filter, std::move(rows), scannedUpTo, nullptr, {});
}

void TraceModel::clearFilter() { setView(std::nullopt, {}, 0, nullptr, {}); }

void TraceModel::setView(std::optional<TraceFilter> filter, std::vector<FrameNo> rows, FrameNo scannedUpTo,
                         std::shared_ptr<SdoGroupIndex> groups, GroupedRows grouped) {
    filter_ = std::move(filter);
    filtered_ = std::move(rows);
    if (!filter_) filtered_.shrink_to_fit();
    scanned_ = filter_ || groups ? scannedUpTo : 0;
    groups_ = std::move(groups);
    grouped_ = std::move(grouped);
    expanded_.clear();
    expandedRows_ = 0;
    expandedDirty_ = true;
    groupTexts_.clear();
    resetRows();
}

void TraceModel::setGrouped(bool on) {
    if (!on) {
        if (filter_) setView(filter_, std::move(filtered_), scanned_, nullptr, {});
        else clearFilter();
        return;
    }
    if (!store_) return;
    const auto upTo = static_cast<FrameNo>(store_->size());
    std::vector<FrameNo> rows = std::move(filtered_);
    if (filter_ && scanned_ < upTo) {
        const auto more = runFilter(*store_, *filter_, *decoder_, scanned_, upTo);
        if (more) rows.insert(rows.end(), more->begin(), more->end());
    }
    auto index = std::make_shared<SdoGroupIndex>();
    index->scan(*store_, upTo);
    GroupedRows grouped;
    grouped.append(*index, filter_ ? &rows : nullptr, 0, upTo);
    setView(filter_, std::move(rows), upTo, std::move(index), std::move(grouped));
}

bool TraceModel::inSource(FrameNo n) const {
    return !filter_ || std::binary_search(filtered_.begin(), filtered_.end(), n);
}

size_t TraceModel::topIndexOfGroup(uint32_t group) const {
    const FrameNo key = grouped_.headerKey[group];
    const auto it = std::lower_bound(grouped_.top.begin(), grouped_.top.end(), key,
                                     [](uint64_t row, FrameNo k) { return GroupedRows::keyOf(row) < k; });
    return static_cast<size_t>(it - grouped_.top.begin());
}

void TraceModel::ensureExpandedAt() const {
    if (!expandedDirty_) return;
    expandedAt_.clear();
    for (const auto& [g, members] : expanded_) expandedAt_.push_back({topIndexOfGroup(g), g, members.size()});
    std::sort(expandedAt_.begin(), expandedAt_.end(),
              [](const ExpandedAt& a, const ExpandedAt& b) { return a.top < b.top; });
    expandedDirty_ = false;
}

// Visible row -> top row (+ member). Expanded groups are few (the user opens them one by one).
TraceModel::RowRef TraceModel::resolve(int row) const {
    ensureExpandedAt();
    size_t extra = 0;
    const auto r = static_cast<size_t>(row);
    for (const ExpandedAt& e : expandedAt_) {
        const size_t headerRow = e.top + extra;
        if (r <= headerRow) break;
        if (r <= headerRow + e.count) return {e.top, static_cast<int>(r - headerRow - 1)};
        extra += e.count;
    }
    return {r - extra, -1};
}

int TraceModel::visibleRow(size_t top) const {
    ensureExpandedAt();
    size_t extra = 0;
    for (const ExpandedAt& e : expandedAt_) {
        if (e.top >= top) break;
        extra += e.count;
    }
    return static_cast<int>(top + extra);
}

TraceModel::RowKind TraceModel::rowKind(int row) const {
    if (!isGrouped() || row < 0 || row >= rows_) return RowKind::Frame;
    const RowRef r = resolve(row);
    if (r.member >= 0) return RowKind::TransferFrame;
    return GroupedRows::groupOf(grouped_.top[r.top]) >= 0 ? RowKind::Transfer : RowKind::Frame;
}

int64_t TraceModel::groupAt(int row) const {
    if (!isGrouped() || row < 0 || row >= rows_) return -1;
    return GroupedRows::groupOf(grouped_.top[resolve(row).top]);
}

bool TraceModel::toggleExpanded(int row) {
    if (rowKind(row) != RowKind::Transfer) return false;
    const auto g = static_cast<uint32_t>(groupAt(row));
    const auto it = expanded_.find(g);
    if (it != expanded_.end()) {
        const int count = static_cast<int>(it->second.size());
        if (count > 0) beginRemoveRows({}, row + 1, row + count);
        expanded_.erase(it);
        expandedDirty_ = true;
        expandedRows_ -= static_cast<size_t>(count);
        rows_ -= count;
        if (count > 0) endRemoveRows();
    } else {
        std::vector<FrameNo> members;
        for (FrameNo n : groups_->frames(g))
            if (inSource(n)) members.push_back(n);
        const int count = static_cast<int>(members.size());
        if (count > 0) beginInsertRows({}, row + 1, row + count);
        expanded_.emplace(g, std::move(members));
        expandedDirty_ = true;
        expandedRows_ += static_cast<size_t>(count);
        rows_ += count;
        if (count > 0) endInsertRows();
    }
    emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
    return true;
}

dissect::SdoTransferRecord TraceModel::transferRecord(int64_t group) const {
    if (!groups_ || !store_ || group < 0 || static_cast<size_t>(group) >= groups_->size()) return {};
    return SdoGroupIndex::record(*store_, *groups_, static_cast<size_t>(group), *decoder_);
}

const TraceModel::GroupText& TraceModel::groupText(uint32_t group) const {
    const auto it = groupTexts_.find(group);
    if (it != groupTexts_.end()) return it->second;
    if (groupTexts_.size() >= kSummaryCacheLimit) groupTexts_.clear();
    return groupTexts_.emplace(group, SdoGroupIndex::rowText(transferRecord(group), groups_->group(group).count))
        .first->second;
}

// Live: frames [oldScanned, size) arrived (`newSource` = those the filter lets through).
void TraceModel::refreshGrouped(std::vector<FrameNo> newSource, FrameNo oldScanned) {
    const size_t oldGroups = groups_->size();
    groups_->scan(*store_, scanned_);
    if (grouped_.headerKey.size() < groups_->size()) grouped_.headerKey.resize(groups_->size(), SdoGroupIndex::kNone);
    auto keyLess = [](uint64_t row, FrameNo k) { return GroupedRows::keyOf(row) < k; };
    // Transfers completed now whose first frames were shown as plain rows: the first becomes
    // the header, the others go.
    for (size_t g = oldGroups; g < groups_->size(); ++g) {
        std::vector<FrameNo> shown;
        for (FrameNo n : groups_->frames(g))
            if (n < oldScanned && inSource(n)) shown.push_back(n);
        if (shown.empty()) continue;
        for (size_t i = shown.size(); i-- > 1;) {
            const auto it = std::lower_bound(grouped_.top.begin(), grouped_.top.end(), shown[i], keyLess);
            if (it == grouped_.top.end() || *it != GroupedRows::plain(shown[i])) continue;
            const size_t t = static_cast<size_t>(it - grouped_.top.begin());
            const int row = visibleRow(t);
            beginRemoveRows({}, row, row);
            grouped_.top.erase(it);
            expandedDirty_ = true;
            --rows_;
            endRemoveRows();
        }
        const auto it = std::lower_bound(grouped_.top.begin(), grouped_.top.end(), shown[0], keyLess);
        if (it == grouped_.top.end() || *it != GroupedRows::plain(shown[0])) continue;
        *it = GroupedRows::header(g, shown[0]);
        grouped_.headerKey[g] = shown[0];
        const int row = visibleRow(static_cast<size_t>(it - grouped_.top.begin()));
        emit dataChanged(index(row, 0), index(row, ColumnCount - 1));
    }
    const size_t before = grouped_.top.size();
    grouped_.append(*groups_, filter_ ? &newSource : nullptr, oldScanned, scanned_);
    const size_t added = grouped_.top.size() - before;
    if (added == 0) return;
    beginInsertRows({}, rows_, rows_ + static_cast<int>(added) - 1);
    rows_ += static_cast<int>(added);
    endInsertRows();
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
    if (loading_ && (store_->pageIns() != pageInsSeen_ ||
                     decoder_->readyCount() != decoderReadySeen_)) {  // rows drawn as loading may be back
        loading_ = false;
        if (rows_ > 0) emit dataChanged(index(0, 0), index(rows_ - 1, ColumnCount - 1));
    }
    if (decoder_->revision() != decoderRevision_) {  // dictionaries changed: decode again
        decoderRevision_ = decoder_->revision();
        summaries_.clear();
        groupTexts_.clear();
        if (rows_ > 0) emit dataChanged(index(0, Summary), index(rows_ - 1, Summary));
    }
    const size_t size = store_->size();
    if (size > 0 && !haveT0_) {  // frame 0 may be paged out (a view made late): once it is back
        const FrameNo first = 0;
        if (!requestPageIns(std::span<const FrameNo>(&first, 1))) {
            t0_ = store_->record(0).timestampNs;
            haveT0_ = true;
        }
    }
    switch (source()) {
    case Source::All: {
        if (groups_) {
            // The transfers are found in the new frames that are in RAM (pinned meanwhile);
            // the others once the store's loader has read them back.
            const FrameNo old = scanned_;
            const FrameNo upTo = pinResident(old, static_cast<FrameNo>(size));
            scanned_ = upTo;
            if (old < upTo) refreshGrouped({}, old);
            unpinResident(old, upTo);
            return;
        }
        const int n = static_cast<int>(std::min<size_t>(size, INT_MAX));
        if (n <= rows_) return;
        beginInsertRows({}, rows_, n - 1);
        rows_ = n;
        endInsertRows();
        return;
    }
    case Source::Filtered: {
        if (scanned_ < size) {
            // New frames since the filter ran: few per tick on a live bus, tested here when
            // they are in RAM (pinned meanwhile). Frames paged out to the journal (the filter
            // job ran long, the budget is small) are tested once the store's loader has read
            // them back: the GUI thread never waits for the disk (issue 16).
            const FrameNo old = scanned_;
            const FrameNo upTo = pinResident(old, static_cast<FrameNo>(size));
            auto more = runFilter(*store_, *filter_, *decoder_, old, upTo);
            if (more) filtered_.insert(filtered_.end(), more->begin(), more->end());
            scanned_ = upTo;
            if (groups_ && old < upTo) refreshGrouped(more ? std::move(*more) : std::vector<FrameNo>{}, old);
            unpinResident(old, upTo);
        }
        if (groups_) return;
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
        for (size_t i = 0; i < keys.size(); ++i)
            latestRows_[i] = store_->frameFor(keys[i], store_->countFor(keys[i]) - 1);
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

QString TraceModel::gapText(const TraceStore::Gap& g) {
    auto clock = [](int64_t ns) {
        return QDateTime::fromMSecsSinceEpoch(ns / 1'000'000).toString(QStringLiteral("HH:mm:ss.zzz"));
    };
    return tr("Bus lost at %1, back at %2 (%3 s without frames)")
        .arg(clock(g.lostNs), clock(g.backNs))
        .arg(double(g.backNs - g.lostNs) / 1e9, 0, 'f', 1);
}

QString TraceModel::gapsText(const std::vector<TraceStore::Gap>& gaps) {
    QStringList texts;
    for (const TraceStore::Gap& g : gaps) texts << gapText(g);
    return texts.join(QStringLiteral(" · "));
}

FrameNo TraceModel::frameAt(int row) const {
    if (isGrouped()) {
        const RowRef r = resolve(row);
        if (r.member >= 0)
            return expanded_.at(
                static_cast<uint32_t>(GroupedRows::groupOf(grouped_.top[r.top])))[static_cast<size_t>(r.member)];
        return GroupedRows::keyOf(grouped_.top[r.top]);
    }
    switch (source()) {
    case Source::All: return static_cast<FrameNo>(row);
    case Source::Filtered: return filtered_[static_cast<size_t>(row)];
    case Source::Latest: return latestRows_[static_cast<size_t>(row)];
    }
    return 0;
}

std::vector<FrameNo> TraceModel::shownFrames() const {
    std::vector<FrameNo> out;
    if (isGrouped()) {  // grouping hides no frame: the source's frames
        if (filter_) return filtered_;
        out.resize(scanned_);
        for (FrameNo n = 0; n < scanned_; ++n) out[n] = n;
        return out;
    }
    out.reserve(static_cast<size_t>(rows_));
    for (int r = 0; r < rows_; ++r) out.push_back(frameAt(r));
    if (source() == Source::Latest) std::sort(out.begin(), out.end());
    return out;
}

int TraceModel::rowAtOrAfter(FrameNo n) const {
    if (isGrouped()) {
        const auto end = grouped_.top.begin() + static_cast<std::ptrdiff_t>(grouped_.top.size());
        const auto it = std::lower_bound(grouped_.top.begin(), end, n,
                                         [](uint64_t row, FrameNo k) { return GroupedRows::keyOf(row) < k; });
        return it == end ? -1 : visibleRow(static_cast<size_t>(it - grouped_.top.begin()));
    }
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
    if (isGrouped()) {  // a frame of a transfer: its row under the expanded header, else the header
        const int64_t g = groups_->groupOf(n);
        if (g >= 0 && static_cast<size_t>(g) < grouped_.headerKey.size() &&
            grouped_.headerKey[static_cast<size_t>(g)] != SdoGroupIndex::kNone) {
            const int header = visibleRow(topIndexOfGroup(static_cast<uint32_t>(g)));
            const auto it = expanded_.find(static_cast<uint32_t>(g));
            if (it == expanded_.end()) return header;
            const auto m = std::find(it->second.begin(), it->second.end(), n);
            return m == it->second.end() ? header : header + 1 + static_cast<int>(m - it->second.begin());
        }
    }
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
    QString text = summaryText(scratch_);
    return summaries_.emplace(n, text).first->second;
}

QString TraceModel::timeText(FrameNo n, int row) const {
    const int64_t t = store_->record(n).timestampNs;
    switch (timeMode_) {
    case TimeMode::Absolute:
        if (t > kEpoch1990Ns) {
            const auto dt = QDateTime::fromMSecsSinceEpoch(t / 1'000'000);
            return dt.toString(QStringLiteral("HH:mm:ss.zzz")) +
                   QStringLiteral("%1").arg((t / 1000) % 1000, 3, 10, QLatin1Char('0'));
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
    const RowKind kind = rowKind(index.row());
    if (kind != RowKind::Frame) {
        switch (role) {
        case RowKindRole: return static_cast<int>(kind);
        case GroupRole: return static_cast<qlonglong>(groupAt(index.row()));
        case Qt::BackgroundRole:
            if (isBookmarked(n)) return QBrush(QColor(255, 236, 150));
            return QBrush(kind == RowKind::Transfer ? QColor(222, 234, 250) : QColor(240, 245, 252));
        default: break;
        }
    }
    if (kind == RowKind::Transfer) {
        const auto g = static_cast<uint32_t>(groupAt(index.row()));
        // Every role but the number reads its frames (the texts, the first frame's fields).
        if (col != Number && groupPagedOut(g)) {
            if (role == Qt::DisplayRole && col == Summary) return tr("loading…");
            return {};
        }
        if (role == Qt::ToolTipRole)
            return col == Number ? tr("Click to expand or collapse the transfer's frames") : groupText(g).summary;
        if (role == Qt::DisplayRole) {
            switch (col) {
            case Number:
                return (isExpanded(g) ? QStringLiteral("▾ ") : QStringLiteral("▸ ")) +
                       QString::number(qulonglong(n) + 1);
            case Service: return QStringLiteral("SDO");
            case Length: return groupText(g).size;
            case Data: return groupText(g).data;
            case Summary: return groupText(g).summary;
            case CobId: return QStringLiteral("%1").arg(store_->record(n).id, 3, 16, QLatin1Char('0')).toUpper();
            default: break;  // time, bus, node, direction: of its first frame
            }
        }
    }
    if (kind != RowKind::Transfer &&
        (role == Qt::DisplayRole || role == Qt::ToolTipRole || role == Qt::BackgroundRole ||
         role == Qt::ForegroundRole) &&
        pagedOut(n, index.row(), col)) {
        if (role != Qt::DisplayRole) return {};
        if (col == Number) return static_cast<qulonglong>(n) + 1;
        //: Trace row whose frame is being read back from the capture journal on disk
        if (col == Summary) return tr("loading…");
        return {};
    }
    if (kind == RowKind::TransferFrame && role == Qt::DisplayRole && col == Summary)
        return QStringLiteral("      ↳ ") + summaryOf(n);
    switch (role) {
    case RowKindRole: return static_cast<int>(RowKind::Frame);
    case GroupRole: return -1;
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
        if (!gapsBefore(n).empty()) return QBrush(QColor(200, 200, 215));
        if (store_->record(n).flags & CanFrame::Error) return QBrush(QColor(255, 205, 205));
        return {};
    case Qt::ForegroundRole:
        if (col == Direction && (store_->record(n).flags & CanFrame::Tx)) return QBrush(QColor(30, 90, 200));
        return {};
    case Qt::ToolTipRole:
        if (const auto gaps = gapsBefore(n); !gaps.empty()) return gapsText(gaps);
        if (col == Summary) return summaryOf(n);
        return {};
    case Qt::DisplayRole:
        if (col == Summary)
            if (const auto gaps = gapsBefore(n); !gaps.empty())
                return gapsText(gaps) + QStringLiteral(" · ") + summaryOf(n);
        break;
    default: return {};
    }
    const TraceRecord& r = store_->record(n);
    switch (col) {
    case Number: return static_cast<qulonglong>(n) + 1;
    case Time: return timeText(n, index.row());
    case Bus: return r.bus < busNames_.size() ? busNames_[r.bus] : QString::number(r.bus);
    case CobId: return cobIdText(r);
    case Node: {
        const auto info = canopen::classifyCobId(r.id, r.flags & (CanFrame::Extended | CanFrame::Error));
        return info.node >= 0 ? QVariant(info.node) : QVariant(QString());
    }
    case Service: {
        if (r.flags & CanFrame::Error) return QStringLiteral("ERROR");
        return canopen::serviceName(canopen::classifyCobId(r.id, r.flags & CanFrame::Extended).service);
    }
    case Direction:
        return (r.flags & CanFrame::Tx) ? QStringLiteral("Tx")
                                        : QStringLiteral("Rx");  // as in the CAN tools and manuals
    case Length: return r.len;
    case Data: return dataText(*store_, n);
    case Summary: return summaryOf(n);
    default: return {};
    }
}

QVariant TraceModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    if (section == Time) {
        switch (timeMode_) {
        case TimeMode::Absolute: return tr("Time");
        case TimeMode::Relative: return tr("Time (s)");
        //: Trace column: time since the previous frame, in seconds
        case TimeMode::Delta: return tr("Δt (s)");
        }
    }
    //: Trace columns: frame number, time, bus, COB-ID, node, CANopen service, direction (Rx/Tx), data length, data bytes, decoded summary
    static const char* const names[] = {
        QT_TR_NOOP("No."),     QT_TR_NOOP("Time"), QT_TR_NOOP("Bus"), QT_TR_NOOP("COB-ID"), QT_TR_NOOP("Node"),
        QT_TR_NOOP("Service"), QT_TR_NOOP("Dir"),  QT_TR_NOOP("Len"), QT_TR_NOOP("Data"),   QT_TR_NOOP("Summary")};
    return section >= 0 && section < ColumnCount ? tr(names[section]) : QVariant();
}

}  // namespace coscope::gui
