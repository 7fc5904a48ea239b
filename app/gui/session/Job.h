// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <atomic>
#include <mutex>
#include <thread>

namespace coscope::gui {

// Long work off the GUI thread (loading, saving, filtering): runs run() on its own thread.
// The GUI polls progress()/isDone() from its refresh timer; nothing is signalled per step.
// cancel() may be called from any thread; the destructor cancels and joins.
class Job {
public:
    explicit Job(QString title) : title_(std::move(title)) {}
    virtual ~Job();
    Job(const Job&) = delete;
    Job& operator=(const Job&) = delete;

    void start();
    void cancel() { cancelled_.store(true, std::memory_order_relaxed); }
    void wait();  // joins the worker (tests, shutdown)

    const QString& title() const { return title_; }
    double progress() const { return progress_.load(std::memory_order_relaxed); }  // 0..1
    bool isDone() const { return done_.load(std::memory_order_acquire); }
    bool isCancelled() const { return cancelled_.load(std::memory_order_relaxed); }
    // Set when the job failed; valid once isDone().
    QString errorString() const;
    bool hasError() const { return !errorString().isEmpty(); }

protected:
    virtual void run() = 0;  // worker thread
    void setProgress(double p) { progress_.store(p, std::memory_order_relaxed); }
    void fail(const QString& message);
    // Derived destructors must call this before their members go away.
    void stopAndJoin();

private:
    QString title_;
    std::thread thread_;
    std::atomic<double> progress_{0.0};
    std::atomic<bool> cancelled_{false};
    std::atomic<bool> done_{false};
    mutable std::mutex mutex_;
    QString error_;
};

}  // namespace coscope::gui
