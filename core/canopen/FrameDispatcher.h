// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"
#include "core/trace/CaptureSession.h"

#include <QObject>
#include <QPointer>

#include <array>
#include <atomic>
#include <functional>
#include <mutex>
#include <vector>

namespace coscope::canopen {

// Hands received frames to the master services (SDO client, LSS master, heartbeat monitor...).
// A bus has one reader (CaptureSession's ingest thread); this is the one consumer the services
// share. On the ingest thread each frame is tested against a 2048-entry table of the 11-bit
// COB-IDs some service waits for; only those frames, batched per subscriber, are posted to the
// subscriber's thread. Unrelated traffic never leaves the ingest thread. Frames we sent ourselves
// (CanFrame::Tx echoes) are not delivered.
class FrameDispatcher {
public:
    using Handler = std::function<void(const std::vector<CanFrame>& frames)>;

    FrameDispatcher();
    ~FrameDispatcher();
    FrameDispatcher(const FrameDispatcher&) = delete;
    FrameDispatcher& operator=(const FrameDispatcher&) = delete;

    // Any thread. `handler` runs on `context`'s thread; nothing is delivered once unsubscribe()
    // returned or `context` is destroyed. Returns a subscription id (> 0).
    int subscribe(QObject* context, std::vector<uint32_t> cobIds, Handler handler);
    void unsubscribe(int id);
    // Replaces the COB-IDs of a subscription.
    void setCobIds(int id, std::vector<uint32_t> cobIds);

    // Frames of `cobIds` (11-bit), our own Tx copies included, handed to `watch` on the ingest
    // thread as they are stored, after the trace store and the capture journal got them: for a
    // bounded wait that needs no event loop (DriveDisable.h). Any thread; nothing is handed on
    // once removeWatch() returned.
    using Watch = std::function<void(const CanFrame& frame)>;
    int addWatch(std::vector<uint32_t> cobIds, Watch watch);
    void removeWatch(int id);

    // Ingest thread: offer a batch of frames.
    void dispatch(const CanFrame* frames, size_t count);
    // A CaptureSession consumer that feeds dispatch() from the store.
    CaptureSession::Consumer consumer();

private:
    struct Subscription {
        int id = 0;
        QPointer<QObject> context;
        std::vector<uint32_t> cobIds;
        std::shared_ptr<Handler> handler;
        std::shared_ptr<std::atomic<bool>> alive;  // false once unsubscribed (checked on the subscriber's thread)
        std::vector<CanFrame> pending;             // ingest thread, under mutex_
    };
    struct WatchEntry {
        int id = 0;
        std::vector<uint32_t> cobIds;
        Watch watch;
    };
    void rebuildWantedLocked();
    void offerToWatches(const TraceStore& store, FrameNo first, size_t count);

    std::mutex mutex_;
    std::vector<Subscription> subs_;
    std::array<std::atomic<uint8_t>, 2048> wanted_{};  // per 11-bit id: some subscriber wants it
    int nextId_ = 1;
    std::mutex watchMutex_;
    std::vector<WatchEntry> watches_;
    std::atomic<int> watchCount_{0};
    int nextWatchId_ = 1;
};

}  // namespace coscope::canopen
