// SPDX-License-Identifier: GPL-3.0-or-later
// TraceModel's rows whose frames are paged out to the capture journal (issue 16 "Bounded
// memory"): the store loads them on its loader thread; the GUI thread never waits for the disk.
#include "app/gui/trace/TraceModel.h"

#include "dissectors/NetworkContext.h"

#include <algorithm>

namespace coscope::gui {

bool TraceModel::rowPagedOut(int row) const {
    if (!store_ || row < 0 || row >= rows_) return false;
    if (rowKind(row) == RowKind::Transfer) return groupPagedOut(static_cast<uint32_t>(groupAt(row)));
    return pagedOut(frameAt(row), row, Summary);
}

void TraceModel::pinRows(int first, int last, int current) {
    std::vector<uint32_t> chunks;
    const auto add = [&](int row) {
        if (!store_ || row < 0 || row >= rows_) return;
        chunks.push_back(frameAt(row) >> TraceStore::kChunkBits);
        if (rowKind(row) != RowKind::Transfer || !groups_) return;
        const SdoGroup& g = groups_->group(static_cast<size_t>(groupAt(row)));
        for (FrameNo n = g.first; n <= g.last; n += TraceStore::kChunkSize)
            chunks.push_back(n >> TraceStore::kChunkBits);
        chunks.push_back(g.last >> TraceStore::kChunkBits);
    };
    for (int row = std::max(first, 0); row <= last && row < rows_; ++row) add(row);
    add(current);
    std::sort(chunks.begin(), chunks.end());
    chunks.erase(std::unique(chunks.begin(), chunks.end()), chunks.end());
    if (pinnedStore_ == store_ && chunks == pinned_) return;
    const auto chunkRange = [](uint32_t c) {
        return std::pair{FrameNo(c) << TraceStore::kChunkBits, FrameNo(c) << TraceStore::kChunkBits};
    };
    if (store_)
        for (uint32_t c : chunks) store_->pin(chunkRange(c).first, chunkRange(c).second);
    if (pinnedStore_)
        for (uint32_t c : pinned_) pinnedStore_->unpin(chunkRange(c).first, chunkRange(c).second);
    pinnedStore_ = store_;
    pinned_ = std::move(chunks);
}

bool TraceModel::pagedOut(FrameNo n, int row, int col) const {
    // The frames data() reads for this cell: the frame; for the summary also the frames the
    // decoder replays from its checkpoint; for Δt the previous row's frame.
    FrameNo need[3] = {n, n, n};
    if (col == Summary) need[1] = static_cast<FrameNo>(n - n % dissect::NetworkContext::checkpointInterval());
    if (col == Time && timeMode_ == TimeMode::Delta && row > 0) need[2] = frameAt(row - 1);
    if (requestPageIns(need)) return true;
    // An old frame whose decoder snapshot is not kept (TraceDecoder): rebuilt on its worker.
    return col == Summary && !decoderReady(n);
}

bool TraceModel::groupPagedOut(uint32_t g) const {
    // A transfer row reads all its frames (reassembly) and decodes its last one (groupText()).
    if (!groups_ || g >= groups_->size()) return false;
    const SdoGroup& grp = groups_->group(g);
    const FrameNo checkpoint =
        static_cast<FrameNo>(grp.last - grp.last % dissect::NetworkContext::checkpointInterval());
    const auto frames = groups_->frames(g);
    bool out = requestPageIns(std::span<const FrameNo>(&checkpoint, 1));
    uint64_t chunk = ~uint64_t(0);
    for (const FrameNo f : frames) {  // one question per chunk
        if ((f >> TraceStore::kChunkBits) == chunk) continue;
        chunk = f >> TraceStore::kChunkBits;
        out = requestPageIns(std::span<const FrameNo>(&f, 1)) || out;
    }
    return out || !decoderReady(grp.last);
}

bool TraceModel::decoderReady(FrameNo n) const {
    if (!loading_) {  // counted before asking, so a snapshot rebuilt meanwhile is not missed
        pageInsSeen_ = store_->pageIns();
        decoderReadySeen_ = decoder_->readyCount();
    }
    if (decoder_->readyAt(*store_, n)) return true;
    loading_ = true;
    return false;
}

bool TraceModel::requestPageIns(std::span<const FrameNo> need) const {
    bool out = false;
    for (const FrameNo f : need) {
        if (f >= store_->size() || store_->isResident(f)) continue;
        if (!loading_) {  // counted before asking, so a page-in done meanwhile is not missed
            loading_ = true;
            pageInsSeen_ = store_->pageIns();
            decoderReadySeen_ = decoder_->readyCount();
        }
        store_->requestPageIn(f);
        out = true;
    }
    return out;
}

FrameNo TraceModel::pinResident(FrameNo from, FrameNo to) const {
    // A text filter decodes a frame from the checkpoint before it, in the same chunk
    // (NetworkContext::checkpointInterval() divides TraceStore::kChunkSize).
    static_assert(TraceStore::kChunkSize % dissect::NetworkContext::checkpointInterval() == 0);
    FrameNo end = from;
    while (end < to) {
        store_->pin(end, end);  // then resident stays resident
        if (!store_->isResident(end)) {
            store_->unpin(end, end);
            requestPageIns(std::span<const FrameNo>(&end, 1));
            break;
        }
        end = std::min<FrameNo>(
            static_cast<FrameNo>(((uint64_t(end) >> TraceStore::kChunkBits) + 1) << TraceStore::kChunkBits), to);
    }
    return end;
}

void TraceModel::unpinResident(FrameNo from, FrameNo upTo) const {
    if (upTo > from) store_->unpin(from, upTo - 1);
}

}  // namespace coscope::gui
