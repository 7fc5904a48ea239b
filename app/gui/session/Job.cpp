// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/gui/session/Job.h"

namespace coscope::gui {

Job::~Job() { stopAndJoin(); }

void Job::start() {
    thread_ = std::thread([this] {
        run();
        progress_.store(1.0, std::memory_order_relaxed);
        done_.store(true, std::memory_order_release);
    });
}

void Job::wait() {
    if (thread_.joinable()) thread_.join();
}

void Job::stopAndJoin() {
    cancel();
    wait();
}

QString Job::errorString() const {
    std::lock_guard lock(mutex_);
    return error_;
}

void Job::fail(const QString& message) {
    std::lock_guard lock(mutex_);
    if (error_.isEmpty()) error_ = message;
}

}  // namespace coscope::gui
