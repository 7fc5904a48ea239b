// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"
#include "dissectors/PdoText.h"
#include "dissectors/SummaryBuffer.h"

#include <QByteArray>
#include <QStringList>

#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace coscope::cli {

// --format text on a thread of its own: the decoding thread hands over each batch's frames with
// their summaries (PDO summaries as decoded values, their text written here: the two threads
// share the work), warnings and transfer lines; this thread formats the lines with appendText()
// (the same bytes as formatting them in place) and writes them to stdout.
class TextWriter {
public:
    struct Line {
        uint32_t frame = 0;                         // index in Job::frames
        uint32_t summaryAt = 0, summaryLength = 0;  // in Job::summaries
        int warningAt = 0, warningCount = 0;        // in Job::warnings
        int transferAt = 0, transferLength = 0;     // in Job::transfers (appendTransferText)
        int pdoRecord = -1;                         // >= 0: the summary is this record of Job::pdo, written here
    };
    struct Job {
        std::vector<CanFrame> frames;  // the batch (logio::ReadAhead::keepBatch), lines index it
        std::vector<Line> lines;
        dissect::SummaryBuffer summaries;  // the dissectors write here (Dissection::summarySink)
        dissect::PdoTextSink pdo;          // and PDO values here (Dissection::pdoTextSink)
        QStringList warnings;
        QByteArray transfers;
        QStringList busNames;
    };

    TextWriter() : thread_([this] { run(); }) {}
    ~TextWriter() { finish(); }
    TextWriter(const TextWriter&) = delete;
    TextWriter& operator=(const TextWriter&) = delete;

    // An empty job to fill (recycled, so its buffers keep their capacity).
    std::unique_ptr<Job> take() {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return !free_.empty() || created_ < kDepth; });
        if (free_.empty()) {
            ++created_;
            return std::make_unique<Job>();
        }
        auto job = std::move(free_.back());
        free_.pop_back();
        return job;
    }
    void submit(std::unique_ptr<Job> job) {
        std::lock_guard lock(mutex_);
        queue_.push_back(std::move(job));
        changed_.notify_all();
    }
    // Writes what is queued and ends the thread.
    void finish() {
        {
            std::lock_guard lock(mutex_);
            done_ = true;
            changed_.notify_all();
        }
        if (thread_.joinable()) thread_.join();
    }

private:
    static constexpr size_t kDepth = 4;
    void run();

    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<std::unique_ptr<Job>> queue_;
    std::vector<std::unique_ptr<Job>> free_;
    size_t created_ = 0;
    bool done_ = false;
    std::thread thread_;  // last: starts when the rest is ready
};

}  // namespace coscope::cli
