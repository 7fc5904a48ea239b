// SPDX-License-Identifier: GPL-3.0-or-later
// Folder core/can/ owns CAN frames and buses: the frame type, bus URLs, the backends (Qt CAN
// plugins, socketcand, replay) reading on their own thread into a lock-free ring, error frames.
// QtCore/QtNetwork/QtSerialBus only, like all of core/.
#pragma once

#include "core/can/BusUrl.h"
#include "core/can/CanErrorFrame.h"
#include "core/can/CanFrame.h"
#include "core/can/FrameRing.h"

#include <QObject>

#include <atomic>
#include <memory>
#include <mutex>

namespace coscope {

// One interface for every way frames come in and go out (DESIGN.md "Data flow"):
// a backend reads on its own thread and pushes into a lock-free ring; consumers drain the ring
// with read(). Nothing per frame crosses a Qt signal: the signals below are for state and errors.
//
// Threading contract for backends:
//  - open()/close() return at once; the outcome is reported through stateChanged/errorOccurred.
//  - deliver() is called from exactly one thread (the backend's reader thread): the ring is SPSC.
//  - sendFrame() may be called from any thread and must be thread-safe (typically it queues the
//    frame to the reader thread). After a frame went out, the backend delivers a copy flagged
//    CanFrame::Tx so traces show both directions.
class CanBus : public QObject {
    Q_OBJECT
public:
    // Lost: the bus was open and its adapter went away (interface deleted or down, socketcand
    // server gone, plugin device/connection error); the backend retries with back-off until it
    // is back (Open) or the user closes it. Frames already read stay in the ring and the trace.
    enum class State { Closed, Opening, Open, Error, Lost };
    Q_ENUM(State)

    struct Counters {
        uint64_t rx = 0;       // frames received and queued
        uint64_t tx = 0;       // frames sent
        uint64_t dropped = 0;  // frames lost because the ring was full
        uint64_t errors = 0;   // error frames and failed sends
        // The controller's fault confinement state and error counters as the last error frame
        // that reported them said (ISO 11898-1 §12.1.4); Unknown / -1 until one did.
        CanErrorReport::BusState controllerState = CanErrorReport::BusState::Unknown;
        int txErrors = -1;
        int rxErrors = -1;
        uint64_t busOffs = 0;  // bus-off reports since the bus opened
    };

    explicit CanBus(const BusUrl& url, QObject* parent = nullptr);
    ~CanBus() override;

    const BusUrl& url() const { return url_; }
    bool isListenOnly() const { return url_.listenOnly(); }

    virtual void open() = 0;
    virtual void close() = 0;

    // Waits until the bus is Open (true) or failed/closed (false), processing events of the
    // calling thread meanwhile; true also when it opened and already closed (a short replay whose
    // frames wait in the ring). For the CLI and tests; the GUI listens to stateChanged instead.
    bool waitForOpen(int timeoutMs);

    // Sends one frame. Listen-only is enforced here, in one place for every backend: a bus opened
    // listen-only refuses every send with an error and transmits nothing.
    bool send(const CanFrame& frame, QString* error = nullptr);

    // Restarts a controller that went bus-off (CiA 301 leaves recovery to the application; Linux
    // SocketCAN needs `ip link set canX type can restart` or restart-ms). False with a reason when
    // the backend cannot (the default).
    virtual bool restartController(QString* error);

    // Consumer side: drains up to `max` frames. Safe from one consumer thread at a time.
    size_t read(CanFrame* out, size_t max);
    // Waits up to timeoutMs for frames to read (processing events of the calling thread).
    bool waitForFrames(int timeoutMs);
    size_t pending() const { return ring_.size(); }

    State state() const;
    QString errorString() const;
    // While Lost: when the adapter went away (ns since the epoch, 0 when not lost) and how long
    // until the next attempt to reopen it (ms, -1 when none is scheduled).
    int64_t lostSinceNs() const { return lostSinceNs_.load(std::memory_order_relaxed); }
    int nextRetryInMs() const;
    Counters counters() const;

signals:
    void stateChanged(coscope::CanBus::State state);
    void errorOccurred(const QString& message);

protected:
    virtual bool sendFrame(const CanFrame& frame, QString* error) = 0;

    // Reader thread: queue a received (or echoed Tx) frame; a full ring counts a drop.
    void deliver(const CanFrame& frame);
    void setState(State state, const QString& error = {});
    void reportError(const QString& message);  // keeps the state, emits errorOccurred
    void countTx() { tx_.fetch_add(1, std::memory_order_relaxed); }
    void countError() { errors_.fetch_add(1, std::memory_order_relaxed); }
    void setLostSince(int64_t ns) { lostSinceNs_.store(ns, std::memory_order_relaxed); }
    void setNextRetryAt(int64_t ns) { nextRetryNs_.store(ns, std::memory_order_relaxed); }  // 0 = none

private:
    BusUrl url_;
    FrameRing ring_;
    mutable std::mutex stateMutex_;
    State state_ = State::Closed;
    bool reachedOpen_ = false;  // since the last Opening: a replay may open and finish before anyone looks
    QString error_;
    std::atomic<uint64_t> rx_{0};
    std::atomic<uint64_t> tx_{0};
    std::atomic<uint64_t> errors_{0};
    std::atomic<uint8_t> controllerState_{0};
    std::atomic<int> txErrors_{-1};
    std::atomic<int> rxErrors_{-1};
    std::atomic<uint64_t> busOffs_{0};
    std::atomic<int64_t> lostSinceNs_{0};
    std::atomic<int64_t> nextRetryNs_{0};
};

// Creates the backend for a URL (not yet opened). Returns nullptr with a one-line reason.
std::unique_ptr<CanBus> createBus(const BusUrl& url, QString* error);
std::unique_ptr<CanBus> createBus(const QString& text, QString* error);

QString toString(CanBus::State state);

// Nanoseconds since the Unix epoch, the timestamp of live frames.
int64_t nowNs();

}  // namespace coscope
