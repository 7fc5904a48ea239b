// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli guard BUS NODE [--guard-time 100ms] [--life 3] | [--heartbeat 300ms] [--duration S]:
// CoScope watches one node's error control (CiA 301 §7.2.8.3.2) through canopen::HeartbeatMonitor,
// as the Nodes dock's "Heartbeat and guarding…" does: node guarding (an RTR on 700h + node every
// guard time, the toggle bit checked, lost after guard time x life time factor) or, with
// --heartbeat, its heartbeat within a consumer time. Prints each change of the watch; exit 1
// when the node was lost.
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "app/cli/PeriodicRun.h"
#include "core/canopen/HeartbeatMonitor.h"
#include "core/canopen/Nmt.h"

#include <QLoggingCategory>

#include <cstdio>

namespace coscope::cli {

namespace {
const QString kVerb = QStringLiteral("guard");

QString statusName(canopen::ErrorControlWatch::Status s) {
    using Status = canopen::ErrorControlWatch::Status;
    switch (s) {
    case Status::Off: return QStringLiteral("off");
    case Status::Waiting: return QStringLiteral("waiting");
    case Status::Ok: return QStringLiteral("ok");
    case Status::Late: return QStringLiteral("late");
    case Status::Lost: return QStringLiteral("lost");
    }
    return {};
}

std::optional<int> parseMs(const QString& text, const QString& option, QString* error) {
    const auto us = parsePeriodUs(text, error);
    if (!us) return std::nullopt;
    if (*us % 1000 || *us / 1000 > 65535) {
        *error = QStringLiteral("%1 must be whole milliseconds, 1-65535 ms (100Ch/1016h hold ms)").arg(option);
        return std::nullopt;
    }
    return static_cast<int>(*us / 1000);
}
}  // namespace

static int runGuard(const QStringList& args) {
    QLoggingCategory::setFilterRules(QStringLiteral("qt.canbus.plugins.*=false"));
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Watch a node's error control (CiA 301 7.2.8.3.2): node guarding (RTR on 700h+NODE every "
                       "--guard-time, toggle bit checked, lost after "
                       "--guard-time x --life without a right answer) or, with --heartbeat, its heartbeat within a "
                       "consumer time. Prints each change; "
                       "runs --duration seconds (default %1 s, 0 = until Ctrl+C); exit 1 when the node was lost.")
            .arg(kDefaultRunSeconds));
    parser.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL, e.g. socketcan://can0, sim://"));
    parser.addPositionalArgument(QStringLiteral("NODE"), QStringLiteral("Node-ID 1-127"));
    const QCommandLineOption guardOpt(
        QStringLiteral("guard-time"),
        QStringLiteral("Guard time (100Ch): 100ms, 1s; a plain number is ms (default 100ms)."), QStringLiteral("T"),
        QStringLiteral("100ms"));
    const QCommandLineOption lifeOpt(QStringLiteral("life"),
                                     QStringLiteral("Life time factor (100Dh), 1-255 (default 3)."),
                                     QStringLiteral("N"), QStringLiteral("3"));
    const QCommandLineOption heartbeatOpt(QStringLiteral("heartbeat"),
                                          QStringLiteral("Watch the node's heartbeat instead: lost when none comes "
                                                         "within T (a consumer time, as 1016h). Sends nothing."),
                                          QStringLiteral("T"));
    const QCommandLineOption durationOpt(
        QStringLiteral("duration"),
        QStringLiteral("Seconds to watch (default %1; 0 = until Ctrl+C).").arg(kDefaultRunSeconds),
        QStringLiteral("S"));
    parser.addOptions({guardOpt, lifeOpt, heartbeatOpt, durationOpt});
    int code = 0;
    if (!parseArgs(parser, kVerb, args, &code)) return code;
    const QStringList pos = parser.positionalArguments();
    if (pos.size() != 2) return usageError(kVerb, QStringLiteral("expected BUS NODE (see --help)"));
    const auto node = parseNodeId(pos[1]);
    if (!node) return usageError(kVerb, QStringLiteral("NODE must be 1-127, not '%1'").arg(pos[1]));
    QString error;
    const bool heartbeat = parser.isSet(heartbeatOpt);
    std::optional<int> timeMs =
        parseMs(parser.value(heartbeat ? heartbeatOpt : guardOpt),
                heartbeat ? QStringLiteral("--heartbeat") : QStringLiteral("--guard-time"), &error);
    if (!timeMs) return usageError(kVerb, error);
    bool ok = false;
    const int life = parser.value(lifeOpt).toInt(&ok);
    if (!ok || life < 1 || life > 255)
        return usageError(kVerb, QStringLiteral("--life must be 1-255 (100Dh), not '%1'").arg(parser.value(lifeOpt)));
    double seconds = kDefaultRunSeconds;
    if (parser.isSet(durationOpt)) {
        seconds = parser.value(durationOpt).toDouble(&ok);
        if (!ok || seconds < 0)
            return usageError(
                kVerb, QStringLiteral("--duration must be seconds >= 0, not '%1'").arg(parser.value(durationOpt)));
    }

    BusSession session;
    if (!session.open(pos[0], &error)) return failure(kVerb, error);
    canopen::HeartbeatMonitor monitor(session.context());
    auto shown = canopen::ErrorControlWatch::Status::Waiting;
    QObject::connect(&monitor, &canopen::HeartbeatMonitor::nodeChanged, [&](int n) {
        if (n != *node) return;
        const canopen::ErrorControlWatch w = monitor.watch(*node);
        if (w.status == shown) return;  // the watch's changes only, not each NMT state
        shown = w.status;
        const auto info = monitor.table().node(n);
        const QString state = info && info->nmtState >= 0 ? canopen::nmtStateName(static_cast<uint8_t>(info->nmtState))
                                                          : QStringLiteral("unknown");
        std::printf("node %d: %s (NMT state %s)\n", n, qPrintable(statusName(w.status)), qPrintable(state));
        std::fflush(stdout);
    });
    QObject::connect(&monitor, &canopen::HeartbeatMonitor::guardingError, [&](int, const QString& what) {
        std::printf("%s\n", qPrintable(what));
        std::fflush(stdout);
    });
    if (heartbeat) {
        monitor.setConsumerTime(*node, *timeMs);
        std::printf("watching node %d's heartbeat: lost when none comes within %d ms\n", *node, *timeMs);
    } else {
        if (!monitor.setGuarding(*node, *timeMs, life, &error))
            return failure(kVerb, error);  // listen-only is refused there
        std::printf("guarding node %d: RTR on 0x%X every %d ms, lost after %d ms without a right answer\n", *node,
                    0x700 + *node, *timeMs, *timeMs * life);
    }
    std::fflush(stdout);
    const RunEnd end = waitWhileRunning(
        session.bus(), [] { return true; }, seconds, &error);
    const canopen::ErrorControlWatch w = monitor.watch(*node);
    const auto info = monitor.table().node(*node);
    if (heartbeat) std::printf("node %d: %s; lost %u time(s)\n", *node, qPrintable(statusName(w.status)), w.lost);
    else
        std::printf("node %d: %s; %llu guarding requests, %d guarding errors, lost %u time(s)\n", *node,
                    qPrintable(statusName(w.status)), static_cast<unsigned long long>(monitor.guardRequests(*node)),
                    info ? info->guardingErrors : 0, w.lost);
    std::fflush(stdout);
    if (end == RunEnd::BusFailed) return failure(kVerb, error);
    if (w.lost) return failure(kVerb, QStringLiteral("node %1 was lost %2 time(s)").arg(*node).arg(w.lost));
    return Ok;
}

COSCOPE_CLI_VERB({QStringLiteral("guard"),
                  QStringLiteral("Node guarding (or --heartbeat watch) of one node; prints ok/late/lost."), runGuard});

}  // namespace coscope::cli
