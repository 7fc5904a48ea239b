// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/canopen/PeriodicSender.h"

#include "core/can/CanBus.h"

#include <QtGlobal>

#include <spdlog/spdlog.h>

#include <atomic>
#include <chrono>

#ifdef __linux__
#include <pthread.h>
#include <sys/prctl.h>
#endif

namespace coscope::canopen {

namespace {

// CLOCK_MONOTONIC in ns: libstdc++'s steady_clock is that clock, and condition_variable waits
// on it with an absolute deadline (pthread_cond_clockwait(CLOCK_MONOTONIC), like
// clock_nanosleep(TIMER_ABSTIME)) while staying wakeable when jobs change.
int64_t monotonicNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

std::chrono::steady_clock::time_point monotonicPoint(int64_t ns) {
    return std::chrono::steady_clock::time_point(std::chrono::nanoseconds(ns));
}

int64_t roundPeriod(int64_t ns) {
    const int64_t us = (ns + PeriodicSender::kResolutionNs / 2) / PeriodicSender::kResolutionNs;
    return std::max<int64_t>(1, us) * PeriodicSender::kResolutionNs;
}

}  // namespace

struct PeriodicSender::Entry {
    Job job;
    std::atomic<bool> removed{false};
    bool running = true;
    bool firstDone = false;  // the first send was attempted
    bool failed = false;
    int64_t due = 0;      // next due time, CLOCK_MONOTONIC ns
    int64_t lastDue = 0;  // due time of the last frame sent
    uint64_t sent = 0;
    uint64_t skipped = 0;
    int64_t lastSentNs = 0;
    QString error;
};

PeriodicSender::PeriodicSender(CanBus* bus)
    : PeriodicSender(SendFunction([bus](const CanFrame& f, QString* error) { return bus->send(f, error); })) {}

PeriodicSender::PeriodicSender(SendFunction send) : send_(std::move(send)) {
    thread_ = std::thread([this] { run(); });
}

PeriodicSender::~PeriodicSender() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
    thread_.join();
}

bool PeriodicSender::onSenderThread() const { return std::this_thread::get_id() == thread_.get_id(); }

PeriodicSender::JobId PeriodicSender::add(Job job, QString* error) {
    if (job.periodNs <= 0) {
        if (error) *error = QStringLiteral("the period must be longer than 0");
        return 0;
    }
    job.periodNs = roundPeriod(job.periodNs);
    auto entry = std::make_shared<Entry>();
    entry->job = std::move(job);
    std::unique_lock lock(mutex_);
    if (stopping_) {
        if (error) *error = QStringLiteral("the periodic sender is stopping");
        return 0;
    }
    const JobId id = nextId_++;
    entry->due = monotonicNs();
    jobs_.emplace(id, entry);
    changed_.notify_all();
    if (onSenderThread()) return id;
    changed_.wait(lock, [&] { return entry->firstDone || stopping_ || entry->removed.load(); });
    if (entry->failed || !entry->firstDone) {
        if (error) *error = entry->error.isEmpty() ? QStringLiteral("the periodic sender is stopping") : entry->error;
        entry->removed = true;
        jobs_.erase(id);
        return 0;
    }
    return id;
}

bool PeriodicSender::setPeriod(JobId id, int64_t periodNs) {
    if (periodNs <= 0) return false;
    std::lock_guard lock(mutex_);
    auto it = jobs_.find(id);
    if (it == jobs_.end()) return false;
    Entry& e = *it->second;
    e.job.periodNs = roundPeriod(periodNs);
    if (e.running && e.firstDone) e.due = std::max(monotonicNs(), e.lastDue + e.job.periodNs);
    changed_.notify_all();
    return true;
}

bool PeriodicSender::remove(JobId id) { return take(id).exists; }

PeriodicSender::Status PeriodicSender::take(JobId id) {
    std::unique_lock lock(mutex_);
    auto it = jobs_.find(id);
    if (it == jobs_.end()) return {};
    std::shared_ptr<Entry> e = it->second;
    e->removed = true;
    jobs_.erase(it);
    const bool wait = running_ == id && !onSenderThread();
    changed_.notify_all();
    lock.unlock();
    // The sender holds runMutex_ while the job's callbacks run: once we hold it, they are done,
    // and the job, marked removed, is never run again.
    if (wait) std::lock_guard run(runMutex_);
    lock.lock();
    return statusOf(*e);
}

void PeriodicSender::removeAll() {
    for (JobId id : jobs()) remove(id);
}

PeriodicSender::Status PeriodicSender::status(JobId id) const {
    std::lock_guard lock(mutex_);
    auto it = jobs_.find(id);
    return it == jobs_.end() ? Status{} : statusOf(*it->second);
}

PeriodicSender::Status PeriodicSender::statusOf(const Entry& e) {
    Status s;
    s.exists = true;
    s.running = e.running;
    s.sent = e.sent;
    s.skipped = e.skipped;
    s.periodNs = e.job.periodNs;
    s.lastSentNs = e.lastSentNs;
    s.error = e.error;
    return s;
}

std::vector<PeriodicSender::JobId> PeriodicSender::jobs() const {
    std::lock_guard lock(mutex_);
    std::vector<JobId> out;
    out.reserve(jobs_.size());
    for (const auto& [id, e] : jobs_) out.push_back(id);
    return out;
}

int PeriodicSender::runningCount() const {
    std::lock_guard lock(mutex_);
    int n = 0;
    for (const auto& [id, e] : jobs_) n += e->running ? 1 : 0;
    return n;
}

void PeriodicSender::run() {
#ifdef __linux__
    pthread_setname_np(pthread_self(), "periodic-send");
    // Wake-ups as close to the due time as the kernel allows (the default slack is 50 µs).
    prctl(PR_SET_TIMERSLACK, 1000UL, 0UL, 0UL, 0UL);
    // A low real-time priority where the system allows it (CAP_SYS_NICE or RLIMIT_RTPRIO, e.g.
    // limits.conf "@canusers - rtprio 10"): a busy desktop then delays SYNC by microseconds, not
    // by a time slice. The thread only sleeps and sends, so it cannot starve the others.
    // COSCOPE_NO_REALTIME=1 keeps the normal policy.
    if (!qEnvironmentVariableIsSet("COSCOPE_NO_REALTIME")) {
        sched_param param{};
        param.sched_priority = 10;
        const int rc = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
        if (rc == 0) spdlog::debug("periodic sends run at real-time priority (SCHED_FIFO 10)");
        else spdlog::debug("periodic sends run at normal priority (no real-time permission: {})", rc);
    }
#endif
    std::unique_lock lock(mutex_);
    while (!stopping_) {
        JobId next = 0;
        int64_t due = 0;
        for (const auto& [id, e] : jobs_) {
            if (e->running && (next == 0 || e->due < due)) {
                next = id;
                due = e->due;
            }
        }
        if (next == 0) {
            changed_.wait(lock);
            continue;
        }
        if (due > monotonicNs()) {
            changed_.wait_until(lock, monotonicPoint(due));
            continue;  // the jobs may have changed meanwhile: choose again
        }
        runDue(next, lock);
    }
}

// Sends one due frame of job `id` (mutex_ held on entry and on return; released while the
// job's maker, the send and the callbacks run).
void PeriodicSender::runDue(JobId id, std::unique_lock<std::mutex>& lock) {
    std::shared_ptr<Entry> e = jobs_.at(id);
    running_ = id;
    lock.unlock();
    {
        std::lock_guard run(runMutex_);
        if (!e->removed) {
            const CanFrame frame = e->job.maker ? e->job.maker() : e->job.frame;
            QString error;
            const bool ok = send_(frame, &error);
            const int64_t now = monotonicNs();
            bool finished = false;
            uint64_t sent = 0;
            lock.lock();
            e->firstDone = true;
            if (ok) {
                sent = ++e->sent;
                e->lastSentNs = now;
                e->lastDue = e->due;
            }
            if (!ok) {
                e->running = false;
                e->failed = true;
                e->error = error.isEmpty() ? QStringLiteral("the frame was not sent") : error;
                finished = true;
            } else if (e->job.count && e->sent >= e->job.count) {
                e->running = false;
                finished = true;
            } else {
                // Next due time on the grid start + k x period. Late by a period or more (or so
                // late that the next one would follow within half a period): skip to the next
                // due time in the future rather than sending a burst.
                const int64_t period = e->job.periodNs;
                int64_t next = e->due + period;
                if (next - now < period / 2) {
                    const int64_t k = (now + period / 2 - e->due) / period + 1;
                    e->skipped += static_cast<uint64_t>(k - 1);
                    next = e->due + k * period;
                }
                e->due = next;
            }
            const QString why = e->error;
            lock.unlock();
            changed_.notify_all();  // add() waits for the first send
            if (!ok) spdlog::warn("periodic send of {:X}h stopped: {}", frame.id, why.toStdString());
            if (ok && e->job.afterSend) e->job.afterSend(frame, sent);
            if (finished && e->job.onStopped) e->job.onStopped(why);
        }
    }
    lock.lock();
    running_ = 0;
}

}  // namespace coscope::canopen
