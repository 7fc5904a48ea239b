// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli nmt BUS start|stop|preop|reset|reset-comm NODE|all
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "core/canopen/NmtMaster.h"
#include "core/canopen/ServiceWait.h"

#include <QTextStream>

namespace coscope::cli {

static int runNmt(const QStringList& args) {
    const QString verb = QStringLiteral("nmt");
    QCommandLineParser p;
    p.setApplicationDescription(
        QStringLiteral("Send an NMT node control command (CiA 301 7.2.8.3.1) to one node or all."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL"));
    p.addPositionalArgument(QStringLiteral("COMMAND"), QStringLiteral("start, stop, preop, reset or reset-comm"));
    p.addPositionalArgument(QStringLiteral("NODE"), QStringLiteral("Node-ID 1-127 or all"));
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 3)
        return usageError(verb, QStringLiteral("expects BUS start|stop|preop|reset|reset-comm NODE|all"));
    const auto cmd = canopen::nmtCommandFromName(pos[1].toLower());
    if (!cmd)
        return usageError(
            verb, QStringLiteral("unknown command '%1'; use start, stop, preop, reset or reset-comm").arg(pos[1]));
    const auto node = parseNodeId(pos[2], true);
    if (!node) return usageError(verb, QStringLiteral("node '%1' must be 1-127 or all").arg(pos[2]));

    BusSession s;
    QString error;
    if (!s.open(pos[0], &error)) return failure(verb, error);
    canopen::NmtMaster nmt(s.context());
    if (!nmt.send(*cmd, *node, &error)) return failure(verb, error);
    // Let the frame leave before the bus closes.
    canopen::waitUntil([&] { return s.bus()->counters().tx > 0; }, 1000);
    QTextStream(stdout) << canopen::nmtCommandName(static_cast<uint8_t>(*cmd)) << " -> "
                        << (*node ? QStringLiteral("node %1").arg(*node) : QStringLiteral("all nodes")) << "\n";
    return Ok;
}

COSCOPE_CLI_VERB({QStringLiteral("nmt"), QStringLiteral("Send an NMT command to a node or all nodes."), runNmt});

}  // namespace coscope::cli
