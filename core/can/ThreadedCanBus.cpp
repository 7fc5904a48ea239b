// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/ThreadedCanBus.h"

#include <QThread>

namespace coscope {

void ThreadedCanBus::open() {
    if (thread_) return;  // already opening or open
    setState(State::Opening);
    thread_ = new QThread;
    thread_->setObjectName(threadName());
    context_ = new QObject;
    context_->moveToThread(thread_);
    thread_->start();
    QMetaObject::invokeMethod(context_, [this] { startOnThread(); }, Qt::QueuedConnection);
}

void ThreadedCanBus::close() {
    if (!thread_) {
        if (state() != State::Closed) setState(State::Closed);
        return;
    }
    QMetaObject::invokeMethod(context_, [this] { stopOnThread(); }, Qt::BlockingQueuedConnection);
    thread_->quit();
    thread_->wait();
    delete context_;
    context_ = nullptr;
    delete thread_;
    thread_ = nullptr;
    setState(State::Closed);  // errorString() keeps the last failure
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
