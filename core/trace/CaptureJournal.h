// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"
#include "core/trace/JournalPager.h"
#include "core/trace/TraceStore.h"

#include <QString>
#include <QStringList>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

namespace coscope {

// The capture journal of DESIGN.md "Reliability": every live frame goes to a pcapng file
// (SocketCAN link type, so Wireshark reads it) as it arrives. The capture path only copies the
// frames into a pending batch; a writer thread writes them, hands them to the kernel every
// 200 ms and syncs them to the disk (fdatasync) at least once a second. Each pcapng block is
// self-contained, so after a SIGKILL or a power loss the file is valid up to the last flush
// (a torn last block is reported and skipped by PcapReader).
// While the journal is open a sidecar `NAME.open` (holding the writer's pid) says so; close()
// removes it, so a sidecar whose process is gone marks a journal that was not closed cleanly
// (see JournalFolder).
class CaptureJournal {
public:
    CaptureJournal() = default;
    ~CaptureJournal();
    CaptureJournal(const CaptureJournal&) = delete;
    CaptureJournal& operator=(const CaptureJournal&) = delete;

    // Creates `path` and its sidecar and starts the writer thread. False with errorString().
    bool open(const QString& path, const QStringList& busNames);
    // Capture path: queues frames (a copy under a short lock; never waits for the disk).
    void append(std::span<const CanFrame> frames);
    // A CaptureSession consumer that queues each new batch.
    void appendFromStore(const TraceStore& store, FrameNo first, size_t count);
    // A gap of the capture (the adapter was lost and is back): recorded with frame
    // gap.firstFrame of the store (a pcapng packet comment), or with the first frame written
    // after that if it was already written. Dropped if no frame follows before close().
    void addGap(const TraceStore::Gap& gap);
    // Frames queued and not yet handed to the writer thread (a producer faster than the disk
    // waits with flush() when this grows: a log read into a spill journal).
    size_t queuedFrames() const;
    // Writes what is queued and syncs it; blocks until done (Save As, tests).
    bool flush();
    // Writes the rest, syncs, closes the file and removes the sidecar.
    bool close();

    bool isOpen() const { return running_.load(); }
    // A write failed (disk full, device gone): nothing more is written; errorString() says why.
    bool hasError() const { return failed_.load(); }
    QString errorString() const;
    QString path() const { return path_; }
    uint64_t framesWritten() const { return written_.load(); }
    // Loads this journal's frames back for a TraceStore with a memory budget (frame n of the
    // journal is frame n of the store it is fed from). Valid from open(); outlives close().
    std::shared_ptr<JournalPager> pager() const { return pager_; }

    static constexpr int kWriteIntervalMs = 200;
    static constexpr int kSyncIntervalMs = 1000;
    static QString sidecarOf(const QString& journalPath);

private:
    void run();
    bool writeBatch(const std::vector<CanFrame>& batch);

    QString path_;
    QStringList busNames_;
    std::thread thread_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::vector<CanFrame> pending_;
    std::vector<TraceStore::Gap> pendingGaps_;
    std::vector<TraceStore::Gap> gaps_;  // writer thread: gaps waiting for their frame
    bool stop_ = false;
    uint64_t flushRequests_ = 0;  // flush() asked this many times
    uint64_t flushesDone_ = 0;
    std::condition_variable flushed_;
    QString error_;
    std::atomic<bool> running_{false};
    std::atomic<bool> failed_{false};
    std::atomic<uint64_t> written_{0};
    struct Writer;
    Writer* writer_ = nullptr;
    std::shared_ptr<JournalPager> pager_;  // owned; lives on the writer thread between open() and close()
};

}  // namespace coscope
