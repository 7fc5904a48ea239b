// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli sim: serves a network of virtual drives over the socketcand protocol.
#include "app/cli/CliVerb.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/SocketcandServer.h"
#include "eds/SimulatorDictionaries.h"

#include <QCoreApplication>
#include <QTextStream>
#include <QTimer>
#include <QUrl>

namespace coscope::cli {

static int runSim(const QStringList& args) {
    const QString verb = QStringLiteral("sim");
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Run virtual CANopen drives and serve their bus over the socketcand protocol (raw mode), for "
                       "python-can's socketcand interface or coscope socketcand://HOST:PORT/CHANNEL. Runs until "
                       "interrupted (Ctrl+C)."));
    parser.addOption(
        {QStringLiteral("nodes"),
         QStringLiteral("Virtual nodes as ID:DICTIONARY,... (default %1).").arg(sim::SimNetwork::defaultSpec()),
         QStringLiteral("SPEC")});
    parser.addOption(
        {QStringLiteral("listen"),
         QStringLiteral("Where to serve: socketcand://HOST:PORT[/CHANNEL] (default socketcand://127.0.0.1:29536; "
                        "port 0 picks a free port; only loopback unless a host is given)."),
         QStringLiteral("URL")});
    int code = 0;
    if (!parseArgs(parser, verb, args, &code)) return code;
    if (!parser.positionalArguments().isEmpty())
        return usageError(verb, QStringLiteral("takes no positional arguments"));

    const QString listen = parser.isSet(QStringLiteral("listen")) ? parser.value(QStringLiteral("listen"))
                                                                  : QStringLiteral("socketcand://127.0.0.1:29536");
    const QUrl url(listen, QUrl::StrictMode);
    if (!url.isValid() || url.scheme() != u"socketcand" || url.host().isEmpty() || url.port() < 0)
        return usageError(verb,
                          QStringLiteral("--listen must be socketcand://HOST:PORT[/CHANNEL], got '%1'").arg(listen));
    QHostAddress address;
    if (url.host() == u"localhost") address = QHostAddress::LocalHost;
    else if (!address.setAddress(url.host()))
        return usageError(verb,
                          QStringLiteral("--listen host must be an IP address or localhost, got '%1'").arg(url.host()));
    const QString channel = url.path().mid(1);

    eds::installSimulatorDictionaries();
    QString error;
    std::shared_ptr<sim::SimNetwork> network = sim::SimNetwork::fromSpec(parser.value(QStringLiteral("nodes")), &error);
    if (!network) return failure(verb, error);

    sim::SocketcandServer server(network);
    if (!channel.isEmpty()) server.setChannels({channel});
    if (!server.listen(address, static_cast<quint16>(url.port()), &error)) return failure(verb, error);
    network->start();

    const QString spec =
        parser.isSet(QStringLiteral("nodes")) ? parser.value(QStringLiteral("nodes")) : sim::SimNetwork::defaultSpec();
    QTextStream out(stdout);
    out << "serving " << network->nodes().size() << " virtual nodes (" << spec << ") on socketcand://"
        << address.toString() << ":" << server.serverPort() << "/"
        << (channel.isEmpty() ? QStringLiteral("can0") : channel) << "\n";
    out.flush();

    installInterruptHandler();
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, [] {
        if (interrupted()) QCoreApplication::quit();
    });
    poll.start(50);
    QCoreApplication::exec();
    network->stop();
    return Ok;
}

COSCOPE_CLI_VERB({QStringLiteral("sim"), QStringLiteral("Serve virtual CANopen drives over socketcand."), runSim});

}  // namespace coscope::cli
