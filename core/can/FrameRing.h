// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"

#include <atomic>
#include <cstddef>
#include <memory>

namespace coscope {

// Single-producer single-consumer lock-free ring of frames between a bus's reader thread and
// whoever drains it (ingest worker, CLI). The producer never blocks: when the ring is full the
// frame is counted as dropped, never silently lost.
class FrameRing {
public:
    explicit FrameRing(size_t capacityPow2 = 1u << 16);

    // Producer side. Returns false (and counts a drop) when the ring is full.
    bool push(const CanFrame& frame);
    // Consumer side. Copies up to `max` frames into `out`, returns how many.
    size_t pop(CanFrame* out, size_t max);

    size_t size() const;
    size_t capacity() const { return mask_ + 1; }
    uint64_t dropped() const { return dropped_.load(std::memory_order_relaxed); }

private:
    std::unique_ptr<CanFrame[]> slots_;
    size_t mask_;
    alignas(64) std::atomic<size_t> head_{0};  // written by the producer
    alignas(64) std::atomic<size_t> tail_{0};  // written by the consumer
    alignas(64) std::atomic<uint64_t> dropped_{0};
};

}  // namespace coscope
