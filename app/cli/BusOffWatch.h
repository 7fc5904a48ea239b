// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QString>

#include <cstdint>

namespace coscope {
class CanBus;
}

namespace coscope::cli {

// Watches a capturing bus for bus-off reports (error frames, CanBus::Counters::busOffs) and says
// so on stderr; with --restart-on-bus-off it restarts the controller (CanBus::restartController)
// once per report. Capturing goes on either way: nothing recorded is lost.
class BusOffWatch {
public:
    BusOffWatch(CanBus* bus, const QString& verb, bool restart) : bus_(bus), verb_(verb), restart_(restart) {}
    void poll();  // call from the capture loop
    static QString optionHelp();

private:
    CanBus* bus_;
    QString verb_;
    bool restart_;
    uint64_t seen_ = 0;
};

}  // namespace coscope::cli
