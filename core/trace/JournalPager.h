// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/trace/TracePager.h"

#include <QString>

#include <atomic>
#include <mutex>
#include <vector>

namespace coscope {

// Loads frames back from a capture journal (pcapng) for a TraceStore with bounded memory
// (issue 16). The journal's writer thread reports where each chunk of TraceStore::kChunkSize
// frames starts in the file and how far the file is written; a load reads one chunk's byte
// range, behind the file's header blocks (SHB, IDB and the first frame), and parses it with
// PcapReader. If that does not give the frames expected (an interface block later in the file),
// the file is read from its start instead: slower, never wrong. Outlives the journal's close:
// a stopped capture stays pageable while the file exists.
class JournalPager : public TracePager {
public:
    explicit JournalPager(QString path) : path_(std::move(path)) {}

    // Writer thread: frame `frame` (a multiple of kChunkSize) starts at byte `offset`.
    void chunkStarts(uint64_t frame, int64_t offset);
    // Writer thread: the header blocks and frame 0 end at byte `offset`.
    void setFirstFrameEnd(int64_t offset);
    // Writer thread: `frames` frames are in the file (handed to the kernel), `bytes` long.
    void setWritten(uint64_t frames, int64_t bytes);

    uint64_t durableFrames() const override { return frames_.load(std::memory_order_acquire); }
    bool load(uint64_t first, uint32_t count, std::vector<CanFrame>& out, std::string* why) override;
    // The journal's folder.
    std::string spillDirectory() const override;

private:
    bool loadRange(const QByteArray& bytes, uint64_t skip, uint32_t count, std::vector<CanFrame>& out, std::string* why) const;

    const QString path_;
    mutable std::mutex mutex_;
    std::vector<int64_t> starts_{0};  // byte offset of frame c * kChunkSize; starts_[0] = 0
    int64_t firstFrameEnd_ = 0;
    int64_t bytes_ = 0;
    std::atomic<uint64_t> frames_{0};
};

}  // namespace coscope
