// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/FrameRing.h"

#include <bit>

namespace coscope {

FrameRing::FrameRing(size_t capacityPow2)
    : slots_(new CanFrame[std::bit_ceil(std::max<size_t>(capacityPow2, 2))]),
      mask_(std::bit_ceil(std::max<size_t>(capacityPow2, 2)) - 1) {}

bool FrameRing::push(const CanFrame& frame) {
    const size_t head = head_.load(std::memory_order_relaxed);
    const size_t tail = tail_.load(std::memory_order_acquire);
    if (head - tail > mask_) {
        dropped_.fetch_add(1, std::memory_order_relaxed);
        return false;
    }
    slots_[head & mask_] = frame;
    head_.store(head + 1, std::memory_order_release);
    return true;
}

size_t FrameRing::pop(CanFrame* out, size_t max) {
    const size_t tail = tail_.load(std::memory_order_relaxed);
    const size_t head = head_.load(std::memory_order_acquire);
    const size_t n = std::min(max, head - tail);
    for (size_t i = 0; i < n; ++i) out[i] = slots_[(tail + i) & mask_];
    tail_.store(tail + n, std::memory_order_release);
    return n;
}

size_t FrameRing::size() const { return head_.load(std::memory_order_acquire) - tail_.load(std::memory_order_acquire); }

}  // namespace coscope
