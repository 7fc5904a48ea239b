// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/SimBus.h"

#include "core/sim/DemoMaster.h"

namespace coscope {

SimBus::SimBus(const BusUrl& url, QObject* parent) : CanBus(url, parent) {
    if (url.bitrate() > 0) bitRate_ = static_cast<uint32_t>(url.bitrate());
}

SimBus::SimBus(const BusUrl& url, std::shared_ptr<sim::SimNetwork> network, QObject* parent)
    : CanBus(url, parent), network_(std::move(network)) {
    if (url.bitrate() > 0) bitRate_ = static_cast<uint32_t>(url.bitrate());
}

SimBus::~SimBus() { close(); }

void SimBus::open() {
    if (attached_) return;
    setState(State::Opening);
    const QString name = url().target.trimmed();
    if (!network_ && !name.isEmpty()) network_ = sim::SimNetwork::published(name);
    if (!network_) {
        QString error;
        std::unique_ptr<sim::SimNetwork> net = sim::SimNetwork::fromSpec(url().option(QStringLiteral("nodes")), &error,
                                                                         url().option(QStringLiteral("serials")));
        if (!net) {
            setState(State::Error, error);
            return;
        }
        if (url().demo()) net->addNode(std::make_unique<sim::DemoMaster>(*net));
        network_ = std::move(net);
        if (!name.isEmpty()) sim::SimNetwork::publish(name, network_);
    }
    network_->attach(this);
    attached_ = true;
    if (!network_->isRunning()) network_->start();
    setState(State::Open);
}

void SimBus::close() {
    if (attached_) {
        network_->detach(this);
        attached_ = false;
    }
    // The last endpoint stops the network it created.
    if (network_ && network_.use_count() == 1) network_->stop();
    if (state() != State::Closed) setState(State::Closed);
}

void SimBus::simReceive(const CanFrame& frame, bool own) {
    if (!own) {
        deliver(frame);
        return;
    }
    CanFrame echo = frame;
    echo.flags |= CanFrame::Tx;
    deliver(echo);
}

bool SimBus::sendFrame(const CanFrame& frame, QString* error) {
    if (!attached_) {
        if (error) *error = QStringLiteral("virtual bus is not open");
        return false;
    }
    network_->inject(frame, this);
    return true;
}

}  // namespace coscope
