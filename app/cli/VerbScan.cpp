// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli scan BUS: nodes 1-127 by 1000h and 1018h, with the matched dictionary.
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "core/canopen/NetworkScan.h"
#include "core/canopen/ServiceWait.h"
#include "eds/ScanMatcher.h"

#include <QTextStream>

namespace coscope::cli {

static QString hex32(std::optional<uint32_t> v) {
    return v ? QStringLiteral("0x%1").arg(*v, 8, 16, QChar(u'0')) : QStringLiteral("-");
}

static int runScan(const QStringList& args) {
    const QString verb = QStringLiteral("scan");
    QCommandLineParser p;
    p.setApplicationDescription(
        QStringLiteral("Find the nodes on a bus: reads 1000h and 1018h of nodes 1-127 over SDO (rate-limited) and "
                       "matches each to a dictionary."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL"));
    const QCommandLineOption timeout(QStringLiteral("timeout"),
                                     QStringLiteral("Per-node SDO timeout in ms (default 200)."), QStringLiteral("MS"),
                                     QStringLiteral("200"));
    const QCommandLineOption parallel(QStringLiteral("parallel"),
                                      QStringLiteral("Requests in flight at most (default 8)."), QStringLiteral("N"),
                                      QStringLiteral("8"));
    const QCommandLineOption range(QStringLiteral("nodes"), QStringLiteral("Node range FIRST-LAST (default 1-127)."),
                                   QStringLiteral("RANGE"), QStringLiteral("1-127"));
    p.addOptions({timeout, parallel, range});
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 1) return usageError(verb, QStringLiteral("expects BUS"));
    bool ok1 = false, ok2 = false;
    const int t = p.value(timeout).toInt(&ok1);
    const int par = p.value(parallel).toInt(&ok2);
    if (!ok1 || t <= 0 || !ok2 || par <= 0)
        return usageError(verb, QStringLiteral("--timeout and --parallel must be positive numbers"));
    const QStringList r = p.value(range).split(u'-');
    const auto first = parseNodeId(r.value(0));
    const auto last = parseNodeId(r.value(r.size() - 1));
    if (!first || !last || *first > *last)
        return usageError(verb, QStringLiteral("--nodes must be FIRST-LAST within 1-127"));

    BusSession s;
    QString error;
    if (!s.open(pos[0], &error)) return failure(verb, error);
    if (s.bus()->isListenOnly())
        return failure(verb, QStringLiteral("cannot scan on a listen-only bus: the scan sends SDO requests"));
    canopen::NetworkScan scan(s.sdo());
    scan.setTimeout(t);
    scan.setMaxOutstanding(par);
    scan.setRange(*first, *last);
    scan.setMatcher(eds::scanMatcher());
    std::optional<std::vector<canopen::ScannedNode>> found;
    scan.start([&](const std::vector<canopen::ScannedNode>& f) { found = f; });
    canopen::waitUntil([&] { return found.has_value(); }, 600000);
    if (!found) return failure(verb, QStringLiteral("scan did not finish"));
    QTextStream out(stdout);
    out << "node  device type  vendor-ID   product     revision    serial      dictionary\n";
    for (const auto& n : *found) {
        out << QString::number(n.node).rightJustified(4) << "  " << hex32(n.deviceType) << "   " << hex32(n.vendorId)
            << "  " << hex32(n.productCode) << "  " << hex32(n.revision) << "  " << hex32(n.serial) << "  "
            << (n.dictionary.isEmpty() ? QStringLiteral("(no match)") : n.dictionary);
        if (!n.error.isEmpty()) out << "  [" << n.error << "]";
        out << "\n";
        // Optional objects (CiA 301 §7.5.2.9-11): a node without them is normal.
        const auto text = [](const std::optional<QString>& v) {
            return v ? QStringLiteral("\"%1\"").arg(*v) : QStringLiteral("not present");
        };
        out << "      device name " << text(n.deviceName) << ", hardware version " << text(n.hardwareVersion)
            << ", software version " << text(n.softwareVersion) << "\n";
    }
    out << found->size() << " node(s) found\n";
    return Ok;
}

COSCOPE_CLI_VERB({QStringLiteral("scan"), QStringLiteral("Find nodes (1000h, 1018h) and match their dictionaries."),
                  runScan});

}  // namespace coscope::cli
