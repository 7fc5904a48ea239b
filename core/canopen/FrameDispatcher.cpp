// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/FrameDispatcher.h"

#include <algorithm>

namespace coscope::canopen {

FrameDispatcher::FrameDispatcher() {
    for (auto& w : wanted_) w.store(0, std::memory_order_relaxed);
}

FrameDispatcher::~FrameDispatcher() = default;

int FrameDispatcher::subscribe(QObject* context, std::vector<uint32_t> cobIds, Handler handler) {
    std::lock_guard lock(mutex_);
    Subscription s;
    s.id = nextId_++;
    s.context = context;
    s.cobIds = std::move(cobIds);
    s.handler = std::make_shared<Handler>(std::move(handler));
    s.alive = std::make_shared<std::atomic<bool>>(true);
    subs_.push_back(std::move(s));
    rebuildWantedLocked();
    return subs_.back().id;
}

void FrameDispatcher::unsubscribe(int id) {
    std::lock_guard lock(mutex_);
    for (auto& s : subs_)
        if (s.id == id) s.alive->store(false);
    std::erase_if(subs_, [id](const Subscription& s) { return s.id == id; });
    rebuildWantedLocked();
}

void FrameDispatcher::setCobIds(int id, std::vector<uint32_t> cobIds) {
    std::lock_guard lock(mutex_);
    for (auto& s : subs_)
        if (s.id == id) {
            s.cobIds = std::move(cobIds);  // ids are unique: one subscription
            break;
        }
    rebuildWantedLocked();
}

void FrameDispatcher::rebuildWantedLocked() {
    std::array<uint8_t, 2048> w{};
    for (const auto& s : subs_)
        for (uint32_t id : s.cobIds)
            if (id < w.size()) w[id] = 1;
    for (size_t i = 0; i < w.size(); ++i) wanted_[i].store(w[i], std::memory_order_relaxed);
}

void FrameDispatcher::dispatch(const CanFrame* frames, size_t count) {
    bool any = false;
    for (size_t i = 0; i < count && !any; ++i) {
        const CanFrame& f = frames[i];
        any = !f.isExtended() && !f.isTx() && !f.isError() && f.id < 2048 &&
              wanted_[f.id].load(std::memory_order_relaxed);
    }
    if (!any) return;  // the common case: nothing for the services in this batch

    std::lock_guard lock(mutex_);
    for (size_t i = 0; i < count; ++i) {
        const CanFrame& f = frames[i];
        if (f.isExtended() || f.isTx() || f.isError() || f.id >= 2048 || !wanted_[f.id].load(std::memory_order_relaxed))
            continue;
        for (auto& s : subs_)
            if (std::find(s.cobIds.begin(), s.cobIds.end(), f.id) != s.cobIds.end()) s.pending.push_back(f);
    }
    for (auto& s : subs_) {
        if (s.pending.empty()) continue;
        std::vector<CanFrame> batch;
        batch.swap(s.pending);
        QObject* ctx = s.context.data();
        if (!ctx) continue;
        std::shared_ptr<Handler> handler = s.handler;
        std::shared_ptr<std::atomic<bool>> alive = s.alive;
        // Queued to the subscriber's thread; Qt drops the call if the context dies first.
        QMetaObject::invokeMethod(
            ctx,
            [handler, alive, batch = std::move(batch)] {
                if (alive->load()) (*handler)(batch);
            },
            Qt::QueuedConnection);
    }
}

int FrameDispatcher::addWatch(std::vector<uint32_t> cobIds, Watch watch) {
    std::lock_guard lock(watchMutex_);
    const int id = nextWatchId_++;
    watches_.push_back({id, std::move(cobIds), std::move(watch)});
    watchCount_.store(static_cast<int>(watches_.size()));
    return id;
}

void FrameDispatcher::removeWatch(int id) {
    std::lock_guard lock(watchMutex_);
    std::erase_if(watches_, [id](const WatchEntry& w) { return w.id == id; });
    watchCount_.store(static_cast<int>(watches_.size()));
}

void FrameDispatcher::offerToWatches(const TraceStore& store, FrameNo first, size_t count) {
    std::lock_guard lock(watchMutex_);
    for (size_t i = 0; i < count; ++i) {
        const FrameNo n = static_cast<FrameNo>(first + i);
        const TraceRecord& r = store.record(n);
        if (r.flags & (CanFrame::Extended | CanFrame::Error)) continue;
        for (const WatchEntry& w : watches_)
            if (std::find(w.cobIds.begin(), w.cobIds.end(), r.id) != w.cobIds.end()) w.watch(store.frame(n));
    }
}

CaptureSession::Consumer FrameDispatcher::consumer() {
    return [this](const TraceStore& store, FrameNo first, size_t count) {
        if (watchCount_.load(std::memory_order_relaxed)) offerToWatches(store, first, count);
        // Cheap test on the stored record (id and flags); only frames some service waits for
        // are rebuilt and handed on.
        std::vector<CanFrame> wanted;
        for (size_t i = 0; i < count; ++i) {
            const FrameNo n = static_cast<FrameNo>(first + i);
            const TraceRecord& r = store.record(n);
            if ((r.flags & (CanFrame::Extended | CanFrame::Tx | CanFrame::Error)) || r.id >= 2048 ||
                !wanted_[r.id].load(std::memory_order_relaxed))
                continue;
            wanted.push_back(store.frame(n));
        }
        if (!wanted.empty()) dispatch(wanted.data(), wanted.size());
    };
}

}  // namespace coscope::canopen
