// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/trace/FrameDecoder.h"
#include "app/gui/trace/SdoGroups.h"
#include "app/gui/trace/TraceFilter.h"
#include "app/gui/trace/TraceFind.h"
#include "core/trace/TraceStore.h"

#include <QAbstractTableModel>
#include <QStringList>

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <unordered_map>
#include <vector>

namespace coscope::gui {

// Table model straight over the trace store: rows are frame numbers, nothing is copied.
// Three row sources: every frame; the frames of a filter (a list computed off-thread, then
// extended as frames arrive); or the latest frame of each COB-ID (from the store's index).
// refresh() — called by a timer at most 30 times a second — announces what changed since the
// last call. The summary column is decoded lazily for the rows the view asks about, and cached.
//
// Grouped view (All or Filtered frames, setView() with an SdoGroupIndex): each reassembled SDO
// transfer is one row (its header: first frame's time, node, service SDO, summary = the transfer
// record) standing where its first shown frame would be; expanding it inserts its frames (those
// the filter lets through) as rows under it. Rows = GroupedRows::top plus the members of the
// expanded groups. refresh() continues the index with the frames that arrived: a transfer
// completed meanwhile turns its frames already shown into its header row (row updates, no reset).
class TraceModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column { Number, Time, Bus, CobId, Node, Service, Direction, Length, Data, Summary, ColumnCount };
    enum class TimeMode { Absolute, Relative, Delta };
    enum Role { FrameRole = Qt::UserRole + 1, BookmarkRole, RowKindRole, GroupRole };
    enum class RowKind { Frame, Transfer, TransferFrame };  // a frame, a transfer's header, a frame under it

    explicit TraceModel(QObject* parent = nullptr);

    void setStore(std::shared_ptr<const TraceStore> store);
    const std::shared_ptr<const TraceStore>& store() const { return store_; }
    void setDecoder(std::shared_ptr<const FrameDecoder> decoder);
    const std::shared_ptr<const FrameDecoder>& decoder() const { return decoder_; }
    void setBusNames(const QStringList& names) { busNames_ = names; }

    void setTimeMode(TimeMode mode);
    TimeMode timeMode() const { return timeMode_; }

    // Shows the frames of `filter`: `rows` are the matches in [0, scannedUpTo); later frames are
    // tested as they arrive.
    void setFilter(const TraceFilter& filter, std::vector<FrameNo> rows, FrameNo scannedUpTo);
    void clearFilter();
    bool isFiltered() const { return filter_.has_value(); }
    // Frames of `filter` (none: all frames) with SDO transfers grouped: `rows` as above, `groups`
    // scanned up to `scannedUpTo`, `grouped` built from both (see FilterJob, which computes them).
    void setView(std::optional<TraceFilter> filter, std::vector<FrameNo> rows, FrameNo scannedUpTo,
                 std::shared_ptr<SdoGroupIndex> groups, GroupedRows grouped);
    // Same, computed on the calling thread (small traces, tests).
    void setGrouped(bool on);
    bool isGrouped() const { return groups_ != nullptr && !latest_; }
    const SdoGroupIndex* groups() const { return groups_.get(); }
    RowKind rowKind(int row) const;
    int64_t groupAt(int row) const;  // the transfer of a header or member row, else -1
    bool isExpanded(int64_t group) const { return expanded_.count(static_cast<uint32_t>(group)) != 0; }
    // Expands or collapses the transfer of header row `row`; false if it is not one.
    bool toggleExpanded(int row);
    // The transfer record of a group (decoded in the trace's context) and its frames.
    dissect::SdoTransferRecord transferRecord(int64_t group) const;
    // Some frames the row's summary and details read (the frame and the decoder's checkpoint;
    // a transfer's frames) are on disk: asks the store to load them and says true until then.
    bool rowPagedOut(int row) const;
    // Keeps the chunks of the rows shown (rows first..last and `current`) in RAM whatever the
    // budget (TraceStore::pin): shown rows and the details pane are not paged out under the view.
    void pinRows(int first, int last, int current);
    void setLatestPerCobId(bool on);
    bool latestPerCobId() const { return latest_; }

    // Pulls what was appended since the last call.
    void refresh();

    FrameNo frameAt(int row) const;
    // The frames the view stands for, in trace order, each once (a collapsed transfer row
    // stands for all its frames the filter lets through): what "save shown frames" writes.
    std::vector<FrameNo> shownFrames() const;
    // What Find looks through (TraceFind.h): the frames of the rows in row order; grouped, the
    // frames of the source in trace order (a frame then stands for its transfer's header row
    // while the transfer is collapsed). findPosition(): the position of a row's frame there;
    // rowOfFindPosition(): the row that shows position `pos` of `rows`.
    FindRows findRows() const;
    int64_t findPosition(int row) const;
    int rowOfFindPosition(const FindRows& rows, int64_t pos) const;
    // The row showing frame n, or the nearest row after it (-1 when none).
    int rowAtOrAfter(FrameNo n) const;
    int rowOf(FrameNo n) const;  // exact, -1 when the frame is not shown

    void toggleBookmark(FrameNo n);
    bool isBookmarked(FrameNo n) const { return bookmarks_.count(n) != 0; }
    const std::set<FrameNo>& bookmarks() const { return bookmarks_; }

    // Decoded one-line summary of frame n (cached).
    QString summaryOf(FrameNo n) const;
    // The gaps of a lost adapter that end right before frame n (TraceStore::Gap), shown on its
    // row: gapText() of each, in the order they happened.
    std::vector<TraceStore::Gap> gapsBefore(FrameNo n) const { return store_->gapsAt(n); }
    static QString gapText(const TraceStore::Gap& gap);
    static QString gapsText(const std::vector<TraceStore::Gap>& gaps);
    QString timeText(FrameNo n, int row) const;

    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

private:
    enum class Source { All, Filtered, Latest };
    Source source() const;
    void resetRows();
    void refreshLatest();
    void refreshGrouped(std::vector<FrameNo> newSource, FrameNo oldScanned);
    bool inSource(FrameNo n) const;
    struct RowRef {
        size_t top = 0;   // index in grouped_.top
        int member = -1;  // -1: the top row itself; else the member of its expanded group
    };
    RowRef resolve(int row) const;
    int visibleRow(size_t top) const;
    size_t topIndexOfGroup(uint32_t group) const;
    void ensureExpandedAt() const;
    using GroupText = SdoGroupIndex::RowText;
    const GroupText& groupText(uint32_t group) const;

    std::shared_ptr<const TraceStore> store_;
    std::shared_ptr<const FrameDecoder> decoder_;
    QStringList busNames_;
    TimeMode timeMode_ = TimeMode::Relative;
    int rows_ = 0;  // rows announced to views
    int64_t t0_ = 0;
    bool haveT0_ = false;

    std::optional<TraceFilter> filter_;
    std::vector<FrameNo> filtered_;  // Filtered: the matches
    FrameNo scanned_ = 0;            // Filtered: frames [0, scanned_) tested
    bool latest_ = false;
    std::vector<FrameNo> latestRows_;  // Latest: one frame per key, ordered by key
    std::vector<uint32_t> latestKeys_;

    std::shared_ptr<SdoGroupIndex> groups_;  // grouped view when set
    GroupedRows grouped_;
    std::map<uint32_t, std::vector<FrameNo>> expanded_;  // group -> its frames shown under it
    struct ExpandedAt {
        size_t top;
        uint32_t group;
        size_t count;
    };
    mutable std::vector<ExpandedAt> expandedAt_;  // by top index; rebuilt when rows move
    mutable bool expandedDirty_ = true;
    size_t expandedRows_ = 0;
    mutable std::unordered_map<uint32_t, GroupText> groupTexts_;

    std::set<FrameNo> bookmarks_;
    mutable std::unordered_map<FrameNo, QString> summaries_;
    mutable dissect::Dissection scratch_;
    uint64_t decoderRevision_ = 0;  // of the cached summaries

    // Rows of frames paged out to the journal (issue 16 "Bounded memory"): data() asks the
    // store to load them on its loader thread and draws them as loading; refresh() repaints
    // once the store has paged something in. The GUI thread never waits for the disk.
    bool pagedOut(FrameNo n, int row, int col) const;
    bool groupPagedOut(uint32_t group) const;                  // a transfer's frames and its last one's checkpoint
    bool requestPageIns(std::span<const FrameNo> need) const;  // true: some are paged out
    bool decoderReady(FrameNo n) const;  // false: its decoder snapshot is being rebuilt (loading_ set)
    // New frames [from, to) tested by refresh(): pins their chunks from `from` on while they are
    // in RAM and returns where the first one that is not starts (asked of the loader), or `to`.
    FrameNo pinResident(FrameNo from, FrameNo to) const;
    void unpinResident(FrameNo from, FrameNo upTo) const;
    std::shared_ptr<const TraceStore> pinnedStore_;
    std::vector<uint32_t> pinned_;  // chunks pinned in pinnedStore_
    mutable bool loading_ = false;
    mutable uint64_t pageInsSeen_ = 0;
    mutable uint64_t decoderReadySeen_ = 0;  // the decoder's readyCount() when loading_ was set
};

}  // namespace coscope::gui
