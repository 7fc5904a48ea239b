// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/ThreadedCanBus.h"
#include "core/can/SocketcandProtocol.h"

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

    QTcpSocket* socket_ = nullptr;
    QTimer* handshakeTimer_ = nullptr;
    socketcand::MessageSplitter splitter_;
    Phase phase_ = Phase::Idle;
};

}  // namespace coscope
