// SPDX-License-Identifier: GPL-3.0-or-later
// A scripted socketcand server for tests: listens on 127.0.0.1 (port chosen by the system),
// plays the handshake of linux-can/socketcand doc/protocol.md ("< hi >", "< ok >" to open and
// rawmode) and records every byte the client sends. Lives on the test's thread: tests wait with
// QTRY_* / CanBus::waitFor*, which process its events.
#pragma once

#include <QByteArray>
#include <QHostAddress>
#include <QTcpServer>
#include <QTcpSocket>

class FakeSocketcandServer {
public:
    bool greet = true;                   // send "< hi >" on connect
    QByteArray answerToOpen = "< ok >";  // what "< open CHANNEL >" gets
    QByteArray received;                 // everything the client sent
    QByteArray afterHandshake;           // client bytes after "< rawmode >" was answered
    bool handshakeDone = false;
    int receiveBufferBytes = 0;  // > 0: a small kernel receive buffer (a slow server)

    // port 0: chosen by the system; a port of a server that went away: "the server restarted".
    bool listen(quint16 port = 0) {
        QObject::connect(&server_, &QTcpServer::newConnection, &server_, [this] { onConnection(); });
        return server_.listen(QHostAddress::LocalHost, port);
    }
    quint16 port() const { return server_.serverPort(); }
    QString url(const QString& options = {}) const {
        return QStringLiteral("socketcand://127.0.0.1:%1/can0%2").arg(port()).arg(options);
    }
    bool hasClient() const { return client_ != nullptr; }

    void write(const QByteArray& bytes) {
        if (!client_) return;
        client_->write(bytes);
        client_->flush();
    }
    void closeClient() {
        if (!client_) return;
        client_->flush();
        client_->disconnectFromHost();
    }

private:
    void onConnection() {
        QTcpSocket* s = server_.nextPendingConnection();
        if (client_) {  // one client at a time, like socketcand's forked child
            s->abort();
            s->deleteLater();
            return;
        }
        client_ = s;
        if (receiveBufferBytes > 0)
            client_->setSocketOption(QAbstractSocket::ReceiveBufferSizeSocketOption, receiveBufferBytes);
        QObject::connect(client_, &QTcpSocket::readyRead, client_, [this] { onData(); });
        if (greet) write("< hi >");
    }
    void onData() {
        const QByteArray bytes = client_->readAll();
        received += bytes;
        if (handshakeDone) {
            afterHandshake += bytes;
            return;
        }
        pending_ += bytes;
        for (;;) {
            const qsizetype open = pending_.indexOf('<');
            const qsizetype close = pending_.indexOf('>', open + 1);
            if (open < 0 || close < 0) return;
            const QByteArray msg = pending_.mid(open, close - open + 1);
            pending_.remove(0, close + 1);
            if (msg.startsWith("< open ")) {
                write(answerToOpen);
            } else if (msg == "< rawmode >") {
                write("< ok >");
                handshakeDone = true;
                afterHandshake += pending_;
                pending_.clear();
                return;
            }
        }
    }

    QTcpServer server_;
    QTcpSocket* client_ = nullptr;
    QByteArray pending_;
};
