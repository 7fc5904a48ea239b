// SPDX-License-Identifier: GPL-3.0-or-later
// Test rig for the master services: a virtual bus with scripted nodes (answers written by the
// test, run on the network thread), a SimBus endpoint, its CaptureSession feeding the
// services' FrameDispatcher, and a MasterContext.
#pragma once

#include "core/can/BusUrl.h"
#include "core/canopen/MasterContext.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/SimNode.h"
#include "core/sim/VirtualDevice.h"
#include "core/trace/CaptureSession.h"
#include "eds/SimulatorDictionaries.h"

#include <QByteArray>

#include <functional>
#include <memory>
#include <mutex>
#include <vector>

namespace svctest {

using coscope::CanFrame;

// A node whose answers are a function of each frame it sees (network thread).
class ScriptedNode : public coscope::sim::SimNode {
public:
    using Script = std::function<void(const CanFrame& in, ScriptedNode& node)>;
    explicit ScriptedNode(uint8_t id) : id_(id) {}
    uint8_t nodeId() const override { return id_; }
    void powerOn(int64_t) override {}
    void tick(int64_t) override {}
    void onFrame(const CanFrame& f, int64_t) override {
        {
            std::lock_guard lock(mutex_);
            seen_.push_back(f);
        }
        Script s;
        {
            std::lock_guard lock(mutex_);
            s = script_;
        }
        if (s) s(f, *this);
    }
    void setScript(Script s) {
        std::lock_guard lock(mutex_);
        script_ = std::move(s);
    }
    void send(const CanFrame& f) { transmit(f); }
    void reply(std::initializer_list<uint8_t> bytes) { transmit(CanFrame::classic(0x580u + id_, bytes)); }
    // Frames this node received with the given COB-ID (default: its SDO requests).
    std::vector<CanFrame> seen(uint32_t cobId = 0) {
        std::lock_guard lock(mutex_);
        std::vector<CanFrame> out;
        for (const auto& f : seen_)
            if (f.id == (cobId ? cobId : 0x600u + id_)) out.push_back(f);
        return out;
    }
    void clearSeen() {
        std::lock_guard lock(mutex_);
        seen_.clear();
    }

private:
    uint8_t id_;
    std::mutex mutex_;
    Script script_;
    std::vector<CanFrame> seen_;
};

inline QByteArray bytesOf(const CanFrame& f) { return QByteArray(reinterpret_cast<const char*>(f.data.data()), f.len); }
inline QByteArray hex(const char* text) { return QByteArray::fromHex(text); }

struct Rig {
    std::shared_ptr<coscope::sim::SimNetwork> network = std::make_shared<coscope::sim::SimNetwork>();
    std::vector<ScriptedNode*> nodes;
    std::unique_ptr<coscope::SimBus> bus;
    coscope::CaptureSession session;
    std::unique_ptr<coscope::canopen::MasterContext> context;

    ScriptedNode* addNode(uint8_t id) {
        auto n = std::make_unique<ScriptedNode>(id);
        nodes.push_back(n.get());
        network->addNode(std::move(n));
        return nodes.back();
    }
    // A network of virtual devices from a spec ("1:delta-asda-a2,2:aimotor").
    bool useSpec(const QString& spec, QString* error = nullptr) {
        coscope::eds::installSimulatorDictionaries();
        auto net = coscope::sim::SimNetwork::fromSpec(spec, error);
        if (!net) return false;
        network = std::shared_ptr<coscope::sim::SimNetwork>(std::move(net));
        return true;
    }
    // Runs fn(device) on the network thread.
    void onDevice(uint8_t node, const std::function<void(coscope::sim::VirtualDevice&)>& fn) {
        network->runOnNetworkThread([&] {
            if (auto* d = network->device(node)) fn(*d);
        });
    }
    bool open(const QString& url = QStringLiteral("sim://")) {
        auto parsed = coscope::BusUrl::parse(url, nullptr);
        if (!parsed) return false;
        bus = std::make_unique<coscope::SimBus>(*parsed, network);
        context = std::make_unique<coscope::canopen::MasterContext>(bus.get());
        session.addConsumer(context->dispatcher().consumer());
        bus->open();
        if (!bus->waitForOpen(2000)) return false;
        session.start(bus.get());
        return true;
    }
    ~Rig() {
        session.stop();
        if (bus) bus->close();
        network->stop();
    }
};

}  // namespace svctest
