// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli stats LOG [--format text|json|html] [--per-second] [--dict NODE=NAME|FILE]...
// [--bitrate N]: the network health report (findings, per node heartbeat/NMT/SDO/EMCY, PDOs, bus
// load; DESIGN.md "Contracts"), then in text the frames per COB-ID and service and the warnings.
#include "app/cli/CliVerb.h"
#include "core/logio/LogFormats.h"
#include "core/logio/ReadAhead.h"
#include "dissectors/BusLoad.h"
#include "dissectors/HealthOutput.h"
#include "dissectors/NetworkHealth.h"
#include "dissectors/TraceStats.h"

#include <QFileInfo>
#include <QJsonDocument>

#include <cstdio>
#include <vector>

namespace coscope::cli {

namespace {

const QString kVerb = QStringLiteral("stats");

int runStats(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Network health report of a CAN log decoded as CANopen: findings, heartbeat/NMT, SDO, EMCY, PDO "
                       "and bus load."));
    parser.addPositionalArgument(QStringLiteral("LOG"),
                                 QStringLiteral("Log file (candump, asc, blf, trc, pcap/pcapng, csv, mf4)."));
    parser.addOption({QStringLiteral("dict"),
                      QStringLiteral("Dictionary of a node: bundled name or EDS/DCF/XDD file (repeatable)."),
                      QStringLiteral("NODE=NAME|FILE")});
    parser.addOption({QStringLiteral("bitrate"), QStringLiteral("Bit rate for the bus load estimate (default 500000)."),
                      QStringLiteral("BIT/S"), QStringLiteral("500000")});
    parser.addOption({QStringLiteral("format"),
                      QStringLiteral("text (default), json or html (one self-contained page)."),
                      QStringLiteral("FORMAT"), QStringLiteral("text")});
    parser.addOption({QStringLiteral("per-second"), QStringLiteral("Text: add the bus load of every second.")});
    int code = 0;
    if (!parseArgs(parser, kVerb, args, &code)) return code;
    const QStringList pos = parser.positionalArguments();
    if (pos.size() != 1) return usageError(kVerb, QStringLiteral("expected one LOG file"));
    bool ok = false;
    const int bitRate = parser.value(QStringLiteral("bitrate")).toInt(&ok);
    if (!ok || bitRate < 1000 || bitRate > 10000000)
        return usageError(kVerb, QStringLiteral("--bitrate must be 1000..10000000"));
    const QString format = parser.value(QStringLiteral("format"));
    if (format != QLatin1String("text") && format != QLatin1String("json") && format != QLatin1String("html"))
        return usageError(kVerb, QStringLiteral("--format must be text, json or html"));
    const bool perSecond = parser.isSet(QStringLiteral("per-second"));
    dissect::TraceStats stats(bitRate);
    dissect::NetworkHealth health(bitRate);
    for (const QString& spec : parser.values(QStringLiteral("dict"))) {
        const qsizetype eq = spec.indexOf(u'=');
        const int node = eq > 0 ? spec.left(eq).toInt(&ok, 0) : 0;
        if (!ok || node < 1 || node > 127)
            return usageError(kVerb, QStringLiteral("--dict '%1': expected NODE=NAME|FILE with NODE 1..127").arg(spec));
        QString error;
        if (!stats.context().assignDictionary(node, spec.mid(eq + 1), &error))
            return failure(kVerb, QStringLiteral("--dict %1: %2").arg(spec, error));
    }
    QString error;
    auto reader = logio::LogFormats::openReader(pos[0], &error);
    if (!reader) return failure(kVerb, error);
    // The bus load needs only the frames: counted once, for both reports, on the thread that
    // reads the file, while this one decodes.
    dissect::BusLoad load;
    stats.useBusLoad(&load);
    health.useBusLoad(&load);
    {
        // Parsing the file and counting run on two cores.
        logio::ReadAhead ahead(*reader, logio::ReadAhead::kBatchFrames, logio::ReadAhead::kDepth,
                               [&load](std::span<const CanFrame> batch) {
                                   for (const CanFrame& f : batch) load.add(f);
                               });
        for (auto batch = ahead.next(); !batch.empty(); batch = ahead.next())
            for (const CanFrame& f : batch) {
                stats.add(f);
                health.add(f, stats.lastDissection(), stats.context());
            }
    }
    stats.setBusNames(reader->busNames());
    const dissect::HealthReport hr = health.report(&stats.context());
    QByteArray report;
    if (format == QLatin1String("json"))
        report = QJsonDocument(dissect::healthJson(hr)).toJson(QJsonDocument::Indented);
    else if (format == QLatin1String("html"))
        report =
            dissect::healthHtml(hr, QStringLiteral("CoScope network health: %1").arg(QFileInfo(pos[0]).fileName()));
    else report = dissect::healthText(hr, false) + "\nTrace:\n" + stats.report(perSecond);
    std::fwrite(report.constData(), 1, static_cast<size_t>(report.size()), stdout);
    // Text: a line at the end; json/html keep stdout to the document and say it on stderr.
    if (reader->diagnosticCount())
        std::fprintf(format == QLatin1String("text") ? stdout : stderr,
                     "\nLog problems: %llu (first: line/record %lld: %s)\n",
                     (unsigned long long)reader->diagnosticCount(),
                     reader->diagnostics().empty() ? 0LL : static_cast<long long>(reader->diagnostics().front().where),
                     reader->diagnostics().empty() ? "" : qPrintable(reader->diagnostics().front().message));
    std::fflush(stdout);
    if (reader->hasError()) return failure(kVerb, QStringLiteral("%1: %2").arg(pos[0], reader->errorString()));
    return Ok;
}

}  // namespace

COSCOPE_CLI_VERB({QStringLiteral("stats"),
                  QStringLiteral("Network health report of a log: findings, heartbeat, NMT, SDO, EMCY, PDO, bus load."),
                  runStats});

}  // namespace coscope::cli
