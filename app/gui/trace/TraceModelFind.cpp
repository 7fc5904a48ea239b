// SPDX-License-Identifier: GPL-3.0-or-later
// The rows Find looks through (TraceFind.h), as the trace shows them: in the grouped view a
// transfer's header row is one row with its own texts, and the frames of an expanded transfer
// follow it, as on screen.
#include "app/gui/trace/TraceModel.h"

#include <algorithm>

namespace coscope::gui {

FindRows TraceModel::findRows() const {
    FindRows rows;
    rows.count = static_cast<size_t>(rows_);
    if (isGrouped()) {
        auto t = std::make_shared<FindTransfers>();
        t->rows.reserve(rows.count);
        t->begin.push_back(0);
        for (const uint64_t top : grouped_.top) {
            if (t->rows.size() >= rows.count) break;
            const int64_t g = GroupedRows::groupOf(top);
            if (g < 0) {
                t->rows.push_back(top);
                continue;
            }
            const auto frames = groups_->frames(static_cast<size_t>(g));
            t->rows.push_back(GroupedRows::header(t->group.size(), GroupedRows::keyOf(top)));
            t->group.push_back(static_cast<uint32_t>(g));
            t->members.insert(t->members.end(), frames.begin(), frames.end());
            t->begin.push_back(static_cast<uint32_t>(t->members.size()));
            const auto expanded = expanded_.find(static_cast<uint32_t>(g));
            if (expanded == expanded_.end()) continue;
            for (const FrameNo n : expanded->second) t->rows.push_back(GroupedRows::plain(n));
        }
        rows.count = std::min(rows.count, t->rows.size());
        rows.transfers = std::move(t);
        return rows;
    }
    switch (source()) {
    case Source::All: break;
    case Source::Filtered:
        rows.frames = std::make_shared<const std::vector<FrameNo>>(filtered_.begin(), filtered_.begin() + rows_);
        break;
    case Source::Latest:
        rows.frames = std::make_shared<const std::vector<FrameNo>>(latestRows_.begin(), latestRows_.begin() + rows_);
        break;
    }
    return rows;
}

int64_t TraceModel::findPosition(int row) const { return row; }

int TraceModel::rowOfFindPosition(const FindRows& rows, int64_t pos) const {
    if (pos < 0 || static_cast<size_t>(pos) >= rows.count) return -1;
    // The rows may have changed since `rows` was taken (a live capture appends, a transfer
    // completes): the row that shows the same frame or transfer now.
    const int64_t t = rows.transferAt(static_cast<size_t>(pos));
    if (t < 0 || !isGrouped()) return rowOf(rows.frameAt(static_cast<size_t>(pos)));
    const uint32_t g = rows.transfers->group[static_cast<size_t>(t)];
    if (g >= grouped_.headerKey.size() || grouped_.headerKey[g] == SdoGroupIndex::kNone) return -1;
    return visibleRow(topIndexOfGroup(g));
}

}  // namespace coscope::gui
