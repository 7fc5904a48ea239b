// SPDX-License-Identifier: GPL-3.0-or-later
// What the bus tests share: open a bus by URL, and read until a count of frames or a timeout.
#pragma once

#include "core/can/CanBus.h"

#include <QElapsedTimer>
#include <QString>
#include <QtGlobal>

#include <memory>
#include <vector>

namespace coscope::testing {

// Reads from bus until want frames arrived or timeoutMs passed; returns what arrived.
inline std::vector<CanFrame> readFrames(CanBus& bus, size_t want, int timeoutMs = 3000) {
    std::vector<CanFrame> out;
    QElapsedTimer t;
    t.start();
    CanFrame buf[64];
    while (out.size() < want && t.elapsed() < timeoutMs) {
        bus.waitForFrames(20);
        for (size_t n = bus.read(buf, 64), i = 0; i < n; ++i) out.push_back(buf[i]);
    }
    return out;
}

// createBus + open; a URL the factory refuses ends the test program with the factory's error.
inline std::unique_ptr<CanBus> openBus(const QString& url) {
    QString err;
    auto bus = createBus(url, &err);
    if (!bus) qFatal("createBus: %s", qPrintable(err));
    bus->open();
    return bus;
}

}  // namespace coscope::testing
