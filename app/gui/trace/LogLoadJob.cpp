// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/trace/LogLoadJob.h"

#include "core/logio/LogFormats.h"
#include "core/trace/JournalFolder.h"

#include <QFile>

#include <QFileInfo>

#include <algorithm>
#include <condition_variable>
#include <ctime>
#include <deque>
#include <thread>

#include <spdlog/spdlog.h>

#include <QCoreApplication>

namespace coscope::gui {

LogLoadJob::LogLoadJob(QString path, std::shared_ptr<TraceStore> store, std::vector<CaptureSession::Consumer> consumers,
                       GapHandler onGap)
    : Job(QCoreApplication::translate("LogLoadJob", "Opening %1").arg(QFileInfo(path).fileName())),
      path_(std::move(path)), store_(std::move(store)), consumers_(std::move(consumers)), onGap_(std::move(onGap)) {}

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
        spdlog::warn("opening {} without a spill file, all in memory: {}", path_.toStdString(),
                     spill->errorString().toStdString());
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

namespace {

// One batch read ahead by the parsing thread: its frames and the capture gaps found up to its
// end (CaptureGap::frame counts the frames read from the start of the log).
struct ReadBatch {
    std::vector<CanFrame> frames;
    size_t count = 0;
    std::vector<logio::CaptureGap> gaps;
};

constexpr size_t kBatchFrames = 4096;
constexpr size_t kBatchesAhead = 8;     // bounded: at most this many batches wait for the store
constexpr size_t kHandoffsBehind = 16;  // and this many stored runs of frames for the consumers

// Frames [first, first + count) of the store for the consumers, or a gap before `first`.
struct Handoff {
    FrameNo first = 0;
    size_t count = 0;
    bool isGap = false;
    TraceStore::Gap gap{};
};

double loadThreadCpuSeconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + double(ts.tv_nsec) / 1e9;
}

}  // namespace

void LogLoadJob::noteReaderLocked(const logio::LogReader& reader, size_t& seenDiagnostics) {
    busNames_ = reader.busNames();
    diagnosticCount_ = reader.diagnosticCount();
    const auto& d = reader.diagnostics();
    for (; seenDiagnostics < d.size() && diagnostics_.size() < 100; ++seenDiagnostics) {
        diagnostics_.append(QStringLiteral("%1:%2: %3")
                                .arg(QFileInfo(path_).fileName())
                                .arg(d[seenDiagnostics].where)
                                .arg(d[seenDiagnostics].message));
        problems_.push_back(d[seenDiagnostics]);
    }
    linesRead_ = reader.linesRead();
}

// Three stages overlap, each on a thread of its own (issue 19): parsing, a few batches ahead;
// storing (this thread: the store and the spill); and analysing (the consumers), a few batches
// behind the store. The consumers read the frames from the store, in order, as before.
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
    std::mutex queueMutex;
    std::condition_variable queueChanged;
    std::deque<ReadBatch> ready;            // parsed, waiting for the store
    std::vector<ReadBatch> spare;           // emptied, for the parser to fill again
    bool parsed = false;                    // the parser reached the end (or was cancelled)
    std::deque<Handoff> stored;             // in the store, waiting for the consumers
    bool storing = true;                    // this thread may still add to `stored`
    double parserCpu = 0, analysisCpu = 0;  // seconds, for the log line at the end
    std::thread parser([&] {
        size_t seenDiagnostics = 0;
        size_t seenGaps = 0;
        for (;;) {
            ReadBatch b;
            {
                std::unique_lock lock(queueMutex);
                queueChanged.wait(lock, [&] { return ready.size() < kBatchesAhead; });
                if (!spare.empty()) {
                    b = std::move(spare.back());
                    spare.pop_back();
                }
            }
            if (isCancelled()) reader->cancel();
            b.frames.resize(kBatchFrames);
            b.gaps.clear();
            b.count = reader->read(b.frames.data(), b.frames.size());
            for (const auto& gaps = reader->gaps(); seenGaps < gaps.size(); ++seenGaps)
                b.gaps.push_back(gaps[seenGaps]);
            setProgress(reader->progress());
            {
                std::lock_guard lock(mutex_);
                noteReaderLocked(*reader, seenDiagnostics);
            }
            std::lock_guard lock(queueMutex);
            if (b.count == 0) {
                parsed = true;
                parserCpu = loadThreadCpuSeconds();
                queueChanged.notify_all();
                return;
            }
            ready.push_back(std::move(b));
            queueChanged.notify_all();
        }
    });
    // The consumers see the frames before each gap, the gap (onGap), then the frames after it.
    std::thread analyst([&] {
        for (;;) {
            Handoff h;
            {
                std::unique_lock lock(queueMutex);
                queueChanged.wait(lock, [&] { return !stored.empty() || !storing; });
                if (stored.empty()) break;
                h = stored.front();
                stored.pop_front();
                queueChanged.notify_all();
            }
            if (h.isGap) {
                if (onGap_) onGap_(h.gap);
            } else {
                for (const auto& c : consumers_) c(*store_, h.first, h.count);
            }
        }
        std::lock_guard lock(queueMutex);
        analysisCpu = loadThreadCpuSeconds();
    });
    auto handOff = [&](const Handoff& h) {
        std::unique_lock lock(queueMutex);
        queueChanged.wait(lock, [&] { return stored.size() < kHandoffsBehind; });
        stored.push_back(h);
        queueChanged.notify_all();
    };
    for (;;) {
        if (isCancelled()) reader->cancel();  // thread-safe: the parser's read() returns 0 soon
        ReadBatch b;
        {
            std::unique_lock lock(queueMutex);
            queueChanged.wait(lock, [&] { return !ready.empty() || parsed; });
            if (ready.empty()) break;
            b = std::move(ready.front());
            ready.pop_front();
            queueChanged.notify_all();
        }
        const size_t n = b.count;
        const FrameNo first = static_cast<FrameNo>(store_->size());
        store_->append(std::span<const CanFrame>(b.frames.data(), n));
        FrameNo done = first;
        const FrameNo end = FrameNo(first + n);
        for (const logio::CaptureGap& cg : b.gaps) {
            const TraceStore::Gap g{std::clamp(FrameNo(cg.frame), done, end), cg.lostNs, cg.backNs};
            if (g.firstFrame > done) handOff({done, size_t(g.firstFrame - done)});
            done = g.firstFrame;
            store_->addGap(g);
            handOff({done, 0, true, g});
        }
        if (end > done) handOff({done, size_t(end - done)});
        if (spill_) {
            spill_->appendFromStore(*store_, first, n);
            if (spill_->queuedFrames() > TraceStore::kChunkSize) spill_->flush();  // the disk sets the pace
        } else if (budget_ && !spillFolder_.isEmpty() && store_->memoryBytes() > budget_ / 2) {
            startSpill();
        }
        std::lock_guard lock(queueMutex);
        spare.push_back(std::move(b));
    }
    parser.join();
    {
        std::lock_guard lock(queueMutex);
        storing = false;
        queueChanged.notify_all();
    }
    analyst.join();
    if (spill_) {
        spill_->close();  // all durable: the store evicts down to its budget
        store_->setMemoryBudget(budget_);
    }
    if (reader->hasError()) fail(reader->errorString());
    std::lock_guard lock(mutex_);
    spdlog::info("opened {}: {} frames ({}), {} problems; CPU {:.2f} s parsing, {:.2f} s storing, {:.2f} s analysing",
                 path_.toStdString(), store_->size(), format_.toStdString(), diagnosticCount_, parserCpu,
                 loadThreadCpuSeconds(), analysisCpu);
}

}  // namespace coscope::gui
