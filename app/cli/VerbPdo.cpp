// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli pdo show BUS NODE / pdo map BUS NODE tpdo1 6041:00,6064:00 [--type N] ...
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "core/canopen/NmtMaster.h"
#include "core/canopen/PdoConfigurator.h"
#include "core/canopen/ServiceWait.h"
#include "core/od/NumberNotation.h"
#include "eds/StandardDictionary.h"

#include <QTextStream>

namespace coscope::cli {

namespace {

void printPdo(QTextStream& out, const canopen::PdoReadResult& r, const od::ObjectDictionary* dict) {
    const auto& c = r.config;
    out << r.pdo.name() << "  COB-ID 0x" << QString::number(c.cobId & 0x7FFFFFFF, 16).toUpper()
        << (c.valid() ? "" : " (not valid)") << "  type " << od::transmissionTypeText(c.transmissionType);
    if (c.inhibitTime) out << "  inhibit " << *c.inhibitTime << " x100us";
    if (c.eventTimer) out << "  event timer " << *c.eventTimer << " ms";
    out << "  " << c.totalBits() << " bits\n";
    for (const auto& e : c.entries) {
        out << "    " << canopen::objectRef(e.index, e.sub) << "/" << e.bits;
        // Names from the node's dictionary, else the CiA 301/402 standard objects.
        const od::ObjectDictionary* names = nullptr;
        if (const od::SubObject* entry = eds::entryWithStandard(dict, e.index, e.sub, &names))
            out << "  " << names->displayName(e.index, e.sub) << " (" << od::dataTypeName(entry->dataType) << ")";
        out << "\n";
    }
}

int runShow(const QStringList& args) {
    const QString verb = QStringLiteral("pdo show");
    QCommandLineParser p;
    p.setApplicationDescription(
        QStringLiteral("Read a node's TPDO1-4 and RPDO1-4: COB-ID, transmission type, timers and mapping."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL"));
    p.addPositionalArgument(QStringLiteral("NODE"), QStringLiteral("Node-ID 1-127"));
    const QCommandLineOption dictOpt(QStringLiteral("dict"),
                                     QStringLiteral("Dictionary file or name (default: matched by identity)."),
                                     QStringLiteral("FILE|NAME"));
    p.addOption(dictOpt);
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2) return usageError(verb, QStringLiteral("expects BUS NODE"));
    const auto node = parseNodeId(pos[1]);
    if (!node) return usageError(verb, QStringLiteral("node-ID '%1' must be 1-127").arg(pos[1]));
    BusSession s;
    QString error, name;
    if (!s.open(pos[0], &error)) return failure(verb, error);
    auto dict = s.nodeDictionary(*node, p.value(dictOpt), &name, &error);
    if (!dict && p.isSet(dictOpt)) return failure(verb, error);
    canopen::PdoConfigurator pdo(s.sdo());
    std::optional<std::vector<canopen::PdoReadResult>> set;
    pdo.readSet(*node, [&](const auto& r) { set = r; });
    canopen::waitUntil([&] { return set.has_value(); }, 120000);
    if (!set) return failure(verb, QStringLiteral("no answer from node %1").arg(*node));
    QTextStream out(stdout);
    int ok = 0;
    QString firstError;
    for (const auto& r : *set) {
        if (!r.ok) {
            if (firstError.isEmpty()) firstError = r.error;
            continue;
        }
        printPdo(out, r, dict ? &*dict : nullptr);
        ++ok;
    }
    if (!ok) return failure(verb, firstError.isEmpty() ? QStringLiteral("node %1 has no PDOs").arg(*node) : firstError);
    return Ok;
}

int runMap(const QStringList& args) {
    const QString verb = QStringLiteral("pdo map");
    QCommandLineParser p;
    p.setApplicationDescription(
        QStringLiteral("Write a PDO mapping in the CiA 301 order (pre-operational, COB-ID invalid, transmission type, "
                       "inhibit time, event timer, "
                       "sub0 = 0, entries, sub0 = n, COB-ID valid), verify it by reading back, and restore the "
                       "previous mapping if a step fails."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL"));
    p.addPositionalArgument(QStringLiteral("NODE"), QStringLiteral("Node-ID 1-127"));
    p.addPositionalArgument(QStringLiteral("PDO"), QStringLiteral("tpdo1..tpdo512 or rpdo1..rpdo512"));
    p.addPositionalArgument(QStringLiteral("OBJECTS"), QStringLiteral("IIII:SS[/BITS],... e.g. 6041:00,6064:00"));
    const QCommandLineOption type(QStringLiteral("type"), QStringLiteral("Transmission type 0-255 (default: keep)."),
                                  QStringLiteral("N"));
    const QCommandLineOption inhibit(QStringLiteral("inhibit"),
                                     QStringLiteral("Inhibit time in ms (TPDO; written in 100 us units)."),
                                     QStringLiteral("MS"));
    const QCommandLineOption event(QStringLiteral("event-timer"), QStringLiteral("Event timer in ms."),
                                   QStringLiteral("MS"));
    const QCommandLineOption cob(QStringLiteral("cob-id"), QStringLiteral("COB-ID (default: keep)."),
                                 QStringLiteral("ID"));
    const QCommandLineOption dictOpt(QStringLiteral("dict"),
                                     QStringLiteral("Dictionary file or name (default: matched by identity)."),
                                     QStringLiteral("FILE|NAME"));
    p.addOptions({type, inhibit, event, cob, dictOpt});
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 4) return usageError(verb, QStringLiteral("expects BUS NODE PDO OBJECTS"));
    const auto node = parseNodeId(pos[1]);
    if (!node) return usageError(verb, QStringLiteral("node-ID '%1' must be 1-127").arg(pos[1]));
    const auto pdoId = canopen::parsePdoName(pos[2]);
    if (!pdoId) return usageError(verb, QStringLiteral("'%1' is not a PDO name (tpdo1, rpdo2, ...)").arg(pos[2]));
    QString error;
    auto entries = canopen::parsePdoEntries(pos[3], &error);
    if (!entries) return usageError(verb, error);
    canopen::PdoConfig wanted;
    wanted.entries = *entries;
    bool ok = true;
    auto number = [&](const QCommandLineOption& o, uint max) -> std::optional<uint> {
        if (!p.isSet(o)) return std::nullopt;
        bool good = false;
        const uint v = p.value(o).toUInt(&good, 0);
        if (!good || v > max) ok = false;
        return v;
    };
    const auto t = number(type, 255);
    const auto inh = number(inhibit, 6553);
    const auto ev = number(event, 65535);
    const auto c = number(cob, 0x7FF);
    if (!ok)
        return usageError(
            verb, QStringLiteral("--type 0-255, --inhibit 0-6553 ms, --event-timer 0-65535 ms, --cob-id up to 0x7FF"));
    if (inh && !pdoId->transmit) return usageError(verb, QStringLiteral("--inhibit applies to TPDOs only"));
    if (inh) wanted.inhibitTime = static_cast<uint16_t>(*inh * 10);
    if (ev) wanted.eventTimer = static_cast<uint16_t>(*ev);
    if (c) wanted.cobId = *c;

    BusSession s;
    QString name;
    if (!s.open(pos[0], &error)) return failure(verb, error);
    auto dict = s.nodeDictionary(*node, p.value(dictOpt), &name, &error);
    if (!dict && p.isSet(dictOpt)) return failure(verb, error);
    canopen::NmtMaster nmt(s.context());
    canopen::PdoConfigurator pdo(s.sdo(), &nmt);
    if (!t) {
        // Keep the current transmission type.
        std::optional<canopen::PdoReadResult> cur;
        pdo.read(*node, *pdoId, [&](const auto& r) { cur = r; });
        canopen::waitUntil([&] { return cur.has_value(); }, 60000);
        if (!cur || !cur->ok) return failure(verb, cur ? cur->error : QStringLiteral("no answer"));
        wanted.transmissionType = cur->config.transmissionType;
    } else {
        wanted.transmissionType = static_cast<uint8_t>(*t);
    }
    QTextStream out(stdout);
    std::optional<canopen::PdoWriteResult> res;
    pdo.write(*node, *pdoId, wanted, dict ? &*dict : nullptr, [&](const auto& r) { res = r; });
    canopen::waitUntil([&] { return res.has_value(); }, 120000);
    if (!res) return failure(verb, QStringLiteral("no result"));
    if (!res->steps.isEmpty()) out << "node " << *node << " to pre-operational, then:\n";
    for (const QString& step : res->steps) out << "  " << step << "\n";
    out.flush();
    if (!res->ok)
        return failure(verb, res->error.startsWith(QStringLiteral("node "))
                                 ? res->error
                                 : QStringLiteral("node %1 %2: %3").arg(*node).arg(pdoId->name(), res->error));
    out << pdoId->name() << " of node " << *node << " mapped and verified (" << res->written.totalBits()
        << " bits); node left pre-operational\n";
    return Ok;
}

}  // namespace

COSCOPE_CLI_VERB({QStringLiteral("pdo show"), QStringLiteral("Show a node's PDO configuration and mapping."), runShow});
COSCOPE_CLI_VERB({QStringLiteral("pdo map"), QStringLiteral("Write, verify (and on failure roll back) a PDO mapping."),
                  runMap});

}  // namespace coscope::cli
