// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli ds402 state|enable|disable BUS NODE [--mode M] [--axis N]
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "core/canopen/Ds402Controller.h"
#include "core/canopen/ServiceWait.h"

#include <QTextStream>

namespace coscope::cli {

static int runDs402(const QStringList& args, const QString& action) {
    const QString verb = QStringLiteral("ds402 ") + action;
    QCommandLineParser p;
    if (action == u"state") p.setApplicationDescription(QStringLiteral("Read a CiA 402 drive's state from its statusword 6041h."));
    else if (action == u"enable") p.setApplicationDescription(QStringLiteral("Step a CiA 402 drive to Operation enabled (fault reset, shutdown, switch on, enable operation). "
                                                                           "THIS CAN MOVE A MOTOR: running it is the confirmation. Every controlword sent is printed; "
                                                                           "if a step fails the drive is sent Disable voltage."));
    else p.setApplicationDescription(QStringLiteral("Bring a CiA 402 drive to Switch on disabled (shutdown, disable voltage)."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL"));
    p.addPositionalArgument(QStringLiteral("NODE"), QStringLiteral("Node-ID 1-127"));
    const QCommandLineOption mode(QStringLiteral("mode"), QStringLiteral("Set the mode of operation first (pp, pv, pt, hm, ip, csp, csv, cst) and verify 6061h."), QStringLiteral("M"));
    const QCommandLineOption axis(QStringLiteral("axis"), QStringLiteral("Axis of a multi-axis device, 0-7 (objects at +N*800h; default 0)."), QStringLiteral("N"), QStringLiteral("0"));
    const QCommandLineOption timeout(QStringLiteral("timeout"), QStringLiteral("Time to wait for each state in ms (default 1000)."), QStringLiteral("MS"), QStringLiteral("1000"));
    p.addOptions({mode, axis, timeout});
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2) return usageError(verb, QStringLiteral("expects BUS NODE"));
    const auto node = parseNodeId(pos[1]);
    if (!node) return usageError(verb, QStringLiteral("node-ID '%1' must be 1-127").arg(pos[1]));
    bool ok = false;
    const int ax = p.value(axis).toInt(&ok);
    if (!ok || ax < 0 || ax > 7) return usageError(verb, QStringLiteral("--axis must be 0-7"));
    const int t = p.value(timeout).toInt(&ok);
    if (!ok || t <= 0) return usageError(verb, QStringLiteral("--timeout must be a positive number of ms"));
    std::optional<int8_t> m;
    if (p.isSet(mode)) {
        m = canopen::ds402::modeFromShortName(p.value(mode).toLower());
        if (!m) return usageError(verb, QStringLiteral("unknown mode '%1'; use pp, pv, pt, hm, ip, csp, csv or cst").arg(p.value(mode)));
    }

    BusSession s;
    QString error;
    if (!s.open(pos[0], &error)) return failure(verb, error);
    QTextStream out(stdout);
    canopen::Ds402Controller ctl(s.sdo(), *node, ax);
    ctl.setTimeout(t);
    ctl.setSendObserver([&out](const QString& line) {
        out << "send " << line << "\n";
        out.flush();
    });
    auto wait = [&](const std::function<void(canopen::Ds402Callback)>& start) {
        auto r = canopen::waitForResult<canopen::Ds402Result>(start, 120000);
        if (!r) {
            canopen::Ds402Result none;
            none.error = QStringLiteral("no result");
            return none;
        }
        return *r;
    };
    auto show = [&](const canopen::Ds402Result& r) {
        out << "node " << *node;
        if (ax) out << " axis " << ax;
        out << ": " << canopen::ds402::stateName(r.state) << " (statusword 0x" << QStringLiteral("%1").arg(r.statusword, 4, 16, QChar(u'0')).toUpper() << ": "
            << canopen::ds402::statuswordBits(r.statusword).join(QStringLiteral(", ")) << ")\n";
    };
    if (m) {
        const auto r = wait([&](auto cb) { ctl.setMode(*m, cb); });
        if (!r.ok) return failure(verb, r.error);
        out << "mode of operation: " << canopen::ds402::modeName(r.mode) << "\n";
    }
    canopen::Ds402Result r;
    if (action == u"state") r = wait([&](auto cb) { ctl.readState(cb); });
    else if (action == u"enable") r = wait([&](auto cb) { ctl.enable(cb); });
    else r = wait([&](auto cb) { ctl.disable(cb); });
    if (!r.ok) return failure(verb, r.error);
    show(r);
    return Ok;
}

COSCOPE_CLI_VERB({QStringLiteral("ds402 state"), QStringLiteral("Read a CiA 402 drive's state."), [](const QStringList& a) { return runDs402(a, QStringLiteral("state")); }});
COSCOPE_CLI_VERB({QStringLiteral("ds402 enable"), QStringLiteral("Enable a CiA 402 drive (prints every controlword)."), [](const QStringList& a) { return runDs402(a, QStringLiteral("enable")); }});
COSCOPE_CLI_VERB({QStringLiteral("ds402 disable"), QStringLiteral("Disable a CiA 402 drive."), [](const QStringList& a) { return runDs402(a, QStringLiteral("disable")); }});

}  // namespace coscope::cli
