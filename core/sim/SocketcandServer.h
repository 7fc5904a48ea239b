// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/SocketcandProtocol.h"
#include "core/sim/SimNetwork.h"

#include <QHostAddress>
#include <QObject>
#include <QString>

#include <memory>
#include <vector>

class QTcpServer;
class QTcpSocket;
class QTimer;

namespace coscope::sim {

// Serves a virtual network over the socketcand text protocol (raw mode; see
// core/can/SocketcandProtocol.h), so other programs (python-can's socketcand interface, the
// CoScope GUI with socketcand://HOST:PORT/CHANNEL) reach the virtual drives. Every client is a tap
// on the network: it receives all frames other participants send and its "send" frames go on the
// bus. Frames reach the sockets through per-client queues drained by a 2 ms timer in the server's
// thread (nothing per frame crosses a Qt signal). Binds to loopback unless told otherwise.
//
// Compatibility with python-can 4.1 (can/interfaces/socketcand): "< hi >" and "< ok >" are
// written alone (it compares whole recv() results), frames start 50 ms after "< ok >", and each
// frame is preceded by one space, which socketcand readers skip: python-can drops the character
// after the last complete message of a read, so without it a frame split across reads is lost.
class SocketcandServer : public QObject {
public:
    explicit SocketcandServer(std::shared_ptr<SimNetwork> network, QObject* parent = nullptr);
    ~SocketcandServer() override;

    // Channel names the server accepts in "< open CHANNEL >" (default: any).
    void setChannels(const QStringList& channels) { channels_ = channels; }
    bool listen(const QHostAddress& address, quint16 port, QString* error);
    quint16 serverPort() const;
    int clientCount() const { return static_cast<int>(clients_.size()); }

private:
    struct Client;
    void onNewConnection();
    void onReadyRead(Client* c);
    void drop(Client* c);
    void flush();

    std::shared_ptr<SimNetwork> network_;
    QTcpServer* server_ = nullptr;
    QTimer* timer_ = nullptr;
    QStringList channels_;
    std::vector<std::unique_ptr<Client>> clients_;
};

}  // namespace coscope::sim
