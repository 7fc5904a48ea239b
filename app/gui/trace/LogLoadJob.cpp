// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/trace/LogLoadJob.h"

#include "core/logio/LogFormats.h"
#include "core/trace/JournalFolder.h"

#include <QFile>

#include <QFileInfo>

#include <algorithm>

#include <spdlog/spdlog.h>

#include <QCoreApplication>

namespace coscope::gui {

LogLoadJob::LogLoadJob(QString path, std::shared_ptr<TraceStore> store, std::vector<CaptureSession::Consumer> consumers, GapHandler onGap)
    : Job(QCoreApplication::translate("LogLoadJob", "Opening %1").arg(QFileInfo(path).fileName())),
      path_(std::move(path)),
      store_(std::move(store)),
      consumers_(std::move(consumers)),
      onGap_(std::move(onGap)) {}

LogLoadJob::~LogLoadJob() {
    stopAndJoin();
    if (spill_) {
        spill_->close();
        QFile::remove(spill_->path());
    }
}

void LogLoadJob::setSpill(QString folder, size_t budget) {
    spillFolder_ = std::move(folder);
    budget_ = budget;
}

QString LogLoadJob::spillPath() const {
    std::lock_guard lock(mutex_);
    return spillPath_;
}

// The frames read so far go to the spill first, a chunk at a time (never a copy of them all in
// the queue), then the store pages from it.
void LogLoadJob::startSpill() {
    const QString path = journals::newJournalPath(spillFolder_, QFileInfo(path_).fileName());
    auto spill = std::make_unique<CaptureJournal>();
    if (path.isEmpty() || !spill->open(path, {})) {
        spdlog::warn("opening {} without a spill file, all in memory: {}", path_.toStdString(), spill->errorString().toStdString());
        spillFolder_.clear();
        return;
    }
    const size_t size = store_->size();
    for (size_t first = 0; first < size; first += TraceStore::kChunkSize) {
        spill->appendFromStore(*store_, FrameNo(first), std::min<size_t>(TraceStore::kChunkSize, size - first));
        spill->flush();
    }
    store_->setPager(spill->pager());
    store_->setMemoryBudget(budget_);
    spill_ = std::move(spill);
    std::lock_guard lock(mutex_);
    spillPath_ = path;
}

QString LogLoadJob::formatName() const {
    std::lock_guard lock(mutex_);
    return format_;
}

QStringList LogLoadJob::busNames() const {
    std::lock_guard lock(mutex_);
    return busNames_;
}

uint64_t LogLoadJob::diagnosticCount() const {
    std::lock_guard lock(mutex_);
    return diagnosticCount_;
}

QStringList LogLoadJob::diagnostics(int max) const {
    std::lock_guard lock(mutex_);
    return diagnostics_.mid(0, max);
}

std::vector<logio::LogDiagnostic> LogLoadJob::firstProblems(int max) const {
    std::lock_guard lock(mutex_);
    return {problems_.begin(), problems_.begin() + std::min<ptrdiff_t>(max, ptrdiff_t(problems_.size()))};
}

int64_t LogLoadJob::linesRead() const {
    std::lock_guard lock(mutex_);
    return linesRead_;
}

void LogLoadJob::run() {
    QString error;
    auto reader = logio::LogFormats::openReader(path_, &error);
    if (!reader) {
        fail(error.isEmpty() ? QCoreApplication::translate("LogLoadJob", "%1: cannot open").arg(path_) : error);
        return;
    }
    {
        std::lock_guard lock(mutex_);
        format_ = reader->formatName();
    }
    std::vector<CanFrame> batch(4096);
    size_t seenDiagnostics = 0;
    size_t seenGaps = 0;
    for (;;) {
        if (isCancelled()) reader->cancel();
        const size_t n = reader->read(batch.data(), batch.size());
        if (n == 0) break;
        const FrameNo first = static_cast<FrameNo>(store_->size());
        store_->append(std::span<const CanFrame>(batch.data(), n));
        // The consumers see the frames before each gap, the gap, then the frames after it.
        FrameNo done = first;
        const FrameNo end = FrameNo(first + n);
        for (const auto& gaps = reader->gaps(); seenGaps < gaps.size(); ++seenGaps) {
            const TraceStore::Gap g{std::clamp(FrameNo(gaps[seenGaps].frame), done, end), gaps[seenGaps].lostNs, gaps[seenGaps].backNs};
            if (g.firstFrame > done)
                for (const auto& c : consumers_) c(*store_, done, g.firstFrame - done);
            done = g.firstFrame;
            store_->addGap(g);
            if (onGap_) onGap_(g);
        }
        if (end > done)
            for (const auto& c : consumers_) c(*store_, done, end - done);
        if (spill_) {
            spill_->appendFromStore(*store_, first, n);
            if (spill_->queuedFrames() > TraceStore::kChunkSize) spill_->flush();  // the disk sets the pace
        } else if (budget_ && !spillFolder_.isEmpty() && store_->memoryBytes() > budget_ / 2) {
            startSpill();
        }
        setProgress(reader->progress());
        std::lock_guard lock(mutex_);
        busNames_ = reader->busNames();
        diagnosticCount_ = reader->diagnosticCount();
        const auto& d = reader->diagnostics();
        for (; seenDiagnostics < d.size() && diagnostics_.size() < 100; ++seenDiagnostics) {
            diagnostics_.append(QStringLiteral("%1:%2: %3").arg(QFileInfo(path_).fileName()).arg(d[seenDiagnostics].where).arg(d[seenDiagnostics].message));
            problems_.push_back(d[seenDiagnostics]);
        }
        linesRead_ = reader->linesRead();
    }
    if (spill_) {
        spill_->close();  // all durable: the store evicts down to its budget
        store_->setMemoryBudget(budget_);
    }
    std::lock_guard lock(mutex_);
    busNames_ = reader->busNames();
    diagnosticCount_ = reader->diagnosticCount();
    const auto& d = reader->diagnostics();
    for (; seenDiagnostics < d.size() && diagnostics_.size() < 100; ++seenDiagnostics) {
        diagnostics_.append(QStringLiteral("%1:%2: %3").arg(QFileInfo(path_).fileName()).arg(d[seenDiagnostics].where).arg(d[seenDiagnostics].message));
        problems_.push_back(d[seenDiagnostics]);
    }
    linesRead_ = reader->linesRead();
    if (reader->hasError()) fail(reader->errorString());
    spdlog::info("opened {}: {} frames ({}), {} problems", path_.toStdString(), store_->size(), format_.toStdString(), diagnosticCount_);
}

}  // namespace coscope::gui
