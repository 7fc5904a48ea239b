// SPDX-License-Identifier: GPL-3.0-or-later
// Folder core/sim/ owns the virtual device network behind sim://: virtual nodes with SDO/LSS/PDO
// engines, the CiA 402 drive model, vendor personalities, injected faults and the socketcand
// server.
#pragma once

#include "core/can/CanFrame.h"
#include "core/sim/SimNode.h"

#include <QObject>
#include <QString>

#include <memory>
#include <mutex>
#include <vector>

class QThread;
class QTimer;

namespace coscope::sim {

class VirtualDevice;

// Something outside the network that sees its traffic: a SimBus endpoint, the socketcand server.
class SimTap {
public:
    virtual ~SimTap() = default;
    // Called on the network thread for every frame on the bus. `own` is true for a frame this
    // tap injected itself (its Tx echo).
    virtual void simReceive(const CanFrame& frame, bool own) = 0;
    // The tap's bit rate (bit/s): it sees only frames sent at this rate and its frames reach
    // only nodes at this rate. 0 = any rate (the socketcand server).
    virtual uint32_t simBitRate() const { return 0; }
};

// The in-process virtual CAN bus with its nodes. Runs on its own thread with a 1 ms tick (a late
// tick is caught up in 1 ms steps of the simulated clock); frames injected from other threads
// are queued and handled on that thread in order.
class SimNetwork : public QObject {
    Q_OBJECT
public:
    SimNetwork();
    ~SimNetwork() override;

    // Before start(): the nodes living on this bus.
    void addNode(std::unique_ptr<SimNode> node);
    const std::vector<std::unique_ptr<SimNode>>& nodes() const { return nodes_; }
    // The virtual device answering on `nodeId` now (node-IDs can change through LSS or vendor
    // parameters), nullptr if none. Use on the network thread once the network runs.
    VirtualDevice* device(uint8_t nodeId) const;

    // A technician's replacement: the device answering on `nodeId` is taken off the bus and a new
    // one of the same type (dictionary) put in its place, at factory defaults (nothing stored),
    // node-ID `nodeId`, with 1018h:04 serial number `serial`; it boots (sends its boot-up) on the
    // next tick. Any thread. False with *error when no device answers on `nodeId`.
    // `factoryNodeId` (1-127, or 255 = none, LSS only): the new drive comes at that node-ID
    // instead, as a new drive out of its box does (0 = `nodeId`).
    bool replaceDevice(uint8_t nodeId, uint32_t serial, QString* error = nullptr, uint8_t factoryNodeId = 0);

    void start();
    void stop();
    bool isRunning() const;

    void attach(SimTap* tap);
    void detach(SimTap* tap);
    // Any thread: put a frame on the bus as `from` (may be null).
    void inject(const CanFrame& frame, SimTap* from);

    // Runs `fn` on the network thread and waits for it (for tests and fault injection).
    void runOnNetworkThread(const std::function<void()>& fn);

    // Parses "1:delta-asda-a2,2:aimotor" (empty = the default network) and builds VirtualDevices
    // from the dictionaries sim::loadDictionary gives (eds::installSimulatorDictionaries()).
    // `serials` ("3:0x51000099,4:77", the sim:// option serials=) gives devices another 1018h:04
    // serial number than the default 0x51000000 + node-ID (a replaced drive).
    static std::unique_ptr<SimNetwork> fromSpec(const QString& spec, QString* error, const QString& serials = {});
    static QString defaultSpec();

    // The bit rate a virtual device starts at (its personality's default).
    static constexpr uint32_t kDefaultBitRate = 500000;

    // Named networks (sim://NAME?...): endpoints opening the same name share one network,
    // so a bus can be closed and reopened (e.g. at a new bit rate) without losing the devices'
    // state. The registry holds weak references: a network lives while an endpoint or another
    // owner holds it. Any thread.
    static void publish(const QString& name, const std::shared_ptr<SimNetwork>& network);
    static std::shared_ptr<SimNetwork> published(const QString& name);

private:
    void forgetSender(SimTap* tap);  // with mutex_ held
    void onTick();
    void broadcast(const CanFrame& frame, SimNode* fromNode, SimTap* fromTap);
    // Frames pass between participants at the same bit rate (0 = any).
    static bool sameBitRate(uint32_t a, uint32_t b) { return a == 0 || b == 0 || a == b; }

    std::vector<std::unique_ptr<SimNode>> nodes_;
    QThread* thread_ = nullptr;
    QTimer* timer_ = nullptr;
    std::mutex mutex_;  // guards taps_ and inbox_
    std::vector<SimTap*> taps_;
    std::vector<std::pair<CanFrame, SimTap*>> inbox_;
    bool powered_ = false;
    static constexpr int64_t kTickNs = 1'000'000;
    static constexpr int64_t kMaxCatchUpMs = 100;
    int64_t clockNs_ = 0;  // simulated clock: the time of the tick being run (network thread)
};

}  // namespace coscope::sim
