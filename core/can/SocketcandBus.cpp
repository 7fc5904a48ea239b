// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/SocketcandBus.h"

#include <QTcpSocket>
#include <QThread>
#include <QTimer>

#include <spdlog/spdlog.h>

#include <sys/socket.h>
#include <cerrno>
#include <cstring>

namespace coscope {

using socketcand::Message;

SocketcandBus::SocketcandBus(const BusUrl& url, QObject* parent) : ThreadedCanBus(url, parent) {}

SocketcandBus::~SocketcandBus() { close(); }

QString SocketcandBus::where() const {
    const QString host = url().host.contains(u':') ? u'[' + url().host + u']' : url().host;
    return QStringLiteral("%1:%2").arg(host).arg(url().port);
}

QString SocketcandBus::threadName() const { return QStringLiteral("socketcand"); }

void SocketcandBus::startOnThread() {
    splitter_ = {};
    socket_ = new QTcpSocket(context_);
    handshakeTimer_ = new QTimer(context_);
    handshakeTimer_->setSingleShot(true);
    QObject::connect(handshakeTimer_, &QTimer::timeout, context_, [this] { onHandshakeTimeout(); });
    QObject::connect(socket_, &QTcpSocket::connected, context_, [this] { onConnected(); });
    QObject::connect(socket_, &QTcpSocket::readyRead, context_, [this] { onReadyRead(); });
    QObject::connect(socket_, &QTcpSocket::errorOccurred, context_, [this] { onSocketError(); });
    QObject::connect(socket_, &QTcpSocket::disconnected, context_, [this] { onDisconnected(); });
    QObject::connect(socket_, &QTcpSocket::bytesWritten, context_, [this] { onBytesWritten(); });
    phase_ = Phase::Connecting;
    handshakeTimer_->start(kHandshakeTimeoutMs);
    spdlog::debug("socketcand: connecting to {} channel {}", where().toStdString(), url().channel.toStdString());
    socket_->connectToHost(url().host, url().port);
}

void SocketcandBus::stopOnThread() {
    phase_ = Phase::Closing;
    if (handshakeTimer_) handshakeTimer_->stop();
    stopDirectSends();
    if (socket_) {
        QObject::disconnect(socket_, nullptr, context_, nullptr);
        // Let queued "< send >" commands leave before the connection goes.
        if (socket_->state() == QAbstractSocket::ConnectedState && socket_->bytesToWrite() > 0)
            socket_->waitForBytesWritten(500);
        socket_->abort();
        delete socket_;
        socket_ = nullptr;
    }
    delete handshakeTimer_;
    handshakeTimer_ = nullptr;
    phase_ = Phase::Idle;
}

void SocketcandBus::fail(const QString& message) {
    if (phase_ == Phase::Idle || phase_ == Phase::Closing) return;
    const bool wasOpen = phase_ == Phase::Raw;
    phase_ = Phase::Idle;
    if (handshakeTimer_) handshakeTimer_->stop();
    {
        std::lock_guard lock(sendMutex_);
        directFd_ = -1;
        backlog_.clear();  // the connection is gone: nothing of it can leave any more
    }
    if (socket_) {
        QObject::disconnect(socket_, nullptr, context_, nullptr);
        socket_->abort();
        socket_->deleteLater();
        socket_ = nullptr;
    }
    // An open connection that drops is a lost adapter: reconnect with back-off (ThreadedCanBus).
    if (wasOpen) connectionLost(message);
    else failedToOpen(message);
}

void SocketcandBus::onConnected() {
    phase_ = Phase::WaitHi;
    // Each "< send >" goes out at once (TCP_NODELAY): with Nagle a frame waits for the server's
    // delayed ACK of the previous one, and periodic frames (SYNC at 10 ms) arrive in pairs,
    // up to 40 ms late (issue 35, measured by tests/bench/bench_master_jitter).
    socket_->setSocketOption(QAbstractSocket::LowDelayOption, 1);
    spdlog::debug("socketcand: connected to {}", where().toStdString());
}

void SocketcandBus::onReadyRead() {
    if (!socket_) return;
    splitter_.feed(socket_->readAll());
    for (;;) {
        QString discarded;
        auto raw = splitter_.next(&discarded);
        if (!discarded.isEmpty()) {
            countError();
            spdlog::warn("socketcand {}: {}", where().toStdString(), discarded.toStdString());
        }
        if (!raw) break;
        QString why;
        auto message = socketcand::parseMessage(*raw, &why);
        if (!message) {
            countError();
            spdlog::warn("socketcand {}: {}", where().toStdString(), why.toStdString());
            continue;
        }
        handle(*message);
        if (!socket_) break;  // failed while handling
    }
}

void SocketcandBus::handle(const Message& m) {
    const QString channel = url().channel;
    switch (phase_) {
    case Phase::Connecting:  // data before connected() cannot happen; treat as greeting phase
    case Phase::WaitHi:
        if (m.kind == Message::Kind::Hi) {
            phase_ = Phase::WaitOpenOk;
            socket_->write(socketcand::encodeOpen(channel));
        } else if (m.kind == Message::Kind::Error) {
            fail(QStringLiteral("socketcand at %1 refused the connection: %2").arg(where(), m.text));
        } else {
            fail(QStringLiteral("socketcand at %1 sent '%2' instead of the '< hi >' greeting").arg(where(), m.word));
        }
        return;
    case Phase::WaitOpenOk:
        if (m.kind == Message::Kind::Ok) {
            phase_ = Phase::WaitRawOk;
            socket_->write(socketcand::encodeRawMode());
        } else if (m.kind == Message::Kind::Error) {
            fail(QStringLiteral("socketcand at %1 cannot open channel '%2': %3").arg(where(), channel, m.text));
        } else {
            fail(QStringLiteral("socketcand at %1 answered '%2' to '< open %3 >'").arg(where(), m.word, channel));
        }
        return;
    case Phase::WaitRawOk:
        if (m.kind == Message::Kind::Ok) {
            phase_ = Phase::Raw;
            handshakeTimer_->stop();
            startDirectSends();
            reachedOpen();
        } else if (m.kind == Message::Kind::Error) {
            fail(QStringLiteral("socketcand at %1 refused raw mode: %2").arg(where(), m.text));
        } else {
            fail(QStringLiteral("socketcand at %1 answered '%2' to '< rawmode >'").arg(where(), m.word));
        }
        return;
    case Phase::Raw:
        if (m.kind == Message::Kind::Frame) {
            deliverFrame(m.frame, false);
        } else if (m.kind == Message::Kind::Error) {
            // e.g. "< error unknown command >" after a command the server does not support
            countError();
            reportError(QStringLiteral("socketcand at %1: %2").arg(where(), m.text));
        }
        return;  // ok/echo and the like need nothing
    case Phase::Idle:
    case Phase::Closing: return;
    }
}

void SocketcandBus::onSocketError() {
    if (!socket_ || phase_ == Phase::Idle || phase_ == Phase::Closing) return;
    const auto error = socket_->error();
    if (error == QAbstractSocket::RemoteHostClosedError) {
        onDisconnected();
        return;
    }
    QString reason;
    switch (error) {
    case QAbstractSocket::ConnectionRefusedError: reason = QStringLiteral("connection refused"); break;
    case QAbstractSocket::HostNotFoundError: reason = QStringLiteral("host not found"); break;
    case QAbstractSocket::SocketTimeoutError: reason = QStringLiteral("timed out"); break;
    case QAbstractSocket::NetworkError:
        reason = QStringLiteral("network error (%1)").arg(socket_->errorString());
        break;
    default: reason = socket_->errorString(); break;
    }
    if (phase_ == Phase::Connecting) fail(QStringLiteral("cannot reach socketcand at %1: %2").arg(where(), reason));
    else fail(QStringLiteral("connection to socketcand at %1 lost: %2").arg(where(), reason));
}

void SocketcandBus::onDisconnected() {
    switch (phase_) {
    case Phase::Raw: fail(QStringLiteral("socketcand server at %1 closed the connection").arg(where())); return;
    case Phase::Connecting:
    case Phase::WaitHi:
    case Phase::WaitOpenOk:
    case Phase::WaitRawOk:
        fail(QStringLiteral("socketcand at %1 closed the connection during the handshake (channel '%2')")
                 .arg(where(), url().channel));
        return;
    case Phase::Idle:
    case Phase::Closing: return;
    }
}

void SocketcandBus::onHandshakeTimeout() {
    const QString s = QString::number(kHandshakeTimeoutMs / 1000.0);
    switch (phase_) {
    case Phase::Connecting:
        fail(QStringLiteral("cannot reach socketcand at %1: no answer within %2 s").arg(where(), s));
        return;
    case Phase::WaitHi:
        fail(QStringLiteral("socketcand at %1 did not greet with '< hi >' within %2 s").arg(where(), s));
        return;
    case Phase::WaitOpenOk:
        fail(
            QStringLiteral("socketcand at %1 did not answer '< open %2 >' within %3 s").arg(where(), url().channel, s));
        return;
    case Phase::WaitRawOk:
        fail(QStringLiteral("socketcand at %1 did not answer '< rawmode >' within %2 s").arg(where(), s));
        return;
    case Phase::Raw:
    case Phase::Idle:
    case Phase::Closing: return;
    }
}

void SocketcandBus::deliverFrame(CanFrame frame, bool ours) {
    std::lock_guard lock(deliverMutex_);
    if (ours) frame.flags |= CanFrame::Tx;
    // Stamped under the lock, so the ring's times never go backwards between producers.
    if (ours || frame.timestampNs == 0) frame.timestampNs = nowNs();
    deliver(frame);
}

void SocketcandBus::startDirectSends() {
    socket_->flush();  // the handshake's commands are out
    std::lock_guard lock(sendMutex_);
    directFd_ = static_cast<int>(socket_->socketDescriptor());
    backlog_.clear();
    queuedInSocket_ = socket_->bytesToWrite() > 0;
}

void SocketcandBus::stopDirectSends() {
    QByteArray rest;
    {
        std::lock_guard lock(sendMutex_);
        directFd_ = -1;
        rest.swap(backlog_);
    }
    if (socket_ && !rest.isEmpty() && socket_->state() == QAbstractSocket::ConnectedState) socket_->write(rest);
}

void SocketcandBus::drainBacklog() {
    QByteArray rest;
    {
        std::lock_guard lock(sendMutex_);
        drainPosted_ = false;
        if (directFd_ < 0) return;  // closed meanwhile; stopOnThread() took the backlog
        rest.swap(backlog_);
        if (!rest.isEmpty()) queuedInSocket_ = true;
    }
    if (socket_ && !rest.isEmpty()) {
        socket_->write(rest);
        socket_->flush();
    }
    onBytesWritten();
}

void SocketcandBus::onBytesWritten() {
    if (!socket_ || socket_->bytesToWrite() > 0) return;
    std::lock_guard lock(sendMutex_);
    if (backlog_.isEmpty()) queuedInSocket_ = false;  // nothing left to overtake
}

bool SocketcandBus::sendFrame(const CanFrame& frame, QString* error) {
    if (frame.isError()) {
        if (error) *error = QStringLiteral("error frames cannot be sent");
        return false;
    }
    const QByteArray line = socketcand::encodeSend(frame);
    {
        std::unique_lock lock(sendMutex_);
        if (directFd_ >= 0) {
            if (!queuedInSocket_ && backlog_.isEmpty()) {
                const ssize_t n = ::send(directFd_, line.constData(), size_t(line.size()), MSG_NOSIGNAL | MSG_DONTWAIT);
                if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK) {
                    const int e = errno;
                    lock.unlock();
                    if (error)
                        *error = QStringLiteral("cannot write to socketcand at %1: %2")
                                     .arg(where(), QString::fromLocal8Bit(std::strerror(e)));
                    return false;
                }
                if (n < line.size()) backlog_ = line.mid(n < 0 ? 0 : n);
            } else {
                backlog_ += line;
            }
            // socketcand's raw socket does not echo our own frames: record the Tx copy here.
            deliverFrame(frame, true);
            if (!backlog_.isEmpty() && !drainPosted_) {
                drainPosted_ = true;  // context_ lives while directFd_ is set (stopOnThread clears it first)
                QMetaObject::invokeMethod(
                    context_, [this] { drainBacklog(); }, Qt::QueuedConnection);
            }
            return true;
        }
    }
    // Raw mode is reached before the bus reports Open, and left before it reports anything else.
    if (error) *error = QStringLiteral("socketcand connection to %1 is not open").arg(where());
    return false;
}

}  // namespace coscope
