// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli node-id BUS NODE NEW_ID [--via lss|vendor]
// coscope-cli bitrate BUS NODE NEW_RATE [--via lss|vendor]
// Changes a device's node-ID or CAN bit rate through canopen::NodeSettingsChanger (the service
// the GUI's "Baud rate and node-ID" wizard uses) and checks that the node comes back.
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "core/canopen/NodeSettingsChanger.h"
#include "core/canopen/ServiceWait.h"
#include "core/sim/BusAtBitRate.h"

#include <QTextStream>

namespace coscope::cli {

namespace {

int runNodeSettings(const QStringList& args, bool bitRate) {
    const QString verb = bitRate ? QStringLiteral("bitrate") : QStringLiteral("node-id");
    QCommandLineParser p;
    p.setApplicationDescription(
        bitRate ? QStringLiteral(
                      "Change the CAN bit rate of one device, reconnect at the new rate and wait for the node.\n"
                      "LSS (CiA 305): switch selective, configure bit timing, store, activate bit timing.\n"
                      "vendor: the device's own parameter over SDO (Delta P3-01 digit Z), then NMT reset node.\n"
                      "Every other node on the bus stays at the old rate: change them all, or the bus will not work.")
                : QStringLiteral("Change the node-ID of one device and wait until it reports at the new node-ID.\n"
                                 "LSS (CiA 305): switch selective, configure node-ID, store, NMT reset communication.\n"
                                 "vendor: the device's own parameter over SDO (Delta P3-00, AIMOTOR H0C-00, DEXMART "
                                 "09-19), then NMT reset node.\n"
                                 "NODE 255 = an LSS-unconfigured device, found with LSS Fastscan first."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL"));
    p.addPositionalArgument(QStringLiteral("NODE"), QStringLiteral("Current node-ID"));
    p.addPositionalArgument(bitRate ? QStringLiteral("RATE") : QStringLiteral("NEW_ID"),
                            bitRate ? QStringLiteral("New bit rate in bit/s") : QStringLiteral("New node-ID"));
    const QCommandLineOption via(QStringLiteral("via"), QStringLiteral("lss (default) or vendor."),
                                 QStringLiteral("METHOD"), QStringLiteral("lss"));
    const QCommandLineOption dict(
        QStringLiteral("dict"),
        QStringLiteral("The device's dictionary (name or file) for the vendor method; default: matched by identity."),
        QStringLiteral("NAME"));
    const QCommandLineOption dryRun(QStringLiteral("dry-run"),
                                    QStringLiteral("Print the sequence; send nothing but the reads it needs."));
    const QCommandLineOption save(QStringLiteral("save"),
                                  QStringLiteral("Also write the sequence as a script for `coscope-cli script run`."),
                                  QStringLiteral("FILE"));
    const QCommandLineOption wait(QStringLiteral("wait"),
                                  QStringLiteral("How long to wait for the node afterwards, ms (default 5000)."),
                                  QStringLiteral("MS"), QStringLiteral("5000"));
    p.addOptions({via, dict, dryRun, save, wait});
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 3)
        return usageError(
            verb, bitRate ? QStringLiteral("expects BUS NODE RATE") : QStringLiteral("expects BUS NODE NEW_ID"));
    canopen::NodeSettingsRequest req;
    req.change = bitRate ? canopen::NodeSettingsRequest::Change::BitRate : canopen::NodeSettingsRequest::Change::NodeId;
    const QString method = p.value(via).toLower();
    if (method != u"lss" && method != u"vendor")
        return usageError(verb, QStringLiteral("--via must be lss or vendor, not '%1'").arg(p.value(via)));
    req.method =
        method == u"lss" ? canopen::NodeSettingsRequest::Method::Lss : canopen::NodeSettingsRequest::Method::Vendor;
    bool ok = false;
    const uint node = pos[1].toUInt(&ok, 0);
    if (!ok || !((node >= 1 && node <= 127) || (node == 255 && !bitRate)))
        return usageError(verb, QStringLiteral("NODE must be 1-127%1, not '%2'")
                                    .arg(bitRate ? QString() : QStringLiteral(" or 255"), pos[1]));
    req.node = static_cast<uint8_t>(node);
    const uint value = pos[2].toUInt(&ok, 0);
    if (!ok) return usageError(verb, QStringLiteral("'%1' is not a number").arg(pos[2]));
    if (bitRate) req.newBitRate = static_cast<int>(value);
    else if (value < 1 || value > 127) return usageError(verb, QStringLiteral("NEW_ID must be 1-127"));
    else req.newNodeId = static_cast<uint8_t>(value);
    req.waitMs = static_cast<uint32_t>(std::max(100, p.value(wait).toInt()));

    auto session = std::make_unique<BusSession>();
    QString error;
    if (!session->open(pos[0], &error)) return failure(verb, error);
    req.bitRate = session->bus()->url().bitrate() > 0 ? session->bus()->url().bitrate() : 500000;
    if (req.method == canopen::NodeSettingsRequest::Method::Vendor) {
        QString name, why;
        if (!session->nodeDictionary(req.node, p.value(dict), &name, &why)) return failure(verb, why);
        req.dictionary = name;
    }
    if (req.node == 0xFF) {
        // Fastscan leaves the one unconfigured device in LSS configuration state (CiA 305 §6.7).
        canopen::LssMaster lss(session->context());
        auto r = canopen::waitForResult<canopen::LssResult>([&](auto cb) { lss.fastscan(cb); }, 120000);
        if (!r || !r->ok) return failure(verb, r ? r->error : QStringLiteral("LSS Fastscan gave no result"));
        if (r->noSlave) return failure(verb, QStringLiteral("no LSS-unconfigured device answered Fastscan"));
    }
    QTextStream out(stdout);
    auto changer = std::make_unique<canopen::NodeSettingsChanger>(session->context(), session->sdo());
    using PlanResult = std::pair<std::optional<canopen::NodeSettingsPlan>, QString>;
    auto prepared = canopen::waitForResult<PlanResult>(
        [&](auto cb) { changer->prepare(req, [cb](auto plan, QString e) {
                           cb(PlanResult{plan, e});
                       }); }, 30000);
    if (!prepared || !prepared->first)
        return failure(verb, prepared ? prepared->second : QStringLiteral("no answer while preparing"));
    const canopen::NodeSettingsPlan plan = *prepared->first;
    if (p.isSet(save) && !plan.whole().save(p.value(save), &error)) return failure(verb, error);
    if (p.isSet(dryRun)) {
        out << plan.whole().toText();
        out << "# takes effect: " << plan.takesEffect << "\n";
        return Ok;
    }
    auto runPart = [&](int part) -> bool {
        auto outcome = canopen::waitForResult<canopen::NodeSettingsOutcome>(
            [&](auto cb) {
                changer->run(
                    plan, part, {},
                    [&](int step, bool stepOk, const QString& detail) {
                        const auto& steps = (part == 0 ? plan.beforeReconnect : plan.afterReconnect).steps;
                        out << (stepOk ? "ok    " : "FAIL  ") << steps[size_t(step)].describe()
                            << (detail.isEmpty() ? QString() : QStringLiteral(" — ") + detail) << "\n";
                        out.flush();
                    },
                    cb);
            },
            int(req.waitMs) + 60000);
        if (!outcome) {
            error = QStringLiteral("no result");
            return false;
        }
        if (outcome->ok) return true;
        error = QStringLiteral("%1 failed: %2. %3%4")
                    .arg(outcome->step, outcome->answer, outcome->advice,
                         outcome->restored.isEmpty() ? QString() : QStringLiteral(" ") + outcome->restored);
        return false;
    };
    if (!runPart(0)) return failure(verb, error);
    if (plan.reconnect) {
        std::shared_ptr<sim::SimNetwork> keep;
        const QString url = sim::urlAtBitRate(*session->bus(), plan.reconnectBitRate, &keep);
        out << "reconnecting at " << canopen::bitRateText(plan.reconnectBitRate) << ": " << url << "\n";
        changer.reset();
        session.reset();
        session = std::make_unique<BusSession>();
        if (!session->open(url, &error)) return failure(verb, error);
        changer = std::make_unique<canopen::NodeSettingsChanger>(session->context(), session->sdo());
        if (!runPart(1)) return failure(verb, error);
    }
    out << (bitRate ? QStringLiteral("node %1 runs at %2\n").arg(req.node).arg(canopen::bitRateText(req.newBitRate))
                    : QStringLiteral("node %1 is now node %2\n")
                          .arg(req.node == 0xFF ? QStringLiteral("(unconfigured)") : QString::number(req.node))
                          .arg(req.newNodeId));
    return Ok;
}

}  // namespace

COSCOPE_CLI_VERB({QStringLiteral("node-id"),
                  QStringLiteral("Change a device's node-ID by LSS or its vendor parameter and wait for it."),
                  [](const QStringList& a) { return runNodeSettings(a, false); }});
COSCOPE_CLI_VERB(
    {QStringLiteral("bitrate"),
     QStringLiteral("Change a device's CAN bit rate by LSS or its vendor parameter, reconnect and find it."),
     [](const QStringList& a) { return runNodeSettings(a, true); }});

}  // namespace coscope::cli
