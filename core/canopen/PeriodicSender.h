// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanFrame.h"

#include <QString>

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace coscope {
class CanBus;
}

namespace coscope::canopen {

// The one scheduler of the periodic frames of a bus (DESIGN.md "Master services": periodic sends
// are scheduled off the GUI thread and reported to the GUI at most 30 times a second, never as a
// signal per frame). SYNC, the tool's heartbeat and the transmit list's periodic entries are jobs
// here; the GUI and the CLI poll status() instead of receiving a signal per frame.
//
// Timing: one thread of its own. Each job is due at start + k x period on CLOCK_MONOTONIC,
// computed as absolute times (no drift), and the thread waits for the earliest due time with an
// absolute CLOCK_MONOTONIC wait. A job that falls behind (the machine stalled) skips to its next
// due time in the future instead of sending a burst; the skipped due times are counted.
// Frames go out through CanBus::send (thread-safe; listen-only is refused there, in one place).
//
// Thread-safety: every public function may be called from any thread. Job ids are never reused.
// The callbacks of a job (maker, afterSend, onStopped) run on the sender thread, one job at a time;
// they may call status()/setPeriod()/remove() of this sender (remove() of their own job included).
class PeriodicSender {
public:
    using JobId = uint64_t;  // 0 = no job
    // Sends one frame; false with *error when it did not go out.
    using SendFunction = std::function<bool(const CanFrame&, QString*)>;
    // Makes the next frame (e.g. SYNC with its counter); called on the sender thread right
    // before each send.
    using FrameMaker = std::function<CanFrame()>;
    // Runs on the sender thread after each frame that went out (things that go "with each SYNC");
    // `sent` counts the frames of this job so far, this one included.
    using AfterSend = std::function<void(const CanFrame& frame, uint64_t sent)>;
    // Runs on the sender thread once when the job stops by itself: its count was reached (error
    // empty) or a send failed (error says why). Not called for remove().
    using OnStopped = std::function<void(const QString& error)>;

    struct Job {
        CanFrame frame;        // the frame sent each period when `maker` is empty
        FrameMaker maker;      // optional: makes each frame instead of `frame`
        int64_t periodNs = 0;  // > 0; rounded to whole microseconds
        uint64_t count = 0;    // frames to send, then the job stops; 0 = until removed
        AfterSend afterSend;   // optional
        OnStopped onStopped;   // optional
    };

    struct Status {
        bool exists = false;   // false: unknown or removed id
        bool running = false;  // false once stopped (count reached or error) or unknown
        uint64_t sent = 0;     // frames that went out
        uint64_t skipped = 0;  // due times skipped because the sender was late
        int64_t periodNs = 0;
        int64_t lastSentNs = 0;  // CLOCK_MONOTONIC ns of the last send, 0 = none yet
        QString error;           // why the job stopped; empty while running or after its count
    };

    // Sends through bus->send (the bus outlives this sender).
    explicit PeriodicSender(CanBus* bus);
    // Sends through `send` (tests, other sinks).
    explicit PeriodicSender(SendFunction send);
    // Stops the thread; no callback runs after it returns.
    ~PeriodicSender();
    PeriodicSender(const PeriodicSender&) = delete;
    PeriodicSender& operator=(const PeriodicSender&) = delete;

    // Adds a job whose first frame goes out at once (on the sender thread), the next ones every
    // period after that. Returns after that first send attempt: its id, or 0 with *error when the
    // period is not positive or the first send failed (a listen-only bus refuses it; the failed
    // job is not kept). Called from a callback on the sender thread it cannot wait for the first
    // send: it returns the id at once and a failure shows in status().
    JobId add(Job job, QString* error = nullptr);

    // Changes a running job's period (> 0 ns, rounded to µs). The next frame is due one new
    // period after the last one sent (at once if that is already past), then every new period.
    bool setPeriod(JobId id, int64_t periodNs);

    // Removes a job, running or stopped. After it returns none of the job's callbacks is running
    // or will run (except when called from that very callback). False for an unknown id.
    bool remove(JobId id);
    // remove() that also returns the job's last status (exists = false for an unknown id): the
    // final sent count, with no frame between reading it and removing.
    Status take(JobId id);
    void removeAll();

    // A snapshot of a job's state (cheap, for polling at 30 Hz).
    Status status(JobId id) const;
    // Ids of the jobs (running and stopped) in the order they were added.
    std::vector<JobId> jobs() const;
    // How many jobs are running.
    int runningCount() const;

    // Smallest period step (µs resolution).
    static constexpr int64_t kResolutionNs = 1000;

private:
    struct Entry;
    void run();
    void runDue(JobId id, std::unique_lock<std::mutex>& lock);
    bool onSenderThread() const;
    static Status statusOf(const Entry& e);  // mutex_ held

    SendFunction send_;
    mutable std::mutex mutex_;         // guards the jobs and the flags below
    std::condition_variable changed_;  // jobs changed, a first send finished, or stopping
    std::mutex runMutex_;              // held while a job's callbacks run (remove() waits on it)
    std::map<JobId, std::shared_ptr<Entry>> jobs_;
    JobId nextId_ = 1;
    JobId running_ = 0;  // the job whose callbacks run now
    bool stopping_ = false;
    std::thread thread_;
};

}  // namespace coscope::canopen
