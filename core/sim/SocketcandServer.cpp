// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/SocketcandServer.h"

#include <QDateTime>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTimer>

#include <spdlog/spdlog.h>

#include <mutex>

namespace coscope::sim {

namespace {
constexpr size_t kMaxQueued = 200'000;  // frames a slow client may lag behind before drops
}

// One connection: a tap on the network with its own frame queue.
struct SocketcandServer::Client : SimTap {
    QTcpSocket* socket = nullptr;
    socketcand::MessageSplitter splitter;
    bool open = false;
    bool raw = false;
    qint64 rawSinceMs = 0;  // frames start a moment after "< ok >" so it arrives alone
    std::mutex mutex;
    std::vector<CanFrame> queue;
    uint64_t dropped = 0;

    void simReceive(const CanFrame& frame, bool own) override {
        if (own) return;  // socketcand does not echo a client's own frames
        std::lock_guard lock(mutex);
        if (queue.size() >= kMaxQueued) {
            ++dropped;
            return;
        }
        queue.push_back(frame);
    }
};

SocketcandServer::SocketcandServer(std::shared_ptr<SimNetwork> network, QObject* parent)
    : QObject(parent), network_(std::move(network)) {
    server_ = new QTcpServer(this);
    connect(server_, &QTcpServer::newConnection, this, &SocketcandServer::onNewConnection);
    timer_ = new QTimer(this);
    timer_->setInterval(2);
    connect(timer_, &QTimer::timeout, this, &SocketcandServer::flush);
}

SocketcandServer::~SocketcandServer() {
    for (auto& c : clients_) network_->detach(c.get());
    clients_.clear();
}

bool SocketcandServer::listen(const QHostAddress& address, quint16 port, QString* error) {
    if (!server_->listen(address, port)) {
        if (error)
            *error = QStringLiteral("cannot listen on %1:%2: %3")
                         .arg(address.toString())
                         .arg(port)
                         .arg(server_->errorString());
        return false;
    }
    timer_->start();
    return true;
}

quint16 SocketcandServer::serverPort() const { return server_->serverPort(); }

void SocketcandServer::onNewConnection() {
    while (QTcpSocket* s = server_->nextPendingConnection()) {
        auto c = std::make_unique<Client>();
        c->socket = s;
        s->setParent(this);
        s->setSocketOption(QAbstractSocket::LowDelayOption, 1);
        Client* raw = c.get();
        connect(s, &QTcpSocket::readyRead, this, [this, raw] { onReadyRead(raw); });
        connect(s, &QTcpSocket::disconnected, this, [this, raw] { drop(raw); });
        clients_.push_back(std::move(c));
        s->write(socketcand::encodeHi());
        s->flush();
        spdlog::info("socketcand client connected from {}:{}", s->peerAddress().toString().toStdString(),
                     s->peerPort());
    }
}

void SocketcandServer::onReadyRead(Client* c) {
    c->splitter.feed(c->socket->readAll());
    QString discarded;
    while (auto msg = c->splitter.next(&discarded)) {
        QString error;
        auto m = socketcand::parseMessage(*msg, &error);
        if (!m) {
            c->socket->write(socketcand::encodeError(error));
            continue;
        }
        using K = socketcand::Message::Kind;
        switch (m->kind) {
        case K::Open:
            if (c->open) {
                c->socket->write(socketcand::encodeError(QStringLiteral("channel already open")));
            } else if (!channels_.isEmpty() && !channels_.contains(m->text)) {
                c->socket->write(socketcand::encodeError(QStringLiteral("unknown channel %1").arg(m->text)));
            } else {
                c->open = true;
                c->socket->write(socketcand::encodeOk());
            }
            break;
        case K::RawMode:
            if (!c->open) {
                c->socket->write(socketcand::encodeError(QStringLiteral("open a channel first")));
                break;
            }
            c->socket->write(socketcand::encodeOk());
            if (!c->raw) {
                c->raw = true;
                c->rawSinceMs = QDateTime::currentMSecsSinceEpoch();
                network_->attach(c);
            }
            break;
        case K::Echo: c->socket->write("< echo >"); break;
        case K::Send:
            if (c->raw) network_->inject(m->frame, c);
            else c->socket->write(socketcand::encodeError(QStringLiteral("not in raw mode")));
            break;
        default:
            c->socket->write(socketcand::encodeError(QStringLiteral("unsupported command %1").arg(m->word)));
            break;
        }
    }
    if (!discarded.isEmpty()) spdlog::warn("socketcand client: {}", discarded.toStdString());
}

void SocketcandServer::drop(Client* c) {
    network_->detach(c);
    c->socket->deleteLater();
    std::erase_if(clients_, [c](const auto& p) { return p.get() == c; });
}

void SocketcandServer::flush() {
    const qint64 now = QDateTime::currentMSecsSinceEpoch();
    std::vector<CanFrame> batch;
    for (auto& c : clients_) {
        if (!c->raw || now - c->rawSinceMs < 50) continue;
        {
            std::lock_guard lock(c->mutex);
            batch.swap(c->queue);
        }
        if (batch.empty()) continue;
        QByteArray out;
        out.reserve(static_cast<qsizetype>(batch.size()) * 40);
        for (const CanFrame& f : batch) {
            out += ' ';  // see the class comment: a space before each frame
            out += socketcand::encodeFrame(f);
        }
        c->socket->write(out);
        batch.clear();
    }
}

}  // namespace coscope::sim
