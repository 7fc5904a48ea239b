// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli pdo dbc LOG OUT.dbc [--dict NODE=NAME|FILE]... [--signal NAME=...]...
// The PDO layout in force at the end of a log (dictionary defaults, then what SDO writes in the
// log changed) as a DBC file (dissectors/DbcExport.h), with the raw signals given.
#include "app/cli/CliVerb.h"
#include "core/logio/LogFormats.h"
#include "dissectors/DbcExport.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/RawSignal.h"

#include <QFile>
#include <QFileInfo>

#include <cstdio>

namespace coscope::cli {

namespace {

int runDbc(const QStringList& args) {
    const QString verb = QStringLiteral("pdo dbc");
    QCommandLineParser p;
    p.setApplicationDescription(QStringLiteral(
        "Export the PDO layout in force at the end of a log (dictionary defaults plus what SDO writes in the log changed) as a DBC "
        "file: one message per TPDO/RPDO, the mapped objects as Intel signals with the dictionary's scaling, the object index:sub "
        "as comments. Raw signals given with --signal are exported too."));
    p.addPositionalArgument(QStringLiteral("LOG"), QStringLiteral("Log file (candump, asc, blf, trc, pcap/pcapng, csv)."));
    p.addPositionalArgument(QStringLiteral("OUT"), QStringLiteral("DBC file to write."));
    const QCommandLineOption dictOpt(QStringLiteral("dict"), QStringLiteral("Dictionary of a node: bundled name or EDS/DCF/XDD file (repeatable)."),
                                     QStringLiteral("NODE=NAME|FILE"));
    const QCommandLineOption sigOpt(QStringLiteral("signal"),
                                    QStringLiteral("Raw signal to export too (repeatable), as for decode: TYPE u, s or f, @0 after it for Motorola."),
                                    QStringLiteral("NAME=COBID:START:LEN:TYPE[:FACTOR[:OFFSET[:UNIT]]]"));
    const QCommandLineOption noIdentity(QStringLiteral("no-identity"), QStringLiteral("Do not pick dictionaries by the identity read in the log."));
    p.addOptions({dictOpt, sigOpt, noIdentity});
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2) return usageError(verb, QStringLiteral("expects LOG OUT.dbc"));
    std::vector<dissect::RawSignal> raw;
    for (const QString& spec : p.values(sigOpt)) {
        QString error;
        const auto r = dissect::RawSignal::parse(spec, &error);
        if (!r) return usageError(verb, error);
        raw.push_back(*r);
    }
    dissect::NetworkContext ctx;
    ctx.setIdentityMatching(!p.isSet(noIdentity));
    for (const QString& spec : p.values(dictOpt)) {
        const qsizetype eq = spec.indexOf(u'=');
        bool ok = false;
        const int node = eq > 0 ? spec.left(eq).toInt(&ok, 0) : 0;
        if (!ok || node < 1 || node > 127) return usageError(verb, QStringLiteral("--dict '%1': expected NODE=NAME|FILE with NODE 1..127").arg(spec));
        QString error;
        if (!ctx.assignDictionary(node, spec.mid(eq + 1), &error)) return failure(verb, QStringLiteral("--dict %1: %2").arg(spec, error));
    }
    if (!QFileInfo(pos[0]).isFile()) return failure(verb, QStringLiteral("%1: no such log file").arg(pos[0]));
    QString error;
    auto reader = logio::LogFormats::openReader(pos[0], &error);
    if (!reader) return failure(verb, error);
    dissect::Dissection d;
    std::vector<CanFrame> batch(4096);
    while (const size_t n = reader->read(batch.data(), batch.size()))
        for (size_t i = 0; i < n; ++i) ctx.dissect(batch[i], d, dissect::Dissection::Level::Stats);
    if (reader->hasError()) return failure(verb, QStringLiteral("%1: %2").arg(pos[0], reader->errorString()));
    int pdos = 0;
    const QByteArray dbc = dissect::pdoLayoutDbc(ctx, raw, 0, &pdos);
    QFile out(pos[1]);
    if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate) || out.write(dbc) != dbc.size() || !out.flush())
        return failure(verb, QStringLiteral("%1: %2").arg(pos[1], out.errorString()));
    std::printf("%s: %d PDO messages, %zu raw signals\n", qPrintable(pos[1]), pdos, raw.size());
    if (!pdos && raw.empty())
        std::fprintf(stderr, "coscope-cli pdo dbc: warning: no PDO mapping is known (give --dict NODE=NAME, or a log with the mapping's SDO writes)\n");
    return Ok;
}

}  // namespace

COSCOPE_CLI_VERB({QStringLiteral("pdo dbc"), QStringLiteral("Export the PDO layout in force (and raw signals) as a DBC file."), runDbc});

}  // namespace coscope::cli
