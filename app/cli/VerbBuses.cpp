// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli buses: the bus schemes and the devices Qt's CAN plugins report.
#include "app/cli/CliVerb.h"
#include "core/can/BusUrl.h"
#include "core/can/SocketCanLinkJob.h"
#include "core/can/SocketCanLinks.h"
#include "core/logio/LogFormats.h"
#include "core/sim/SimNetwork.h"

#include <QCanBus>
#include <QTextStream>

namespace coscope::cli {

static int runBuses(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("List bus schemes and the CAN interfaces the Qt CAN plugins find."));
    const QCommandLineOption bringUp(
        QStringLiteral("bring-up"),
        QStringLiteral(
            "Bring the SocketCAN interface IFACE up (needs CAP_NET_ADMIN, e.g. root); set down first when up."),
        QStringLiteral("IFACE"));
    const QCommandLineOption bitrate(QStringLiteral("bitrate"),
                                     QStringLiteral("With --bring-up: the bit rate (default 500000)."),
                                     QStringLiteral("BPS"), QStringLiteral("500000"));
    const QCommandLineOption dataBitrate(QStringLiteral("data-bitrate"),
                                         QStringLiteral("With --bring-up: CAN FD data bit rate (turns FD on)."),
                                         QStringLiteral("BPS"));
    parser.addOptions({bringUp, bitrate, dataBitrate});
    int code = 0;
    if (!parseArgs(parser, QStringLiteral("buses"), args, &code)) return code;
    if (!parser.positionalArguments().isEmpty())
        return usageError(QStringLiteral("buses"), QStringLiteral("takes no arguments"));
    if (parser.isSet(bringUp)) {
        bool okRate = false, okData = true;
        const int rate = parser.value(bitrate).toInt(&okRate);
        const int data = parser.isSet(dataBitrate) ? parser.value(dataBitrate).toInt(&okData) : 0;
        if (!okRate || rate <= 0 || !okData || data < 0)
            return usageError(QStringLiteral("buses"),
                              QStringLiteral("--bitrate and --data-bitrate take a positive number of bit/s"));
        QString error;
        const QList<SocketCanLink> links = listSocketCanLinks(&error);
        const QString name = parser.value(bringUp);
        for (const SocketCanLink& l : links) {
            if (l.name != name) continue;
            if (!mayConfigureLinks())
                return failure(QStringLiteral("buses"),
                               QStringLiteral("no permission to configure %1 (needs CAP_NET_ADMIN); run: %2")
                                   .arg(name, bringUpCommand(l, rate, data)));
            if (!bringUpLink(l, rate, data, &error)) return failure(QStringLiteral("buses"), error);
            for (const SocketCanLink& now : listSocketCanLinks(&error))
                if (now.name == name) QTextStream(stdout) << name << ": " << describeLink(now) << "\n";
            return Ok;
        }
        return failure(QStringLiteral("buses"),
                       error.isEmpty() ? QStringLiteral("there is no CAN interface named '%1'").arg(name) : error);
    }

    QTextStream out(stdout);
    out << "Schemes:\n";
    out << "  socketcand://HOST:PORT/CHANNEL   remote CAN over the socketcand protocol\n";
    out << "  sim://?nodes=1:delta-asda-a2,...  in-process virtual drives\n";
    out << "  replay://PATH?speed=1.0&loop=1     play a log file with its timing\n";
    const QStringList plugins = qtCanPlugins();
    for (const QString& p : plugins)
        out << "  " << (p + QStringLiteral("://DEVICE")).leftJustified(33) << "Qt CAN plugin\n";
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
    // Logs for replay:// and convert, found by their content.
    out << "\nLog formats (r = read, w = write):\n";
    for (const auto& f : logio::LogFormats::all()) {
        QStringList ext;
        for (const QString& e : f.extensions) ext << QStringLiteral("*.") + e;
        out << "  " << f.name.leftJustified(10) << (f.canRead ? "r" : "-") << (f.canWrite ? "w" : "-") << "  "
            << f.description << "  (" << ext.join(QLatin1Char(' ')) << ")\n";
    }
    return Ok;
}

COSCOPE_CLI_VERB({QStringLiteral("buses"), QStringLiteral("List bus schemes and CAN interfaces found."), runBuses});

}  // namespace coscope::cli
