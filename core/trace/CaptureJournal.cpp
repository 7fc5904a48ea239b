// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/trace/CaptureJournal.h"

#include "core/logio/PcapLog.h"

#include <QCoreApplication>
#include <QFile>

#include <cerrno>
#include <chrono>
#include <cstring>

#include <spdlog/spdlog.h>
#include <unistd.h>

namespace coscope {

struct CaptureJournal::Writer {
    QFile file;
    logio::PcapngWriter pcapng;
};

namespace {
using Clock = std::chrono::steady_clock;
// fdatasync where the file system has it; a device without it (a pipe, /dev/null) is no failure.
bool syncToDisk(int fd, QString* why) {
    if (fd < 0 || ::fdatasync(fd) == 0) return true;
    const int e = errno;
    if (e == EINVAL || e == EROFS || e == ENOTSUP) return true;
    *why = QString::fromLocal8Bit(std::strerror(e));
    return false;
}
}  // namespace

QString CaptureJournal::sidecarOf(const QString& journalPath) {
    QString s = journalPath;
    if (s.endsWith(QLatin1String(".pcapng"))) s.chop(7);
    return s + QStringLiteral(".open");
}

CaptureJournal::~CaptureJournal() { close(); }

bool CaptureJournal::open(const QString& path, const QStringList& busNames) {
    close();
    path_ = path;
    busNames_ = busNames;
    error_.clear();
    failed_.store(false);
    written_.store(0);
    stop_ = false;
    pendingGaps_.clear();
    gaps_.clear();
    flushRequests_ = flushesDone_ = 0;
    QFile sidecar(sidecarOf(path));
    if (!sidecar.open(QIODevice::WriteOnly | QIODevice::Truncate) ||
        sidecar.write(QByteArray::number(QCoreApplication::applicationPid()) + '\n') < 0) {
        error_ = QStringLiteral("cannot write %1: %2").arg(sidecar.fileName(), sidecar.errorString());
        return false;
    }
    sidecar.close();
    auto* w = new Writer;
    w->file.setFileName(path);
    // Unbuffered: every write reaches the kernel at once, so its failure is seen at once.
    if (!w->file.open(QIODevice::WriteOnly | QIODevice::Truncate | QIODevice::Unbuffered) ||
        !w->pcapng.open(&w->file)) {
        error_ = QStringLiteral("cannot write %1: %2").arg(path, w->file.errorString());
        delete w;
        QFile::remove(sidecarOf(path));
        return false;
    }
    w->pcapng.setBusNames(busNames);
    writer_ = w;
    pager_ = std::make_shared<JournalPager>(path);
    running_.store(true);
    thread_ = std::thread([this] { run(); });
    spdlog::info("capture journal {}", path.toStdString());
    return true;
}

void CaptureJournal::append(std::span<const CanFrame> frames) {
    if (frames.empty() || failed_.load(std::memory_order_relaxed) || !running_.load(std::memory_order_relaxed)) return;
    std::lock_guard lock(mutex_);
    pending_.insert(pending_.end(), frames.begin(), frames.end());
}

void CaptureJournal::appendFromStore(const TraceStore& store, FrameNo first, size_t count) {
    if (count == 0 || failed_.load(std::memory_order_relaxed) || !running_.load(std::memory_order_relaxed)) return;
    std::lock_guard lock(mutex_);
    pending_.reserve(pending_.size() + count);
    for (size_t i = 0; i < count; ++i) pending_.push_back(store.frame(FrameNo(first + i)));
}

void CaptureJournal::addGap(const TraceStore::Gap& gap) {
    if (!running_.load()) return;
    std::lock_guard lock(mutex_);
    pendingGaps_.push_back(gap);
}

size_t CaptureJournal::queuedFrames() const {
    std::lock_guard lock(mutex_);
    return pending_.size();
}

bool CaptureJournal::flush() {
    if (!running_.load()) return !hasError();
    std::unique_lock lock(mutex_);
    const uint64_t ticket = ++flushRequests_;
    wake_.notify_all();
    flushed_.wait(lock, [&] { return flushesDone_ >= ticket || !running_.load(); });
    return !failed_.load();
}

bool CaptureJournal::close() {
    if (!thread_.joinable()) return !hasError();
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
    running_.store(false);
    flushed_.notify_all();
    writer_->pcapng.close();
    writer_->file.close();
    delete writer_;
    writer_ = nullptr;
    // Closed cleanly: the journal is complete (even after a write error, which was reported).
    QFile::remove(sidecarOf(path_));
    spdlog::info("capture journal closed: {} frames in {}", written_.load(), path_.toStdString());
    return !hasError();
}

QString CaptureJournal::errorString() const {
    std::lock_guard lock(mutex_);
    return error_;
}

// Writes the frames, telling the pager where each chunk of the trace store starts in the file.
bool CaptureJournal::writeBatch(const std::vector<CanFrame>& batch) {
    logio::PcapngWriter& out = writer_->pcapng;
    for (const CanFrame& f : batch) {
        const uint64_t n = out.framesWritten();
        // Every gap before this frame (the adapter may have been lost twice in a row).
        while (!gaps_.empty() && gaps_.front().firstFrame <= n) {
            out.markGap(gaps_.front().lostNs, gaps_.front().backNs);
            gaps_.erase(gaps_.begin());
        }
        if (n > 0 && n % TraceStore::kChunkSize == 0) {
            if (!out.flush()) return false;
            pager_->chunkStarts(n, writer_->file.pos());
        }
        if (!out.write(f)) return false;
    }
    // The header blocks written so far, for the pager to read a chunk alone.
    const auto& blocks = out.headerBlocks();
    for (size_t i = pager_->headerBlocks(); i < blocks.size(); ++i)
        pager_->addHeaderBlock(blocks[i].beforeFrame, blocks[i].bytes, blocks[i].bus);
    return true;
}

void CaptureJournal::run() {
    std::vector<CanFrame> batch;
    auto lastSync = Clock::now();
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait_for(lock, std::chrono::milliseconds(kWriteIntervalMs),
                       [&] { return stop_ || flushRequests_ > flushesDone_; });
        const bool stopping = stop_;
        const uint64_t ticket = flushRequests_;
        batch.clear();
        batch.swap(pending_);
        gaps_.insert(gaps_.end(), pendingGaps_.begin(), pendingGaps_.end());
        pendingGaps_.clear();
        lock.unlock();

        QString why;
        bool ok = !failed_.load();
        if (ok) {
            ok = writeBatch(batch);
            ok = ok && writer_->pcapng.flush();  // to the kernel: survives a killed process
            if (!ok) why = writer_->pcapng.errorString();
            else {
                written_.store(writer_->pcapng.framesWritten());
                pager_->setWritten(writer_->pcapng.framesWritten(), writer_->file.pos());
            }
            const auto now = Clock::now();
            // Synced to the disk at least once a second (a power loss keeps all but the last second).
            if (ok && (stopping || ticket > flushesDone_ ||
                       now - lastSync >= std::chrono::milliseconds(kSyncIntervalMs - kWriteIntervalMs))) {
                ok = syncToDisk(writer_->file.handle(), &why);
                lastSync = now;
            }
        }

        lock.lock();
        if (!ok && !failed_.load()) {
            error_ = why.isEmpty() ? QStringLiteral("write failed") : why;
            failed_.store(true);
            pending_.clear();
            spdlog::error("capture journal {}: {}", path_.toStdString(), error_.toStdString());
        }
        flushesDone_ = ticket;
        flushed_.notify_all();
        if (stopping) break;
    }
}

}  // namespace coscope
