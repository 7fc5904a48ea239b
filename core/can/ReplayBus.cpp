// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/ReplayBus.h"

#include "core/logio/LogFormats.h"

#include <QThread>

#include <chrono>

namespace coscope {

namespace {
int64_t steadyNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}
constexpr size_t kBatch = 256;
constexpr int kMaxReportedDiagnostics = 20;
}  // namespace

ReplayBus::ReplayBus(const BusUrl& url, QObject* parent) : CanBus(url, parent) {}

ReplayBus::~ReplayBus() { stopThread(); }

void ReplayBus::open() {
    stopThread();
    setState(State::Opening);
    QString error;
    // Open once here so an unreadable file is an error right away; the thread reopens per pass.
    auto reader = logio::LogFormats::openReader(url().target, &error);
    if (!reader) {
        setState(State::Error, error);
        return;
    }
    stop_ = false;
    setState(State::Open);
    thread_ = std::thread([this] { run(); });
}

void ReplayBus::close() {
    stopThread();
    setState(State::Closed);
}

void ReplayBus::stopThread() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    if (thread_.joinable()) {
        if (thread_.get_id() == std::this_thread::get_id()) thread_.detach();
        else thread_.join();
    }
}

bool ReplayBus::sendFrame(const CanFrame&, QString* error) {
    if (error) *error = QStringLiteral("replay bus is read-only");
    return false;
}

bool ReplayBus::waitUntil(int64_t dueNs) {
    std::unique_lock lock(mutex_);
    const auto due = std::chrono::steady_clock::time_point(std::chrono::nanoseconds(dueNs));
    wake_.wait_until(lock, due, [this] { return stop_.load(); });
    return !stop_;
}

void ReplayBus::run() {
    const double speed = url().speed();
    const bool loop = url().loop();
    CanFrame batch[kBatch];
    bool firstPass = true;
    int reported = 0;
    for (;;) {
        QString error;
        auto reader = logio::LogFormats::openReader(url().target, &error);
        if (!reader) {
            setState(State::Error, error);
            return;
        }
        bool haveFirst = false;
        int64_t firstLogNs = 0, passWallNs = 0, passSteadyNs = 0;
        uint64_t frames = 0;
        size_t seenDiagnostics = 0;
        while (!stop_) {
            const size_t n = reader->read(batch, kBatch);
            if (firstPass) {
                const auto& diags = reader->diagnostics();
                for (; seenDiagnostics < diags.size(); ++seenDiagnostics) {
                    if (reported++ < kMaxReportedDiagnostics)
                        reportError(QStringLiteral("%1:%2: %3")
                                        .arg(url().target)
                                        .arg(diags[seenDiagnostics].where)
                                        .arg(diags[seenDiagnostics].message));
                }
            }
            if (n == 0) break;
            for (size_t i = 0; i < n && !stop_; ++i) {
                CanFrame f = batch[i];
                if (!haveFirst) {
                    haveFirst = true;
                    firstLogNs = f.timestampNs;
                    passWallNs = nowNs();
                    passSteadyNs = steadyNs();
                }
                const int64_t offset = f.timestampNs - firstLogNs;
                if (speed > 0 && offset > 0) {
                    if (!waitUntil(passSteadyNs + int64_t(double(offset) / speed))) break;
                }
                // Back-pressure instead of drops: a file can wait for its consumer.
                while (pending() > 60000 && !stop_) QThread::usleep(500);
                f.timestampNs = passWallNs + (speed > 0 ? int64_t(double(offset) / speed) : offset);
                deliver(f);
                ++frames;
            }
        }
        if (stop_) return;
        if (reader->hasError()) {
            setState(State::Error, QStringLiteral("%1: %2").arg(url().target, reader->errorString()));
            return;
        }
        firstPass = false;
        if (!loop || frames == 0) break;
    }
    setState(State::Closed, QStringLiteral("replay finished"));
}

}  // namespace coscope
