// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanBus.h"
#include "core/can/ReconnectBackoff.h"

#include <functional>

class QThread;
class QTimer;

namespace coscope {

// A bus whose device or socket lives on its own thread (DESIGN.md "Data flow": reading happens
// on its own thread). open() starts the thread and runs startOnThread() there; close() runs
// stopOnThread() there, then ends the thread. Subclasses call close() in their destructor.
//
// Lost adapter (issue 16): a backend whose open device goes away calls connectionLost(); the
// bus becomes Lost and reopens (stopOnThread() + startOnThread()) after 0.5 s, 1 s, 2 s, ... 8 s
// (ReconnectBackoff) until the backend reports reachedOpen(). Opening failures while Lost only
// schedule the next attempt. close() (the user's Disconnect) ends the retries. Reopening sends
// no frame, so a listen-only bus still never transmits.
class ThreadedCanBus : public CanBus {
    Q_OBJECT
public:
    using CanBus::CanBus;

    void open() override;
    void close() override;

protected:
    virtual QString threadName() const = 0;
    virtual void startOnThread() = 0;  // on the bus thread; owns its objects through context_
    virtual void stopOnThread() = 0;   // on the bus thread

    // Backends report the outcome of startOnThread() and a loss through these (bus thread).
    void reachedOpen();
    void failedToOpen(const QString& message);
    void connectionLost(const QString& message);

    // Runs fn on the bus thread and waits for it (directly when already there).
    void runOnBusThread(const std::function<void()>& fn);
    // After a frame went out: queue its copy flagged Tx, stamped now (bus thread only).
    void deliverTxEcho(const CanFrame& frame);

    QThread* thread_ = nullptr;
    QObject* context_ = nullptr;  // lives on thread_; parent of the thread's objects

private:
    void scheduleRetry();
    void retry();

    ReconnectBackoff backoff_;  // bus thread
    QTimer* retryTimer_ = nullptr;
    bool lost_ = false;  // bus thread: between connectionLost() and reachedOpen()
};

}  // namespace coscope
