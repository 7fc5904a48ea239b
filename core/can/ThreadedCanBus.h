// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/CanBus.h"

#include <functional>

class QThread;

namespace coscope {

// A bus whose device or socket lives on its own thread (DESIGN.md "Data flow": reading happens
// on its own thread). open() starts the thread and runs startOnThread() there; close() runs
// stopOnThread() there, then ends the thread. Subclasses call close() in their destructor.
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

    // Runs fn on the bus thread and waits for it (directly when already there).
    void runOnBusThread(const std::function<void()>& fn);
    // After a frame went out: queue its copy flagged Tx, stamped now (bus thread only).
    void deliverTxEcho(const CanFrame& frame);

    QThread* thread_ = nullptr;
    QObject* context_ = nullptr;  // lives on thread_; parent of the thread's objects
};

}  // namespace coscope
