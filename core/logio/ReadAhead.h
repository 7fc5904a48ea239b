// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"

#include <QStringList>

#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

namespace coscope::logio {

class LogReader;

// Reads a log on a thread of its own, a few batches ahead of the consumer, so parsing the file
// and using its frames (dissecting, counting) run on two cores. The reader belongs to this
// object until it is destroyed: do not touch it (diagnostics, bus names) before next() has
// returned an empty batch, which means the end, a fatal error or cancel().
class ReadAhead {
public:
    // What runs on the reading thread for each batch it has read, before the consumer gets it
    // (work that needs only the frames, taken off the consumer's thread); it must not block.
    using BatchObserver = std::function<void(std::span<const CanFrame>)>;

    static constexpr size_t kBatchFrames = 4096, kDepth = 4;

    explicit ReadAhead(LogReader& reader, size_t batchFrames = kBatchFrames, size_t depth = kDepth,
                       BatchObserver observer = {});
    ~ReadAhead();  // cancels the reader if it is still running and waits for the thread
    ReadAhead(const ReadAhead&) = delete;
    ReadAhead& operator=(const ReadAhead&) = delete;

    // The next batch of frames; valid until the next call. Empty at the end.
    std::span<const CanFrame> next();
    // Keeps the current batch past next() without a copy: its storage moves into `frames` (the
    // span next() returned stays valid, now owned by `frames`), and `frames`' former storage
    // (any size; resized to a batch) takes its place for a later batch. Only between next()
    // returning a batch and the next call.
    void keepBatch(std::vector<CanFrame>& frames);
    // The reader's bus names as they were after the current batch (CanFrame::bus indexes them).
    const QStringList& busNames() const { return busNames_; }

private:
    void produce();

    struct Slot {
        std::vector<CanFrame> frames;
        size_t count = 0;
        QStringList busNames;
    };
    LogReader& reader_;
    size_t batchFrames_;
    BatchObserver observer_;
    std::vector<Slot> slots_;
    std::mutex mutex_;
    std::condition_variable changed_;
    size_t filled_ = 0;    // slots produced (monotonic)
    size_t consumed_ = 0;  // slots handed back by the consumer (monotonic)
    bool finished_ = false;
    bool stop_ = false;
    bool holding_ = false;  // the consumer holds slot consumed_ % size
    QStringList busNames_;
    std::thread thread_;
};

}  // namespace coscope::logio
