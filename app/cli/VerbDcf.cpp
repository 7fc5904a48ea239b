// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli dcf export / dcf apply: a node's actual values as a CiA 306 DCF (ParameterValue),
// and a DCF written back to a node: plan first, write only with --yes, every entry reported.
// dcf concise: a DCF as the concise DCF of CiA 302-3 (1F22h), offline.
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "core/canopen/ConciseDcf.h"
#include "core/canopen/DeviceConfiguration.h"
#include "core/canopen/ServiceWait.h"
#include "eds/DcfWriter.h"
#include "eds/EdsReader.h"

#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QTextStream>

namespace coscope::cli {

namespace {

using canopen::ApplyPlan;
using canopen::ApplyScope;
using canopen::ConfigEntryResult;
using canopen::ConfigReadResult;
using canopen::DeviceConfiguration;

QCommandLineOption timeoutOption() {
    return {QStringLiteral("timeout"), QStringLiteral("SDO timeout per response in ms (default 1000)."),
            QStringLiteral("MS"), QStringLiteral("1000")};
}

bool parseTimeout(const QCommandLineParser& p, const QCommandLineOption& o, int* ms) {
    bool ok = false;
    *ms = p.value(o).toInt(&ok);
    return ok && *ms > 0;
}

// Runs a read of `entries` (all readable ones when empty) and waits for it.
std::optional<ConfigReadResult> readValues(BusSession& s, uint8_t node, const od::ObjectDictionary& dict,
                                           const std::vector<std::pair<uint16_t, uint8_t>>* entries,
                                           bool includeDomains) {
    DeviceConfiguration config(s.sdo());
    std::optional<ConfigReadResult> out;
    canopen::ConfigReadOptions options;
    options.includeDomains = includeDomains;
    auto done = [&out](const ConfigReadResult& r) { out = r; };
    if (entries) config.read(node, dict, *entries, {}, done, options);
    else config.read(node, dict, {}, done, options);
    canopen::waitUntil([&] { return out.has_value(); }, 3600000);
    return out;
}

int runExport(const QStringList& args) {
    const QString verb = QStringLiteral("dcf export");
    QCommandLineParser p;
    p.setApplicationDescription(QStringLiteral(
        "Read every readable object of a node over SDO and save the values as a DCF (CiA 306 ParameterValue)."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL, e.g. socketcan://can0 or sim://"));
    p.addPositionalArgument(QStringLiteral("NODE"), QStringLiteral("Node-ID 1-127"));
    p.addPositionalArgument(QStringLiteral("OUT.dcf"), QStringLiteral("The DCF to write"));
    const QCommandLineOption dict{
        QStringLiteral("dict"),
        QStringLiteral("Dictionary file or library name for the node (default: matched by its 1018h identity)."),
        QStringLiteral("FILE|NAME")};
    const QCommandLineOption domains{QStringLiteral("include-domains"),
                                     QStringLiteral("Also read DOMAIN objects (may be large).")};
    const QCommandLineOption timeout = timeoutOption();
    p.addOptions({dict, domains, timeout});
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 3) return usageError(verb, QStringLiteral("expects BUS NODE OUT.dcf"));
    const auto node = parseNodeId(pos[1]);
    if (!node) return usageError(verb, QStringLiteral("node-ID '%1' must be 1-127").arg(pos[1]));
    int timeoutMs = 0;
    if (!parseTimeout(p, timeout, &timeoutMs))
        return usageError(verb, QStringLiteral("--timeout must be a positive number of ms"));

    BusSession s;
    QString error;
    if (!s.open(pos[0], &error)) return failure(verb, error);
    s.sdo().setDefaultTimeout(timeoutMs);
    QString dictName;
    auto dictionary = s.nodeDictionary(*node, p.value(dict), &dictName, &error);
    if (!dictionary) return failure(verb, error + (p.isSet(dict) ? QString() : QStringLiteral(" (give --dict)")));

    const auto result = readValues(s, *node, *dictionary, nullptr, p.isSet(domains));
    if (!result) return failure(verb, QStringLiteral("node %1 did not finish answering").arg(*node));
    QTextStream err(stderr);
    for (const ConfigEntryResult& e : result->entries)
        if (!e.ok) err << "coscope-cli dcf export: warning: " << e.error << "\n";
    const int read = static_cast<int>(result->entries.size()) - result->failed;
    if (read == 0)
        return failure(verb,
                       QStringLiteral("node %1 answered no read (%2 tried)").arg(*node).arg(result->entries.size()));

    od::ObjectDictionary out = result->values;
    const QDateTime now = QDateTime::currentDateTime();
    out.fileInfo.fileName = QFileInfo(pos[2]).fileName();
    out.fileInfo.modificationDate = now.toString(QStringLiteral("MM-dd-yyyy"));
    out.fileInfo.modificationTime = now.toString(QStringLiteral("hh:mmAP"));
    out.fileInfo.modifiedBy = QStringLiteral("CoScope");
    out.fileInfo.description = QStringLiteral("Actual values of node %1 (%2)").arg(*node).arg(dictName);
    if (!eds::DcfWriter::writeFile(out, pos[2], &error)) return failure(verb, error);
    QTextStream(stdout) << "node " << *node << " (" << dictName << "): " << read << " values read, " << result->failed
                        << " failed; written to " << pos[2] << "\n";
    return Ok;
}

void printPlan(QTextStream& out, const ApplyPlan& plan, bool showSkipped) {
    for (const auto& w : plan.writes) {
        out << "  write " << canopen::objectRef(w.index, w.sub) << " " << w.name << " (" << od::dataTypeName(w.type)
            << ") = " << w.valueText;
        if (!w.currentText.isEmpty()) out << "  (now " << w.currentText << ")";
        out << "\n";
    }
    if (showSkipped)
        for (const auto& sk : plan.skipped)
            out << "  skip  " << canopen::objectRef(sk.index, sk.sub) << " " << sk.name << ": " << sk.reason << "\n";
}

int runApply(const QStringList& args) {
    const QString verb = QStringLiteral("dcf apply");
    QCommandLineParser p;
    p.setApplicationDescription(
        QStringLiteral("Write the ParameterValue entries of a DCF to a node over SDO. By default the node's current "
                       "values are read first and only "
                       "those that differ are written. Nothing is written without --yes; --dry-run shows the writes."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL, e.g. socketcan://can0 or sim://"));
    p.addPositionalArgument(QStringLiteral("NODE"), QStringLiteral("Node-ID 1-127"));
    p.addPositionalArgument(QStringLiteral("IN.dcf"), QStringLiteral("The DCF to apply"));
    const QCommandLineOption dryRun{QStringLiteral("dry-run"),
                                    QStringLiteral("Show what would be written; write nothing.")};
    const QCommandLineOption yes{QStringLiteral("yes"), QStringLiteral("Write without asking (required to write).")};
    const QCommandLineOption all{
        QStringLiteral("all"),
        QStringLiteral("Write every writable ParameterValue, also those equal to the node's value (no read first).")};
    const QCommandLineOption verbose{QStringLiteral("verbose"),
                                     QStringLiteral("Also list the entries that are not written and why.")};
    const QCommandLineOption timeout = timeoutOption();
    p.addOptions({dryRun, yes, all, verbose, timeout});
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 3) return usageError(verb, QStringLiteral("expects BUS NODE IN.dcf"));
    const auto node = parseNodeId(pos[1]);
    if (!node) return usageError(verb, QStringLiteral("node-ID '%1' must be 1-127").arg(pos[1]));
    int timeoutMs = 0;
    if (!parseTimeout(p, timeout, &timeoutMs))
        return usageError(verb, QStringLiteral("--timeout must be a positive number of ms"));
    if (p.isSet(dryRun) && p.isSet(yes))
        return usageError(verb, QStringLiteral("--dry-run and --yes exclude each other"));

    eds::ReadResult dcf = eds::readDictionaryFile(pos[2]);
    if (!dcf.usable) {
        const QString first =
            dcf.diagnostics.empty() ? QStringLiteral("no object could be read") : dcf.diagnostics.front().toString();
        return failure(verb, QStringLiteral("%1: not a usable DCF: %2").arg(pos[2], first));
    }
    QTextStream out(stdout);
    QTextStream err(stderr);
    if (dcf.dictionary.nodeId() != 0 && dcf.dictionary.nodeId() != *node)
        err << "coscope-cli dcf apply: warning: " << pos[2] << " was made for node " << dcf.dictionary.nodeId()
            << "; writing to node " << *node << " ($NODEID values use " << *node << ")\n";

    BusSession s;
    QString error;
    if (!s.open(pos[0], &error)) return failure(verb, error);
    s.sdo().setDefaultTimeout(timeoutMs);

    ApplyPlan plan = DeviceConfiguration::plan(*node, dcf.dictionary, nullptr, ApplyScope::AllValues);
    if (!p.isSet(all) && !plan.writes.empty()) {
        // Read the node's current values of the candidates, then keep only what differs.
        const auto entries = DeviceConfiguration::planEntries(plan);
        const auto current = readValues(s, *node, dcf.dictionary, &entries, true);
        if (!current) return failure(verb, QStringLiteral("node %1 did not finish answering the reads").arg(*node));
        plan = DeviceConfiguration::plan(*node, dcf.dictionary, &current->values, ApplyScope::OnlyDifferent);
    }
    const int n = static_cast<int>(plan.writes.size());
    out << "node " << *node << ": " << n << " object(s) to write from " << pos[2] << " (" << plan.skipped.size()
        << " not written" << (p.isSet(verbose) || p.isSet(dryRun) ? "" : "; --verbose lists them") << ")\n";
    printPlan(out, plan, p.isSet(verbose) || p.isSet(dryRun));
    out.flush();
    if (p.isSet(dryRun)) return Ok;
    if (n == 0) return Ok;
    if (!p.isSet(yes))
        return failure(verb, QStringLiteral("would write %1 object(s) to node %2; nothing written: give --yes to write "
                                            "them (or --dry-run to only list them)")
                                 .arg(n)
                                 .arg(*node));

    DeviceConfiguration config(s.sdo());
    std::optional<std::vector<ConfigEntryResult>> results;
    config.apply(
        plan, {}, [&results](const std::vector<ConfigEntryResult>& r, bool) { results = r; }, timeoutMs);
    canopen::waitUntil([&] { return results.has_value(); }, 3600000);
    if (!results) return failure(verb, QStringLiteral("node %1 did not finish answering the writes").arg(*node));
    int failed = 0;
    for (const ConfigEntryResult& r : *results) {
        if (r.ok) {
            out << "  ok     " << canopen::objectRef(r.index, r.sub) << " " << r.name << " = " << r.valueText << "\n";
        } else {
            ++failed;
            out << "  FAILED " << canopen::objectRef(r.index, r.sub) << " " << r.name << " = " << r.valueText << ": "
                << r.error << "\n";
        }
    }
    out.flush();
    if (failed)
        return failure(
            verb, QStringLiteral("%1 of %2 write(s) to node %3 failed").arg(failed).arg(results->size()).arg(*node));
    out << "node " << *node << ": " << results->size() << " object(s) written\n";
    return Ok;
}

int runConcise(const QStringList& args) {
    const QString verb = QStringLiteral("dcf concise");
    QCommandLineParser p;
    p.setApplicationDescription(
        QStringLiteral("Write the ParameterValue entries of a DCF as a concise DCF (CiA 302-3, the value of object "
                       "1F22h that a master writes to the node at "
                       "boot): UNSIGNED32 number of entries, then per entry UNSIGNED16 index, UNSIGNED8 sub-index, "
                       "UNSIGNED32 size and the data, "
                       "little-endian. Holds what 'dcf apply --all' writes, in the same order. Sends nothing."));
    p.addPositionalArgument(QStringLiteral("IN.dcf"), QStringLiteral("The DCF"));
    p.addPositionalArgument(QStringLiteral("OUT.bin"), QStringLiteral("The concise DCF to write"));
    const QCommandLineOption nodeOption{
        QStringLiteral("node"),
        QStringLiteral("Node-ID for $NODEID values (default: the DCF's [DeviceCommissioning] NodeID)."),
        QStringLiteral("NODE")};
    const QCommandLineOption verbose{QStringLiteral("verbose"),
                                     QStringLiteral("List the entries and those left out, and why.")};
    p.addOptions({nodeOption, verbose});
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2) return usageError(verb, QStringLiteral("expects IN.dcf OUT.bin"));
    eds::ReadResult dcf = eds::readDictionaryFile(pos[0]);
    if (!dcf.usable) {
        const QString first =
            dcf.diagnostics.empty() ? QStringLiteral("no object could be read") : dcf.diagnostics.front().toString();
        return failure(verb, QStringLiteral("%1: not a usable DCF: %2").arg(pos[0], first));
    }
    std::optional<uint8_t> node;
    if (p.isSet(nodeOption)) {
        node = parseNodeId(p.value(nodeOption));
        if (!node) return usageError(verb, QStringLiteral("node-ID '%1' must be 1-127").arg(p.value(nodeOption)));
    } else if (dcf.dictionary.nodeId() >= 1 && dcf.dictionary.nodeId() <= 127) {
        node = static_cast<uint8_t>(dcf.dictionary.nodeId());
    } else {
        return usageError(verb, QStringLiteral("%1 names no node-ID: give --node").arg(pos[0]));
    }
    const ApplyPlan plan = DeviceConfiguration::plan(*node, dcf.dictionary, nullptr, ApplyScope::AllValues);
    const QByteArray bytes = canopen::conciseDcf(plan);
    QFile f(pos[1]);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
        return failure(verb, QStringLiteral("%1: %2").arg(pos[1], f.errorString()));
    QTextStream out(stdout);
    if (p.isSet(verbose)) printPlan(out, plan, true);
    out << pos[1] << ": " << plan.writes.size() << " entries, " << bytes.size() << " bytes for node " << *node << " ("
        << plan.skipped.size() << " entries of the DCF left out" << (p.isSet(verbose) ? "" : "; --verbose lists them")
        << ")\n";
    return Ok;
}

}  // namespace

COSCOPE_CLI_VERB({QStringLiteral("dcf concise"), QStringLiteral("Write a DCF as a concise DCF (CiA 302-3, 1F22h)."),
                  runConcise});
COSCOPE_CLI_VERB({QStringLiteral("dcf export"), QStringLiteral("Save a node's actual values as a DCF."), runExport});
COSCOPE_CLI_VERB({QStringLiteral("dcf apply"),
                  QStringLiteral("Write a DCF's values to a node (plan, --dry-run, --yes)."), runApply});

}  // namespace coscope::cli
