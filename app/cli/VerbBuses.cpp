// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli buses: the bus schemes and the devices Qt's CAN plugins report.
#include "app/cli/CliVerb.h"
#include "core/can/BusUrl.h"
#include "core/can/SocketCanLinks.h"
#include "core/sim/SimNetwork.h"

#include <QCanBus>
#include <QTextStream>

namespace coscope::cli {

static int runBuses(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral("List bus schemes and the CAN interfaces the Qt CAN plugins find."));
    int code = 0;
    if (!parseArgs(parser, QStringLiteral("buses"), args, &code)) return code;
    if (!parser.positionalArguments().isEmpty()) return usageError(QStringLiteral("buses"), QStringLiteral("takes no arguments"));

    QTextStream out(stdout);
    out << "Schemes:\n";
    out << "  socketcand://HOST:PORT/CHANNEL   remote CAN over the socketcand protocol\n";
    out << "  sim://?nodes=1:delta-asda-a2,...  in-process virtual drives\n";
    out << "  replay://PATH?speed=1.0&loop=1     play a log file with its timing\n";
    const QStringList plugins = qtCanPlugins();
    for (const QString& p : plugins) out << "  " << (p + QStringLiteral("://DEVICE")).leftJustified(33) << "Qt CAN plugin\n";
    out << "\nDevices:\n";
    int found = 0;
    for (const QString& p : plugins) {
        QString error;
        const auto devices = QCanBus::instance()->availableDevices(p, &error);
        QList<SocketCanLink> links;
        if (p == u"socketcan") links = listSocketCanLinks(&error);
        for (const auto& d : devices) {
            out << "  " << p << "://" << d.name();
            for (const SocketCanLink& l : links)
                if (l.name == d.name()) out << "  " << describeLink(l);
            if (!d.description().isEmpty()) out << "  (" << d.description() << ")";
            if (d.hasFlexibleDataRate()) out << "  [CAN FD]";
            if (d.isVirtual()) out << "  [virtual]";
            if (!pluginProbesHardware(p)) out << "  [unverified: the plugin lists it without finding an adapter]";
            out << "\n";
            ++found;
        }
    }
    out << "  sim://  (default virtual network: nodes " << sim::SimNetwork::defaultSpec() << ")\n";
    if (!found) out << "  (no CAN adapters found by the Qt plugins)\n";
    return Ok;
}

COSCOPE_CLI_VERB({QStringLiteral("buses"), QStringLiteral("List bus schemes and CAN interfaces found."), runBuses});

}  // namespace coscope::cli
