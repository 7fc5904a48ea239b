// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/gui/session/Job.h"
#include "app/gui/trace/FrameDecoder.h"
#include "app/gui/trace/SdoGroups.h"
#include "core/trace/TraceStore.h"

#include <QString>

#include <functional>
#include <map>
#include <memory>
#include <span>
#include <vector>

namespace coscope::gui {

// The texts of a frame's trace row that Find looks in, as the trace shows them (TraceModel uses
// them too): the COB-ID column, the data bytes, the decoded summary in the UI language.
QString cobIdText(const TraceRecord& r);
QString dataText(const TraceStore& store, FrameNo n);
QString summaryText(const dissect::Dissection& d);

// The rows of a grouped view as Find sees them (TraceModel::findRows): each row as shown, a
// frame or a transfer's header (GroupedRows encoding, the group being an index into `begin`),
// and the frames of those transfers, copied so a worker can read them while the index grows.
struct FindTransfers {
    std::vector<uint64_t> rows;
    std::vector<uint32_t> group;  // per transfer here: its group in the model's SdoGroupIndex
    std::vector<uint32_t> begin;  // per transfer here: its frames are members[begin[t], begin[t + 1])
    std::vector<FrameNo> members;
};

// The rows Find looks through, in row order: row r is frame r, or (filtered, latest per COB-ID)
// (*frames)[r], or (grouped) transfers->rows[r]. A copy, so a worker can read it while the view
// changes.
struct FindRows {
    std::shared_ptr<const std::vector<FrameNo>> frames;  // null: row r is frame r
    size_t count = 0;
    std::shared_ptr<const FindTransfers> transfers;  // grouped view
    // The row's frame (a transfer's header: the frame it stands at).
    FrameNo frameAt(size_t row) const {
        if (transfers) return GroupedRows::keyOf(transfers->rows[row]);
        return frames ? (*frames)[row] : static_cast<FrameNo>(row);
    }
    // A transfer's header row: its index in `transfers`, else -1.
    int64_t transferAt(size_t row) const { return transfers ? GroupedRows::groupOf(transfers->rows[row]) : -1; }
    std::span<const FrameNo> transferFrames(size_t t) const {
        return {transfers->members.data() + transfers->begin[t], transfers->begin[t + 1] - transfers->begin[t]};
    }
};

// Does frame n's row contain `text` (case-insensitive)? Reads the frame from the store, so a
// frame paged out to the journal is loaded back (issue 16): never matched against "loading…".
class FrameMatcher {
public:
    FrameMatcher(QString text, std::shared_ptr<const FrameDecoder> decoder)
        : text_(std::move(text)), decoder_(std::move(decoder)) {}
    bool matches(const TraceStore& store, FrameNo n);
    // Does row `row` contain it, as the trace shows the row: a frame's texts, or a transfer
    // header's own texts (its COB-ID, reassembled data and summary; SdoGroupIndex::rowText).
    bool matchesRow(const TraceStore& store, const FindRows& rows, size_t row);

private:
    bool gapMatches(const TraceStore& store, FrameNo n);

    QString text_;
    std::shared_ptr<const FrameDecoder> decoder_;
    dissect::Dissection scratch_;
    // The frames whose row says that a gap (an adapter lost) holding text_ ended before them
    // (TraceModel::gapsText): read once from the store.
    std::map<FrameNo, bool> gaps_;
    bool gapsRead_ = false;
};

// Tests rows from `from` on (inclusive) in one direction while `mayRead(row, frame)` says so.
// Backward, the rows of one checkpoint interval are decoded in frame order (FrameDecoder's
// decodeAt is cheap forward only), so a search back costs about one dissection per row too.
// found: the first matching row, else -1; next: the row it stopped before (-1: ran off the end).
struct FindStep {
    int64_t found = -1;
    int64_t next = -1;
};
FindStep findRows(const TraceStore& store, const FindRows& rows, FrameMatcher& matcher, int64_t from, bool forward,
                  const std::function<bool(int64_t row, FrameNo n)>& mayRead);

// The frames a row's texts are read from (the frame, the decoder's checkpoint before it; a
// transfer's frames and its last one's checkpoint) are in RAM: testing it on the GUI thread does
// not wait for the disk.
bool findReadsResident(const TraceStore& store, FrameNo n);
bool findReadsResident(const TraceStore& store, const FindRows& rows, size_t row);

// Find over rows whose frames are paged out (or too many to test at once): on a worker, which
// loads the chunks back from the journal as it goes; `done` is called on the worker when it ends.
class FindJob : public Job {
public:
    FindJob(std::shared_ptr<const TraceStore> store, std::shared_ptr<const FrameDecoder> decoder, QString text,
            FindRows rows, int64_t from, bool forward, std::function<void()> done);
    ~FindJob() override;

    const QString& text() const { return text_; }
    bool forward() const { return forward_; }
    int64_t foundRow() const { return found_; }  // valid once isDone(); -1: not found
    const FindRows& rows() const { return rows_; }

protected:
    void run() override;

private:
    std::shared_ptr<const TraceStore> store_;
    std::shared_ptr<const FrameDecoder> decoder_;
    QString text_;
    FindRows rows_;
    int64_t from_;
    bool forward_;
    std::function<void()> done_;
    int64_t found_ = -1;
};

}  // namespace coscope::gui
