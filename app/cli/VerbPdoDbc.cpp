// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli pdo dbc LOG|BUS OUT.dbc [--dict NODE=NAME|FILE]... [--node N]... [--signal NAME=...]...
// The PDO layout in force at the end of a log (dictionary defaults, then what SDO writes in the
// log changed), or read from the nodes of a bus over SDO as `pdo show` does, as a DBC file
// (dissectors/DbcExport.h), with the raw signals given.
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "core/canopen/PdoConfigurator.h"
#include "core/canopen/ServiceWait.h"
#include "core/logio/LogFormats.h"
#include "dissectors/DbcExport.h"
#include "dissectors/NetworkContext.h"
#include "dissectors/RawSignal.h"

#include <QFile>
#include <QFileInfo>

#include <cstdio>
#include <map>

namespace coscope::cli {

namespace {

int writeDbc(const QString& verb, const dissect::NetworkContext& ctx, const std::vector<dissect::RawSignal>& raw,
             const QString& path) {
    int pdos = 0;
    const QByteArray dbc = dissect::pdoLayoutDbc(ctx, raw, 0, &pdos);
    QFile out(path);
    if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate) || out.write(dbc) != dbc.size() || !out.flush())
        return failure(verb, QStringLiteral("%1: %2").arg(path, out.errorString()));
    std::printf("%s: %d PDO messages, %zu raw signals\n", qPrintable(path), pdos, raw.size());
    if (!pdos && raw.empty())
        std::fprintf(stderr,
                     "coscope-cli pdo dbc: warning: no PDO mapping is known (give --dict NODE=NAME, or a log with the "
                     "mapping's SDO writes)\n");
    return Ok;
}

// The PDO layout of `nodes` read over SDO (1400h..1BFFh, as `pdo show`) into `ctx`.
bool readBus(const QString& url, const std::map<int, QString>& nodes, dissect::NetworkContext& ctx, QString* error) {
    BusSession s;
    if (!s.open(url, error)) return false;
    for (const auto& [node, dictOption] : nodes) {
        QString name, why;
        auto dict = s.nodeDictionary(static_cast<uint8_t>(node), dictOption, &name, &why);
        if (!dict && !dictOption.isEmpty()) {
            *error = QStringLiteral("node %1: %2").arg(node).arg(why);
            return false;
        }
        if (dict) ctx.assignDictionary(node, std::make_shared<const od::ObjectDictionary>(std::move(*dict)), name);
        canopen::PdoConfigurator pdo(s.sdo());
        std::optional<std::vector<canopen::PdoReadResult>> set;
        pdo.readSet(static_cast<uint8_t>(node), [&](const auto& r) { set = r; });
        canopen::waitUntil([&] { return set.has_value(); }, 120000);
        if (!set) {
            *error = QStringLiteral("no answer from node %1").arg(node);
            return false;
        }
        dissect::NodeState& ns = ctx.nodeForEdit(node);
        ns.seen = true;
        for (const canopen::PdoReadResult& r : *set) {
            if (!r.ok) continue;
            dissect::PdoConfig& cfg = ns.pdo(r.pdo.transmit, r.pdo.number);
            cfg.cobId = r.config.cobId;
            cfg.cobIdKnown = true;
            cfg.entries.clear();
            for (const canopen::PdoMapEntry& e : r.config.entries)
                cfg.entries.push_back(dissect::makeMapEntry(e.encode(), ctx.namesFor(node)));
            cfg.count = static_cast<uint8_t>(cfg.entries.size());
            cfg.mappingKnown = true;
        }
    }
    return true;
}

int runDbc(const QStringList& args) {
    const QString verb = QStringLiteral("pdo dbc");
    QCommandLineParser p;
    p.setApplicationDescription(
        QStringLiteral("Export the PDO layout in force at the end of a log (dictionary defaults plus what SDO writes "
                       "in the log changed) as a DBC "
                       "file: one message per TPDO/RPDO, the mapped objects as Intel signals with the dictionary's "
                       "scaling, the object index:sub "
                       "as comments. Raw signals given with --signal are exported too."));
    p.addPositionalArgument(QStringLiteral("LOG|BUS"),
                            QStringLiteral("Log file (candump, asc, blf, trc, pcap/pcapng, csv, mf4), or a bus URL "
                                           "whose nodes (--node, --dict) are read over SDO."));
    p.addPositionalArgument(QStringLiteral("OUT"), QStringLiteral("DBC file to write."));
    const QCommandLineOption dictOpt(
        QStringLiteral("dict"), QStringLiteral("Dictionary of a node: bundled name or EDS/DCF/XDD file (repeatable)."),
        QStringLiteral("NODE=NAME|FILE"));
    const QCommandLineOption sigOpt(
        QStringLiteral("signal"),
        QStringLiteral(
            "Raw signal to export too (repeatable), as for decode: TYPE u, s or f, @0 after it for Motorola."),
        QStringLiteral("NAME=COBID:START:LEN:TYPE[:FACTOR[:OFFSET[:UNIT]]]"));
    const QCommandLineOption nodeOpt(
        QStringLiteral("node"),
        QStringLiteral("BUS: a node to read the PDOs of (repeatable; the --dict nodes are read too)."),
        QStringLiteral("N"));
    const QCommandLineOption noIdentity(QStringLiteral("no-identity"),
                                        QStringLiteral("Do not pick dictionaries by the identity read in the log."));
    p.addOptions({dictOpt, sigOpt, nodeOpt, noIdentity});
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
    std::map<int, QString> dicts;
    for (const QString& spec : p.values(dictOpt)) {
        const qsizetype eq = spec.indexOf(u'=');
        bool ok = false;
        const int node = eq > 0 ? spec.left(eq).toInt(&ok, 0) : 0;
        if (!ok || node < 1 || node > 127)
            return usageError(verb, QStringLiteral("--dict '%1': expected NODE=NAME|FILE with NODE 1..127").arg(spec));
        dicts[node] = spec.mid(eq + 1);
    }
    QString error;
    const bool isBus = pos[0].contains(QStringLiteral("://"));
    if (isBus) {
        for (const QString& n : p.values(nodeOpt)) {
            const auto node = parseNodeId(n);
            if (!node) return usageError(verb, QStringLiteral("--node '%1' must be 1-127").arg(n));
            dicts.emplace(*node, QString());
        }
        if (dicts.empty())
            return usageError(verb, QStringLiteral("a bus needs the nodes to read: --node N or --dict NODE=NAME"));
        if (!readBus(pos[0], dicts, ctx, &error)) return failure(verb, error);
        return writeDbc(verb, ctx, raw, pos[1]);
    }
    for (const auto& [node, name] : dicts)
        if (!ctx.assignDictionary(node, name, &error))
            return failure(verb, QStringLiteral("--dict %1=%2: %3").arg(node).arg(name, error));
    if (!QFileInfo(pos[0]).isFile()) return failure(verb, QStringLiteral("%1: no such log file").arg(pos[0]));
    auto reader = logio::LogFormats::openReader(pos[0], &error);
    if (!reader) return failure(verb, error);
    dissect::Dissection d;
    std::vector<CanFrame> batch(4096);
    while (const size_t n = reader->read(batch.data(), batch.size()))
        for (size_t i = 0; i < n; ++i) ctx.dissect(batch[i], d, dissect::Dissection::Level::Stats);
    if (reader->hasError()) return failure(verb, QStringLiteral("%1: %2").arg(pos[0], reader->errorString()));
    return writeDbc(verb, ctx, raw, pos[1]);
}

}  // namespace

COSCOPE_CLI_VERB({QStringLiteral("pdo dbc"),
                  QStringLiteral("Export the PDO layout in force (and raw signals) as a DBC file."), runDbc});

}  // namespace coscope::cli
