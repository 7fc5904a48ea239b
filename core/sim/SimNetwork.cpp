// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sim/SimNetwork.h"

#include "core/can/CanBus.h"
#include "core/sim/VirtualDevice.h"

#include <QThread>
#include <QTimer>

#include <algorithm>
#include <map>

namespace coscope::sim {

SimNetwork::SimNetwork() = default;

SimNetwork::~SimNetwork() { stop(); }

void SimNetwork::addNode(std::unique_ptr<SimNode> node) {
    SimNode* raw = node.get();
    raw->setTransmitter([this, raw](const CanFrame& f) { broadcast(f, raw, nullptr); });
    nodes_.push_back(std::move(node));
}

void SimNetwork::start() {
    if (thread_) return;
    thread_ = new QThread;
    thread_->setObjectName(QStringLiteral("sim-network"));
    moveToThread(thread_);
    thread_->start();
    QMetaObject::invokeMethod(
        this,
        [this] {
            timer_ = new QTimer(this);
            timer_->setTimerType(Qt::PreciseTimer);
            timer_->setInterval(1);
            connect(timer_, &QTimer::timeout, this, &SimNetwork::onTick);
            timer_->start();
        },
        Qt::BlockingQueuedConnection);
}

void SimNetwork::stop() {
    if (!thread_) return;
    QMetaObject::invokeMethod(
        this,
        [this] {
            delete timer_;
            timer_ = nullptr;
            moveToThread(nullptr);
        },
        Qt::BlockingQueuedConnection);
    thread_->quit();
    thread_->wait();
    delete thread_;
    thread_ = nullptr;
}

bool SimNetwork::isRunning() const { return thread_ != nullptr; }

void SimNetwork::attach(SimTap* tap) {
    std::lock_guard lock(mutex_);
    taps_.push_back(tap);
}

// Frames a tap sent before it detached still go out (an adapter that is closed after a send
// has put the frame on the wire): they lose only their sender, which is gone.
void SimNetwork::forgetSender(SimTap* tap) {
    for (auto& p : inbox_)
        if (p.second == tap) p.second = nullptr;
}

void SimNetwork::detach(SimTap* tap) {
    if (thread_ && QThread::currentThread() != thread_) {
        // Make sure no delivery to this tap is running when we return.
        runOnNetworkThread([this, tap] {
            std::lock_guard lock(mutex_);
            std::erase(taps_, tap);
            forgetSender(tap);
        });
        return;
    }
    std::lock_guard lock(mutex_);
    std::erase(taps_, tap);
    forgetSender(tap);
}

void SimNetwork::inject(const CanFrame& frame, SimTap* from) {
    std::lock_guard lock(mutex_);
    inbox_.emplace_back(frame, from);
}

void SimNetwork::runOnNetworkThread(const std::function<void()>& fn) {
    if (!thread_ || QThread::currentThread() == thread_) {
        fn();
        return;
    }
    QMetaObject::invokeMethod(this, fn, Qt::BlockingQueuedConnection);
}

void SimNetwork::onTick() {
    const int64_t now = nowNs();
    if (!powered_) {
        powered_ = true;
        clockNs_ = now;
        for (auto& n : nodes_) n->powerOn(now);
    }
    // The simulated clock advances in steps of at most 1 ms even when this thread was late, so
    // timers of the nodes (event timers, inhibit times, heartbeats) keep to within 1 ms of it;
    // their frames carry the simulated time. A stall of more than kMaxCatchUpMs is skipped.
    if (now - clockNs_ > kMaxCatchUpMs * kTickNs) clockNs_ = now - kMaxCatchUpMs * kTickNs;
    for (int64_t t = clockNs_ + kTickNs; t < now; t += kTickNs) {
        clockNs_ = t;
        for (auto& n : nodes_) n->tick(t);
    }
    clockNs_ = now;
    std::vector<std::pair<CanFrame, SimTap*>> batch;
    {
        std::lock_guard lock(mutex_);
        batch.swap(inbox_);
    }
    for (auto& [frame, from] : batch) {
        CanFrame f = frame;
        f.timestampNs = now;
        f.flags &= ~CanFrame::Tx;
        broadcast(f, nullptr, from);
    }
    for (auto& n : nodes_) n->tick(now);
}

void SimNetwork::broadcast(const CanFrame& frame, SimNode* fromNode, SimTap* fromTap) {
    CanFrame f = frame;
    if (f.timestampNs == 0)
        f.timestampNs = thread_ && QThread::currentThread() == thread_ && clockNs_ ? clockNs_ : nowNs();
    std::vector<SimTap*> taps;
    {
        std::lock_guard lock(mutex_);
        taps = taps_;
    }
    // A controller at another bit rate cannot decode the frame: it neither receives it nor
    // acknowledges it (on a real bus it would also see error frames; not modelled).
    const uint32_t rate = fromNode ? fromNode->bitRate() : fromTap ? fromTap->simBitRate() : 0;
    for (SimTap* t : taps)
        if (t == fromTap || sameBitRate(rate, t->simBitRate())) t->simReceive(f, t == fromTap);
    for (auto& n : nodes_)
        if (n.get() != fromNode && sameBitRate(rate, n->bitRate())) n->onFrame(f, f.timestampNs);
}

namespace {
std::mutex& registryMutex() {
    static std::mutex m;
    return m;
}
std::map<QString, std::weak_ptr<SimNetwork>>& registry() {
    static std::map<QString, std::weak_ptr<SimNetwork>> r;
    return r;
}
}  // namespace

void SimNetwork::publish(const QString& name, const std::shared_ptr<SimNetwork>& network) {
    std::lock_guard lock(registryMutex());
    auto& r = registry();
    std::erase_if(r, [](const auto& kv) { return kv.second.expired(); });
    r[name] = network;
}

std::shared_ptr<SimNetwork> SimNetwork::published(const QString& name) {
    std::lock_guard lock(registryMutex());
    auto it = registry().find(name);
    return it == registry().end() ? nullptr : it->second.lock();
}

VirtualDevice* SimNetwork::device(uint8_t nodeId) const {
    for (const auto& n : nodes_)
        if (auto* d = dynamic_cast<VirtualDevice*>(n.get()); d && d->nodeId() == nodeId) return d;
    return nullptr;
}

QString SimNetwork::defaultSpec() { return QStringLiteral("1:delta-asda-a2,2:aimotor,3:generic-cia402"); }

bool SimNetwork::replaceDevice(uint8_t nodeId, uint32_t serial, QString* error, uint8_t factoryNodeId) {
    bool done = false;
    runOnNetworkThread([&] {
        for (auto& n : nodes_) {
            auto* old = dynamic_cast<VirtualDevice*>(n.get());
            if (!old || old->nodeId() != nodeId) continue;
            auto fresh = VirtualDevice::create(factoryNodeId ? factoryNodeId : nodeId, old->dictionaryName(), error);
            if (!fresh) return;
            fresh->setSerialNumber(serial);
            SimNode* raw = fresh.get();
            raw->setTransmitter([this, raw](const CanFrame& f) { broadcast(f, raw, nullptr); });
            n = std::move(fresh);
            if (powered_) raw->powerOn(clockNs_ ? clockNs_ : nowNs());
            done = true;
            return;
        }
        if (error) *error = QStringLiteral("no virtual device answers on node %1").arg(nodeId);
    });
    return done;
}

std::unique_ptr<SimNetwork> SimNetwork::fromSpec(const QString& specIn, QString* error, const QString& serials) {
    const QString spec = specIn.trimmed().isEmpty() ? defaultSpec() : specIn;
    auto net = std::make_unique<SimNetwork>();
    std::vector<int> used;
    for (const QString& part : spec.split(u',', Qt::SkipEmptyParts)) {
        const qsizetype colon = part.indexOf(u':');
        bool ok = false;
        const int id = (colon < 0 ? part : part.left(colon)).trimmed().toInt(&ok);
        if (!ok || id < 1 || id > 127) {
            if (error)
                *error =
                    QStringLiteral("sim node '%1': node-ID must be 1-127 (form ID:DICTIONARY, e.g. 1:delta-asda-a2)")
                        .arg(part);
            return nullptr;
        }
        if (std::find(used.begin(), used.end(), id) != used.end()) {
            if (error) *error = QStringLiteral("sim node-ID %1 is used twice").arg(id);
            return nullptr;
        }
        used.push_back(id);
        const QString dict = colon < 0 ? QStringLiteral("generic-cia402") : part.mid(colon + 1).trimmed();
        auto node = VirtualDevice::create(static_cast<uint8_t>(id), dict, error);
        if (!node) return nullptr;
        net->addNode(std::move(node));
    }
    for (const QString& part : serials.split(u',', Qt::SkipEmptyParts)) {
        const QStringList idSerial = part.split(u':');
        bool okId = false, okSerial = false;
        const int id = idSerial.value(0).trimmed().toInt(&okId);
        const qulonglong serial = idSerial.value(1).trimmed().toULongLong(&okSerial, 0);
        VirtualDevice* d = okId && id >= 1 && id <= 127 ? net->device(static_cast<uint8_t>(id)) : nullptr;
        if (idSerial.size() != 2 || !okSerial || serial > 0xFFFFFFFFull || !d) {
            if (error)
                *error =
                    QStringLiteral("sim serials '%1': expects NODE:SERIAL of a node on the network, e.g. 3:0x51000099")
                        .arg(part);
            return nullptr;
        }
        d->setSerialNumber(static_cast<uint32_t>(serial));
    }
    return net;
}

}  // namespace coscope::sim
