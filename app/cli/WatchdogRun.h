// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "app/cli/BusSession.h"
#include "core/canopen/HeartbeatGuard.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QTextStream>

#include <memory>

namespace coscope::cli {

// --watchdog of the verbs that move a drive (ds402 jog, and any verb that adds these options):
// while the verb runs, CoScope sends its heartbeat (the bus's BusMaster::heartbeat()) and the
// drive watches it through a canopen::HeartbeatGuard (1016h, 6007h), so that when coscope-cli
// dies or the cable is pulled the drive stops by itself. The old 1016h/6007h are put back at
// the end, before the heartbeat stops.
struct WatchdogOptions {
    QCommandLineOption watchdog{
        QStringLiteral("watchdog"),
        QStringLiteral("While this runs, send CoScope's heartbeat and have the drive watch it (1016h, 3 x the period) "
                       "with 6007h = --watchdog-reaction: if coscope-cli dies or the cable is pulled, the drive stops "
                       "by itself. The old 1016h/6007h values are put back at the end.")};
    QCommandLineOption node{QStringLiteral("heartbeat-node"),
                            QStringLiteral("CoScope's heartbeat node-ID, 1-127 (default 127)."), QStringLiteral("N"),
                            QStringLiteral("127")};
    QCommandLineOption period{QStringLiteral("heartbeat-ms"),
                              QStringLiteral("CoScope's heartbeat period in ms (default 100; the drive waits 3 x)."),
                              QStringLiteral("MS"), QStringLiteral("100")};
    QCommandLineOption reaction{
        QStringLiteral("watchdog-reaction"),
        QStringLiteral("6007h when the heartbeat stops: quick-stop (default), disable-voltage, fault or none."),
        QStringLiteral("R"), QStringLiteral("quick-stop")};
    void addTo(QCommandLineParser& parser) const;

    // Read by read():
    bool enabled = false;
    uint8_t heartbeatNode = 127;
    uint16_t periodMs = 100;
    int16_t abortOption = canopen::HeartbeatGuard::kQuickStop;
    // False with *error (a usage error) on a bad value; `driveNode` must differ from the heartbeat's.
    bool read(const QCommandLineParser& parser, uint8_t driveNode, QString* error);
};

class WatchdogRun {
public:
    WatchdogRun(BusSession& session, uint8_t node, int axis, QTextStream& out);
    ~WatchdogRun();  // finish()

    // Starts the heartbeat and arms the guard (each SDO write printed as "send ..."). False with
    // *error when either failed; then the heartbeat is stopped and the drive left as it was.
    bool start(const WatchdogOptions& options, QString* error);
    // Puts 1016h/6007h back, then stops the heartbeat. Empty, or why putting back failed.
    QString finish();

private:
    BusSession& session_;
    QTextStream& out_;
    std::unique_ptr<canopen::HeartbeatGuard> guard_;
    bool running_ = false;
};

}  // namespace coscope::cli
