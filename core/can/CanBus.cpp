// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/CanBus.h"

#include "core/can/QtCanBus.h"
#include "core/can/ReplayBus.h"
#include "core/can/SocketcandBus.h"
#include "core/sim/SimBus.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QThread>

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>

namespace coscope {

CanBus::CanBus(const BusUrl& url, QObject* parent) : QObject(parent), url_(url) {}

CanBus::~CanBus() = default;

bool CanBus::waitForOpen(int timeoutMs) {
    QDeadlineTimer deadline(timeoutMs);
    for (;;) {
        State s;
        bool reachedOpen = false;
        {
            std::lock_guard lock(stateMutex_);
            s = state_;
            reachedOpen = reachedOpen_;
        }
        if (s == State::Open) return true;
        // Opened and already closed again (a short replay): what it delivered is in the ring.
        if (s == State::Closed && reachedOpen) return true;
        // Closed right after open() means the backend has not started yet; give it the time.
        // Lost means it is reconnecting: wait for it as well.
        if (s == State::Error) return false;
        if (deadline.hasExpired()) return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        QThread::msleep(2);
    }
}

bool CanBus::send(const CanFrame& frame, QString* error) {
    if (isListenOnly()) {
        const QString why = QStringLiteral("bus %1 is listen-only: sending is refused").arg(url_.toString());
        if (error) *error = why;
        spdlog::info("{}", why.toStdString());
        return false;
    }
    if (state() != State::Open) {
        if (error) *error = QStringLiteral("bus %1 is not open (%2)").arg(url_.toString(), toString(state()));
        return false;
    }
    QString why;
    if (!sendFrame(frame, &why)) {
        countError();
        if (error) *error = why;
        return false;
    }
    return true;
}

size_t CanBus::read(CanFrame* out, size_t max) { return ring_.pop(out, max); }

bool CanBus::waitForFrames(int timeoutMs) {
    QDeadlineTimer deadline(timeoutMs);
    while (ring_.size() == 0) {
        if (deadline.hasExpired()) return false;
        QCoreApplication::processEvents(QEventLoop::AllEvents, 2);
        if (ring_.size() == 0) QThread::usleep(500);
    }
    return true;
}

CanBus::State CanBus::state() const {
    std::lock_guard lock(stateMutex_);
    return state_;
}

QString CanBus::errorString() const {
    std::lock_guard lock(stateMutex_);
    return error_;
}

int CanBus::nextRetryInMs() const {
    const int64_t at = nextRetryNs_.load(std::memory_order_relaxed);
    if (at == 0) return -1;
    return static_cast<int>(std::max<int64_t>(0, (at - nowNs()) / 1'000'000));
}

CanBus::Counters CanBus::counters() const {
    Counters c;
    c.rx = rx_.load(std::memory_order_relaxed);
    c.tx = tx_.load(std::memory_order_relaxed);
    c.dropped = ring_.dropped();
    c.errors = errors_.load(std::memory_order_relaxed);
    c.controllerState = static_cast<CanErrorReport::BusState>(controllerState_.load(std::memory_order_relaxed));
    c.txErrors = txErrors_.load(std::memory_order_relaxed);
    c.rxErrors = rxErrors_.load(std::memory_order_relaxed);
    c.busOffs = busOffs_.load(std::memory_order_relaxed);
    return c;
}

void CanBus::deliver(const CanFrame& frame) {
    if (frame.isTx()) countTx();
    if (frame.isError()) {
        countError();
        const CanErrorReport e = decodeCanError(frame);
        if (e.state != CanErrorReport::BusState::Unknown)
            controllerState_.store(static_cast<uint8_t>(e.state), std::memory_order_relaxed);
        if (e.state == CanErrorReport::BusState::BusOff) busOffs_.fetch_add(1, std::memory_order_relaxed);
        if (e.txErrors) txErrors_.store(*e.txErrors, std::memory_order_relaxed);
        if (e.rxErrors) rxErrors_.store(*e.rxErrors, std::memory_order_relaxed);
    }
    if (ring_.push(frame)) rx_.fetch_add(1, std::memory_order_relaxed);
}

void CanBus::setState(State state, const QString& error) {
    bool changed = false;
    {
        std::lock_guard lock(stateMutex_);
        changed = state_ != state;
        state_ = state;
        if (state == State::Opening) reachedOpen_ = false;
        if (state == State::Open) reachedOpen_ = true;
        if (!error.isEmpty()) error_ = error;
        else if (state == State::Open) error_.clear();
    }
    if ((state == State::Error || state == State::Lost) && !error.isEmpty()) {
        spdlog::warn("{}: {}", url_.toString().toStdString(), error.toStdString());
        emit errorOccurred(error);
    }
    if (changed) emit stateChanged(state);
}

bool CanBus::restartController(QString* error) {
    if (error) *error = QStringLiteral("%1 cannot restart its controller").arg(url_.toString());
    return false;
}

void CanBus::reportError(const QString& message) {
    {
        std::lock_guard lock(stateMutex_);
        error_ = message;
    }
    spdlog::warn("{}: {}", url_.toString().toStdString(), message.toStdString());
    emit errorOccurred(message);
}

std::unique_ptr<CanBus> createBus(const BusUrl& url, QString* error) {
    if (url.scheme == u"socketcand") return std::make_unique<SocketcandBus>(url);
    if (url.scheme == u"sim") return std::make_unique<SimBus>(url);
    if (url.scheme == u"replay") return std::make_unique<ReplayBus>(url);
    if (!qtCanPlugins().contains(url.scheme)) {
        if (error)
            *error = QStringLiteral("Qt CAN plugin '%1' is not installed here; available: %2")
                         .arg(url.scheme, qtCanPlugins().join(QStringLiteral(", ")));
        return nullptr;
    }
    return std::make_unique<QtCanBus>(url);
}

std::unique_ptr<CanBus> createBus(const QString& text, QString* error) {
    auto url = BusUrl::parse(text, error);
    if (!url) return nullptr;
    return createBus(*url, error);
}

QString toString(CanBus::State state) {
    switch (state) {
    case CanBus::State::Closed: return QStringLiteral("closed");
    case CanBus::State::Opening: return QStringLiteral("opening");
    case CanBus::State::Open: return QStringLiteral("open");
    case CanBus::State::Error: return QStringLiteral("error");
    case CanBus::State::Lost: return QStringLiteral("lost");
    }
    return {};
}

int64_t nowNs() {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
        .count();
}

}  // namespace coscope
