// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/trace/TracePager.h"

#include <QByteArray>
#include <QString>

#include <atomic>
#include <mutex>
#include <utility>
#include <vector>

namespace coscope {

// Loads frames back from a capture journal (pcapng) for a TraceStore with bounded memory
// (issue 16). The journal's writer thread reports where each chunk of TraceStore::kChunkSize
// frames starts in the file, how far the file is written, and the header blocks it wrote (the
// section header and each interface block, with the frame they came before). A load reads only
// the byte range of the chunks asked for and parses it with PcapReader behind a copy of the
// header blocks written before it, so a page-in costs one chunk of disk reads and memory
// however large the journal grows. Outlives the journal's close: a stopped capture stays
// pageable while the file exists.
class JournalPager : public TracePager {
public:
    explicit JournalPager(QString path) : path_(std::move(path)) {}

    // Writer thread: frame `frame` (a multiple of kChunkSize) starts at byte `offset`.
    void chunkStarts(uint64_t frame, int64_t offset);
    // Writer thread: a header block (SHB: bus -1; IDB of `bus`) written right before frame
    // `beforeFrame`. A frame read back gets the bus of its interface block, whatever order the
    // buses first appeared in.
    void addHeaderBlock(uint64_t beforeFrame, const QByteArray& bytes, int bus = -1);
    size_t headerBlocks() const;
    // Writer thread: `frames` frames are in the file (handed to the kernel), `bytes` long.
    void setWritten(uint64_t frames, int64_t bytes);

    uint64_t durableFrames() const override { return frames_.load(std::memory_order_acquire); }
    bool load(uint64_t first, uint32_t count, std::vector<CanFrame>& out, std::string* why) override;
    // The journal's folder.
    std::string spillDirectory() const override;

private:
    bool loadRange(QByteArray data, uint64_t skip, uint32_t count, const std::vector<uint8_t>& busOfInterface,
                   std::vector<CanFrame>& out, std::string* why) const;

    const QString path_;
    mutable std::mutex mutex_;
    std::vector<int64_t> starts_{0};                       // byte offset of frame c * kChunkSize; starts_[0] = 0
    std::vector<std::pair<uint64_t, QByteArray>> header_;  // header blocks, by the frame they precede
    std::vector<uint8_t> busOfInterface_;                  // the bus of each interface block, in file order
    int64_t bytes_ = 0;
    std::atomic<uint64_t> frames_{0};
};

}  // namespace coscope
