// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/ThreadedCanBus.h"

#include <QThread>
#include <QTimer>

#include <spdlog/spdlog.h>

namespace coscope {

void ThreadedCanBus::open() {
    if (thread_) return;  // already opening or open
    setState(State::Opening);
    thread_ = new QThread;
    thread_->setObjectName(threadName());
    context_ = new QObject;
    context_->moveToThread(thread_);
    thread_->start();
    QMetaObject::invokeMethod(
        context_, [this] { startOnThread(); }, Qt::QueuedConnection);
}

void ThreadedCanBus::close() {
    if (!thread_) {
        if (state() != State::Closed) setState(State::Closed);
        return;
    }
    QMetaObject::invokeMethod(
        context_,
        [this] {
            delete retryTimer_;  // the user's Disconnect ends the retries
            retryTimer_ = nullptr;
            lost_ = false;
            backoff_.reset();
            stopOnThread();
        },
        Qt::BlockingQueuedConnection);
    thread_->quit();
    thread_->wait();
    delete context_;
    context_ = nullptr;
    delete thread_;
    thread_ = nullptr;
    setLostSince(0);
    setNextRetryAt(0);
    setState(State::Closed);  // errorString() keeps the last failure
}

void ThreadedCanBus::reachedOpen() {
    if (lost_) {
        const double gapS = static_cast<double>(nowNs() - lostSinceNs()) / 1e9;
        spdlog::info("{}: adapter back after {:.1f} s ({} attempts)", url().toString().toStdString(), gapS,
                     backoff_.attempts());
        lost_ = false;
    }
    backoff_.reset();
    setNextRetryAt(0);
    setState(State::Open);
    setLostSince(0);
}

void ThreadedCanBus::failedToOpen(const QString& message) {
    if (!lost_) {
        setState(State::Error, message);
        return;
    }
    spdlog::debug("{}: still lost: {}", url().toString().toStdString(), message.toStdString());
    scheduleRetry();
}

void ThreadedCanBus::connectionLost(const QString& message) {
    if (lost_) {  // a failure of a reopened connection before it was confirmed
        scheduleRetry();
        return;
    }
    lost_ = true;
    backoff_.reset();
    setLostSince(nowNs());
    scheduleRetry();
    setState(State::Lost, message);
}

void ThreadedCanBus::scheduleRetry() {
    if (!retryTimer_) {
        retryTimer_ = new QTimer(context_);
        retryTimer_->setSingleShot(true);
        QObject::connect(retryTimer_, &QTimer::timeout, context_, [this] { retry(); });
    }
    const int waitMs = backoff_.next();
    setNextRetryAt(nowNs() + int64_t{waitMs} * 1'000'000);
    spdlog::info("{}: adapter lost, retrying in {:.1f} s", url().toString().toStdString(), waitMs / 1000.0);
    retryTimer_->start(waitMs);
}

void ThreadedCanBus::retry() {
    if (!lost_) return;
    setNextRetryAt(0);
    stopOnThread();
    startOnThread();
}

void ThreadedCanBus::runOnBusThread(const std::function<void()>& fn) {
    if (QThread::currentThread() == thread_) fn();
    else QMetaObject::invokeMethod(context_, fn, Qt::BlockingQueuedConnection);
}

void ThreadedCanBus::deliverTxEcho(const CanFrame& frame) {
    CanFrame echo = frame;
    echo.flags |= CanFrame::Tx;
    echo.timestampNs = nowNs();
    deliver(echo);
}

}  // namespace coscope
