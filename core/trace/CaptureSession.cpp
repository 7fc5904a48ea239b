// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/trace/CaptureSession.h"

#include <chrono>

namespace coscope {

CaptureSession::CaptureSession(std::shared_ptr<TraceStore> store) : store_(std::move(store)) {}

CaptureSession::~CaptureSession() { stop(); }

void CaptureSession::addConsumer(Consumer consumer) { consumers_.push_back(std::move(consumer)); }

void CaptureSession::start(CanBus* bus) {
    stop();
    bus_ = bus;
    running_.store(true);
    thread_ = std::thread([this] { run(); });
}

void CaptureSession::stop() {
    running_.store(false);
    if (thread_.joinable()) thread_.join();
}

void CaptureSession::run() {
    constexpr size_t kBatch = 4096;
    std::vector<CanFrame> batch(kBatch);
    for (;;) {
        const bool keepGoing = running_.load(std::memory_order_relaxed);
        const size_t n = bus_->read(batch.data(), kBatch);
        if (n) {
            const FrameNo first = static_cast<FrameNo>(store_->size());
            store_->append(std::span<const CanFrame>(batch.data(), n));
            for (const auto& c : consumers_) c(*store_, first, n);
            continue;
        }
        if (!keepGoing) break;  // drained after stop was asked
        std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
}

}  // namespace coscope
