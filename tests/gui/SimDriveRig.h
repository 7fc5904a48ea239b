// SPDX-License-Identifier: GPL-3.0-or-later
// A workspace connected to the virtual drives of sim:// for GUI tests, with a look at a drive's
// own state machine (on the network thread) to check what the app made it do.
#pragma once

#include "app/gui/session/Workspace.h"
#include "core/sim/Ds402Drive.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"

#include <QtTest>

namespace coscope::testing {

struct SimDriveRig {
    gui::Workspace ws;
    // Connects to `url` and waits until the bus is open.
    bool open(const QString& url) {
        QString error;
        if (!ws.connectBus(url, &error)) return false;
        return QTest::qWaitFor([&] { return ws.bus() && ws.bus()->state() == CanBus::State::Open; }, 5000);
    }
    sim::SimNetwork* net() { return static_cast<SimBus*>(ws.bus())->network(); }
    template <typename F>
    auto onDrive(int node, F f) {
        decltype(f(static_cast<sim::Ds402Drive*>(nullptr))) out{};
        net()->runOnNetworkThread([&] { out = f(net()->device(static_cast<uint8_t>(node))->drive(0)); });
        return out;
    }
    canopen::ds402::State driveState(int node) {
        return onDrive(node, [](sim::Ds402Drive* d) { return d->state(); });
    }
};

}  // namespace coscope::testing
