// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/SocketcandProtocol.h"
#include "core/can/ThreadedCanBus.h"

#include <QByteArray>

#include <mutex>

class QThread;
class QTcpSocket;
class QTimer;

namespace coscope {

// socketcand://HOST:PORT/CHANNEL — a remote CAN interface served by socketcand
// (linux-can/socketcand, doc/protocol.md) in raw mode. The TCP socket lives on its own thread:
// frames are decoded there and go into the ring; nothing per frame crosses a signal.
// open(): connect, wait for "< hi >", "< open CHANNEL >" -> "< ok >", "< rawmode >" -> "< ok >".
// Any failure before that (refused, unreachable, no greeting, refusal) puts the bus in Error
// within kHandshakeTimeoutMs with a message naming HOST:PORT.
// Sending (issue 35, jitter of periodic frames): once raw mode is reached, "< send >" is
// written to the socket by the sending thread itself (the periodic sender wakes and the frame
// leaves, with no second thread to wake); what the kernel does not take at once queues, in
// order, through the socket thread. Our own frames' copies (Tx) go into the ring at the same
// moment, before any answer to them can arrive.
class SocketcandBus : public ThreadedCanBus {
    Q_OBJECT
public:
    static constexpr int kHandshakeTimeoutMs = 3000;

    explicit SocketcandBus(const BusUrl& url, QObject* parent = nullptr);
    ~SocketcandBus() override;

protected:
    bool sendFrame(const CanFrame& frame, QString* error) override;

private:
    enum class Phase { Idle, Connecting, WaitHi, WaitOpenOk, WaitRawOk, Raw, Closing };

    // All of these run on the socket thread.
    QString threadName() const override;
    void startOnThread() override;
    void stopOnThread() override;
    void onConnected();
    void onReadyRead();
    void onSocketError();
    void onDisconnected();
    void onHandshakeTimeout();
    void handle(const socketcand::Message& message);
    void fail(const QString& message);
    QString where() const;
    void startDirectSends();  // raw mode reached
    void stopDirectSends();   // leaving raw mode; what is queued goes to the socket
    void drainBacklog();      // socket thread: queued sends into QTcpSocket, in order
    void onBytesWritten();
    void deliverFrame(CanFrame frame, bool ours);  // any thread: one producer at a time

    QTcpSocket* socket_ = nullptr;
    QTimer* handshakeTimer_ = nullptr;
    socketcand::MessageSplitter splitter_;
    Phase phase_ = Phase::Idle;

    std::mutex sendMutex_;         // guards the three below
    int directFd_ = -1;            // the raw-mode socket, or -1
    QByteArray backlog_;           // sends the kernel did not take yet, waiting for the socket thread
    bool queuedInSocket_ = false;  // QTcpSocket still holds bytes: direct writes would overtake them
    bool drainPosted_ = false;
    std::mutex deliverMutex_;  // the ring has one producer: the socket thread or a sender
};

}  // namespace coscope
