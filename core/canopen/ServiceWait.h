// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QEventLoop>
#include <QThread>

#include <functional>
#include <memory>
#include <optional>

namespace coscope::canopen {

// For the CLI and tests only (the GUI never waits): processes events of the calling thread
// until `done()` is true or `timeoutMs` passed. Returns done().
inline bool waitUntil(const std::function<bool()>& done, int timeoutMs) {
    QDeadlineTimer deadline(timeoutMs);
    while (!done()) {
        if (deadline.hasExpired()) return done();
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        if (!done()) QThread::usleep(200);
    }
    return true;
}

// Runs an asynchronous request `start(callback)` and waits for its one result (events keep
// being processed). nullopt when no result came within timeoutMs.
template <typename Result>
std::optional<Result> waitForResult(const std::function<void(std::function<void(const Result&)>)>& start,
                                    int timeoutMs) {
    auto out = std::make_shared<std::optional<Result>>();  // outlives a late callback
    start([out](const Result& r) { *out = r; });
    waitUntil([out] { return out->has_value(); }, timeoutMs);
    return *out;
}

}  // namespace coscope::canopen
