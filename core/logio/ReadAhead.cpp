// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/logio/ReadAhead.h"

#include "core/logio/LogReader.h"

#include <utility>

namespace coscope::logio {

ReadAhead::ReadAhead(LogReader& reader, size_t batchFrames, size_t depth, BatchObserver observer)
    : reader_(reader), batchFrames_(batchFrames ? batchFrames : 1), observer_(std::move(observer)),
      slots_(depth < 2 ? 2 : depth) {
    for (Slot& s : slots_) s.frames.resize(batchFrames_);
    thread_ = std::thread([this] { produce(); });
}

ReadAhead::~ReadAhead() {
    bool running;
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
        running = !finished_;
    }
    if (running) reader_.cancel();  // a read in progress returns soon
    changed_.notify_all();
    thread_.join();
}

void ReadAhead::produce() {
    for (;;) {
        Slot* slot;
        {
            std::unique_lock lock(mutex_);
            changed_.wait(lock, [&] { return stop_ || filled_ - consumed_ < slots_.size(); });
            if (stop_) break;
            slot = &slots_[filled_ % slots_.size()];
        }
        // The slot is free (the consumer moved past it): fill it without the lock.
        slot->count = reader_.read(slot->frames.data(), slot->frames.size());
        slot->busNames = reader_.busNames();  // a shared copy, made on this thread
        if (observer_ && slot->count) observer_(std::span<const CanFrame>(slot->frames.data(), slot->count));
        std::lock_guard lock(mutex_);
        if (slot->count == 0) {
            finished_ = true;
            changed_.notify_all();
            break;
        }
        ++filled_;
        changed_.notify_all();
    }
}

std::span<const CanFrame> ReadAhead::next() {
    std::unique_lock lock(mutex_);
    if (holding_) {
        ++consumed_;
        holding_ = false;
        changed_.notify_all();
    }
    changed_.wait(lock, [&] { return filled_ > consumed_ || finished_; });
    if (filled_ == consumed_) return {};
    holding_ = true;
    const Slot& s = slots_[consumed_ % slots_.size()];
    busNames_ = s.busNames;
    return {s.frames.data(), s.count};
}

void ReadAhead::keepBatch(std::vector<CanFrame>& frames) {
    // The held slot is the consumer's alone (produce() waits for it to be handed back).
    if (!holding_) return;
    if (frames.size() != batchFrames_) frames.resize(batchFrames_);
    slots_[consumed_ % slots_.size()].frames.swap(frames);
}

}  // namespace coscope::logio
