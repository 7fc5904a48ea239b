// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/trace/TraceStore.h"
#include "dissectors/Dissection.h"
#include "dissectors/SdoReassembly.h"

#include <QString>

#include <functional>
#include <limits>
#include <span>
#include <unordered_map>
#include <vector>

namespace coscope::gui {

class FrameDecoder;

// One reassembled SDO transfer (expedited, segmented or block; completed or aborted) and its
// frames, in trace order.
struct SdoGroup {
    FrameNo first = 0;   // its first frame
    FrameNo last = 0;    // the frame that completed or aborted it
    uint32_t begin = 0;  // its frames: SdoGroupIndex::frames()
    uint32_t count = 0;
};

// The SDO transfers of a trace, found by running the reassembly of dissectors/SdoReassembly
// (CiA 301 §7.2.4.3) over the SDO frames (600h+n / 580h+n) of every (bus, node) channel.
// Needs no dictionary: the transfer record with names and typed value is asked of the decoder
// when shown (record()). Built incrementally: scan() continues where the last call stopped,
// so a live capture adds the transfers completed since. Frames of a transfer that never ended
// (abandoned by a new request, still running) belong to no group. Not thread-safe: one owner.
class SdoGroupIndex {
public:
    static constexpr FrameNo kNone = std::numeric_limits<FrameNo>::max();

    // Scans frames [scannedUpTo(), to); false when `progress` asked to stop (the index then
    // holds what was scanned so far and can be continued).
    bool scan(const TraceStore& store, FrameNo to, const std::function<bool(double)>& progress = {});
    FrameNo scannedUpTo() const { return scanned_; }

    size_t size() const { return groups_.size(); }
    const SdoGroup& group(size_t g) const { return groups_[g]; }
    std::span<const FrameNo> frames(size_t g) const { return {members_.data() + groups_[g].begin, groups_[g].count}; }
    // The group frame n belongs to, or -1.
    int64_t groupOf(FrameNo n) const;
    // Members sorted by frame number: (frame, group). For merging with an ascending frame list.
    const std::vector<std::pair<FrameNo, uint32_t>>& byFrame() const { return byFrame_; }

    // The transfer record of group g: from the decoder (names, typed value: it decodes the last
    // frame in its context) when it reports the same transfer, else reassembled from the frames.
    static dissect::SdoTransferRecord record(const TraceStore& store, const SdoGroupIndex& index, size_t g,
                                             const FrameDecoder& decoder);
    // Same, of a transfer's frames (in trace order; the last one completed or aborted it).
    static dissect::SdoTransferRecord record(const TraceStore& store, std::span<const FrameNo> frames,
                                             const FrameDecoder& decoder);
    // "SDO read node 5 1008:00 Device name = "X" (segmented, 18 bytes, 7 frames)".
    static QString summary(const dissect::SdoTransferRecord& t, size_t frames);
    // The texts of a transfer's row in the trace: Summary, Data (its first 8 bytes), Len.
    struct RowText {
        QString summary, data;
        uint32_t size = 0;
    };
    static RowText rowText(const dissect::SdoTransferRecord& t, size_t frames);

private:
    struct Channel {
        dissect::SdoChannel sdo;
        std::vector<FrameNo> frames;  // of the transfer in progress
    };
    void addGroup(Channel& c);

    std::unordered_map<uint32_t, Channel> channels_;  // bus << 7 | node
    std::vector<SdoGroup> groups_;
    std::vector<FrameNo> members_;
    std::vector<std::pair<FrameNo, uint32_t>> byFrame_;
    FrameNo scanned_ = 0;
    dissect::Dissection scratch_;
};

// The rows of a grouped view: one per frame outside any transfer and one per transfer (its
// header, at the place of its first frame shown), in frame order. A row is
// (group + 1) << 32 | frame; group + 1 == 0 for a plain frame, and `frame` is then the frame.
struct GroupedRows {
    std::vector<uint64_t> top;
    std::vector<FrameNo> headerKey;  // per group: the frame its header row stands at, kNone = no row yet

    static uint64_t plain(FrameNo n) { return n; }
    static uint64_t header(size_t g, FrameNo n) { return (uint64_t(g) + 1) << 32 | n; }
    static FrameNo keyOf(uint64_t row) { return static_cast<FrameNo>(row & 0xFFFFFFFFu); }
    static int64_t groupOf(uint64_t row) { return static_cast<int64_t>(row >> 32) - 1; }

    // Appends the rows for the ascending frames `source` (nullptr: all of [from, to)), all
    // after the rows already there. Frames of a group whose header exists are skipped.
    void append(const SdoGroupIndex& index, const std::vector<FrameNo>* source, FrameNo from, FrameNo to);
};

}  // namespace coscope::gui
