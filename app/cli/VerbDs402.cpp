// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli ds402 state|enable|disable|quickstop BUS NODE [--mode M] [--axis N]
//             ds402 mode BUS NODE MODE
//             ds402 jog BUS NODE VELOCITY --for MS [--yes] [--watchdog [--heartbeat-node N] [--heartbeat-ms MS]]
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "app/cli/Ds402Cli.h"
#include "app/cli/WatchdogRun.h"
#include "core/canopen/Ds402Controller.h"
#include "core/canopen/ServiceWait.h"

#include <QElapsedTimer>
#include <QTextStream>

namespace coscope::cli {

static int runDs402(const QStringList& args, const QString& action) {
    const QString verb = QStringLiteral("ds402 ") + action;
    QCommandLineParser p;
    if (action == u"state")
        p.setApplicationDescription(QStringLiteral("Read a CiA 402 drive's state from its statusword 6041h."));
    else if (action == u"enable")
        p.setApplicationDescription(QStringLiteral(
            "Step a CiA 402 drive to Operation enabled (fault reset, shutdown, switch on, enable operation). "
            "THIS CAN MOVE A MOTOR: running it is the confirmation. Every controlword sent is printed; "
            "if a step fails the drive is sent Disable voltage."));
    else if (action == u"quickstop")
        p.setApplicationDescription(
            QStringLiteral("Quick stop a CiA 402 drive (6040h = 0002h): it brakes on its quick stop ramp."));
    else
        p.setApplicationDescription(
            QStringLiteral("Bring a CiA 402 drive to Switch on disabled (shutdown, disable voltage)."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL"));
    p.addPositionalArgument(QStringLiteral("NODE"), QStringLiteral("Node-ID 1-127"));
    const QCommandLineOption mode(
        QStringLiteral("mode"),
        QStringLiteral("Set the mode of operation first (pp, pv, pt, hm, ip, csp, csv, cst) and verify 6061h."),
        QStringLiteral("M"));
    const QCommandLineOption axis(QStringLiteral("axis"),
                                  QStringLiteral("Axis of a multi-axis device, 0-7 (objects at +N*800h; default 0)."),
                                  QStringLiteral("N"), QStringLiteral("0"));
    const QCommandLineOption timeout(QStringLiteral("timeout"),
                                     QStringLiteral("Time to wait for each state in ms (default 1000)."),
                                     QStringLiteral("MS"), QStringLiteral("1000"));
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
        if (!m)
            return usageError(
                verb, QStringLiteral("unknown mode '%1'; use pp, pv, pt, hm, ip, csp, csv or cst").arg(p.value(mode)));
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
        out << ": " << canopen::ds402::stateName(r.state) << " (statusword 0x"
            << QStringLiteral("%1").arg(r.statusword, 4, 16, QChar(u'0')).toUpper() << ": "
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
    else if (action == u"quickstop") r = wait([&](auto cb) { ctl.quickStop(cb); });
    else r = wait([&](auto cb) { ctl.disable(cb); });
    if (!r.ok) return failure(verb, r.advice.isEmpty() ? r.error : r.error + QStringLiteral(" — ") + r.advice);
    // Enabled or quick-stopped as asked: left so on purpose, not disabled when the bus closes
    // (BusSession disables what a verb leaves enabled by accident).
    if (action == u"enable" || action == u"quickstop") s.context().enabledDrives().forget(*node, ax);
    show(r);
    return Ok;
}

static int runMode(const QStringList& args) {
    const QString verb = QStringLiteral("ds402 mode");
    QCommandLineParser p;
    p.setApplicationDescription(
        QStringLiteral("Set a CiA 402 drive's mode of operation (6060h) and verify it in 6061h. The mode must be one "
                       "6502h lists as supported."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL"));
    p.addPositionalArgument(QStringLiteral("NODE"), QStringLiteral("Node-ID 1-127"));
    p.addPositionalArgument(QStringLiteral("MODE"), QStringLiteral("pp, pv, pt, hm, ip, csp, csv or cst"));
    const QCommandLineOption axis(QStringLiteral("axis"), QStringLiteral("Axis of a multi-axis device, 0-7."),
                                  QStringLiteral("N"), QStringLiteral("0"));
    p.addOption(axis);
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 3) return usageError(verb, QStringLiteral("expects BUS NODE MODE"));
    const auto node = parseNodeId(pos[1]);
    if (!node) return usageError(verb, QStringLiteral("node-ID '%1' must be 1-127").arg(pos[1]));
    const auto mode = canopen::ds402::modeFromShortName(pos[2]);
    if (!mode)
        return usageError(verb,
                          QStringLiteral("unknown mode '%1'; use pp, pv, pt, hm, ip, csp, csv or cst").arg(pos[2]));
    bool ok = false;
    const int ax = p.value(axis).toInt(&ok);
    if (!ok || ax < 0 || ax > 7) return usageError(verb, QStringLiteral("--axis must be 0-7"));
    BusSession s;
    QString error;
    if (!s.open(pos[0], &error)) return failure(verb, error);
    QTextStream out(stdout);
    canopen::Ds402Controller ctl(s.sdo(), *node, ax);
    printSends(ctl, out);
    // 6502h: supported drive modes (CiA 402-2 §6.4.3); refuse a mode the drive does not list.
    auto sup = canopen::waitForResult<canopen::SdoResult>(
        [&](canopen::SdoCallback cb) { s.sdo().upload(*node, ctl.objectIndex(0x6502), 0, cb); }, 5000);
    if (sup && sup->ok && sup->data.size() >= 4) {
        uint32_t bits = 0;
        for (int i = 0; i < 4; ++i) bits |= uint32_t(uint8_t(sup->data[i])) << (8 * i);
        if (!canopen::ds402::modeSupported(bits, *mode))
            return failure(verb, QStringLiteral("node %1 does not support %2 (supported drive modes 6502h = 0x%3)")
                                     .arg(*node)
                                     .arg(canopen::ds402::modeName(*mode))
                                     .arg(bits, 8, 16, QChar(u'0')));
    }
    const auto r = waitDs402([&](auto cb) { ctl.setMode(*mode, cb); });
    if (!r.ok) return failure(verb, r.error);
    out << "node " << *node << ": mode of operation " << canopen::ds402::modeName(r.mode) << " (6061h = " << r.mode
        << ")\n";
    return Ok;
}

static int runJog(const QStringList& args) {
    const QString verb = QStringLiteral("ds402 jog");
    QCommandLineParser p;
    p.setApplicationDescription(QStringLiteral(
        "Jog a CiA 402 drive in profile velocity mode for a short time: enable, 6060h = 3, 6083h/6084h ramps, "
        "60FFh = VELOCITY, stop (halt, 60FFh = 0), disable. THIS MOVES A MOTOR: asks for confirmation "
        "unless --yes. Always ends stopped and disabled, also when a step fails."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL"));
    p.addPositionalArgument(QStringLiteral("NODE"), QStringLiteral("Node-ID 1-127"));
    p.addPositionalArgument(QStringLiteral("VELOCITY"),
                            QStringLiteral("Target velocity 60FFh in the drive's velocity units (signed, small)"));
    const QCommandLineOption forMs(QStringLiteral("for"), QStringLiteral("How long to run, in ms (1-30000)."),
                                   QStringLiteral("MS"));
    const QCommandLineOption accel(QStringLiteral("accel"),
                                   QStringLiteral("Acceleration and deceleration 6083h/6084h (default 10000)."),
                                   QStringLiteral("A"), QStringLiteral("10000"));
    const QCommandLineOption yes(QStringLiteral("yes"), QStringLiteral("Do not ask for confirmation."));
    const QCommandLineOption axis(QStringLiteral("axis"), QStringLiteral("Axis of a multi-axis device, 0-7."),
                                  QStringLiteral("N"), QStringLiteral("0"));
    p.addOptions({forMs, accel, yes, axis});
    WatchdogOptions watch;
    watch.addTo(p);
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 3) return usageError(verb, QStringLiteral("expects BUS NODE VELOCITY"));
    const auto node = parseNodeId(pos[1]);
    if (!node) return usageError(verb, QStringLiteral("node-ID '%1' must be 1-127").arg(pos[1]));
    bool ok = false;
    canopen::Ds402TestMove move;
    move.kind = canopen::Ds402TestMove::Kind::Jog;
    move.velocity = pos[2].toInt(&ok);
    if (!ok) return usageError(verb, QStringLiteral("VELOCITY '%1' is not a number").arg(pos[2]));
    if (!p.isSet(forMs)) return usageError(verb, QStringLiteral("--for MS is required"));
    const int ms = p.value(forMs).toInt(&ok);
    if (!ok || ms <= 0 || ms > canopen::Ds402TestMove::kMaxDurationMs)
        return usageError(verb, QStringLiteral("--for must be 1-%1 ms").arg(canopen::Ds402TestMove::kMaxDurationMs));
    const uint a = p.value(accel).toUInt(&ok);
    if (!ok || a == 0) return usageError(verb, QStringLiteral("--accel must be a positive number"));
    move.acceleration = move.deceleration = a;
    move.maxDurationMs = std::min(ms + 500, canopen::Ds402TestMove::kMaxDurationMs);
    const int ax = p.value(axis).toInt(&ok);
    if (!ok || ax < 0 || ax > 7) return usageError(verb, QStringLiteral("--axis must be 0-7"));
    const QString bad = move.check();
    if (!bad.isEmpty()) return usageError(verb, bad);
    if (QString why; !watch.read(p, *node, &why)) return usageError(verb, why);

    QTextStream out(stdout);
    QString why;
    if (!confirmMotion(p.isSet(yes),
                       QStringLiteral("This enables node %1 and turns its motor at %2 units/s for %3 ms.")
                           .arg(*node)
                           .arg(move.velocity)
                           .arg(ms),
                       &why))
        return failure(verb, why);
    BusSession s;
    QString error;
    if (!s.open(pos[0], &error)) return failure(verb, error);
    // --watchdog: armed before enabling; put back after the drive was disabled, on every return.
    WatchdogRun watchdog(s, *node, ax, out);
    if (watch.enabled && !watchdog.start(watch, &error)) return failure(verb, QStringLiteral("--watchdog: ") + error);
    canopen::Ds402Controller ctl(s.sdo(), *node, ax);
    printSends(ctl, out);
    // Whatever happens below, the drive ends disabled: also on Ctrl+C or SIGTERM, which stop the
    // move (halt, then disable) instead of ending the process with the motor turning.
    installInterruptHandler();
    auto disableAtEnd = [&](const QString& failed) { return endDisabled(ctl, verb, *node, failed, out); };
    const auto en = waitDs402([&](auto cb) { ctl.enable(cb); });
    if (!en.ok) return disableAtEnd(en.advice.isEmpty() ? en.error : en.error + QStringLiteral(" — ") + en.advice);
    out << "node " << *node << ": operation enabled\n";
    if (interrupted()) return disableAtEnd(QStringLiteral("interrupted before the move"));
    bool finished = false;
    canopen::Ds402Result moved;
    int32_t lastPos = 0, firstPos = 0;
    bool havePos = false;
    if (!ctl.startTestMove(
            move,
            [&](const canopen::Ds402MotionSample& smp) {
                if (!havePos) firstPos = smp.position, havePos = true;
                lastPos = smp.position;
            },
            [&](const canopen::Ds402Result& r) { moved = r, finished = true; }, &error))
        return disableAtEnd(error);
    QElapsedTimer t;
    t.start();
    // The CLI holds the "button" for --for ms, feeding the controller's watchdog.
    canopen::waitUntil(
        [&] {
            if (finished) return true;
            if (interrupted()) ctl.stopTestMove(QStringLiteral("interrupted"));
            else if (t.elapsed() < ms) ctl.feedWatchdog();
            else ctl.stopTestMove(QStringLiteral("--for %1 ms elapsed").arg(ms));
            return false;
        },
        ms + 10000);
    if (!finished) {
        ctl.stopTestMove(QStringLiteral("timeout"));
        return disableAtEnd(QStringLiteral("the test move did not finish"));
    }
    if (!moved.ok) return disableAtEnd(moved.error);
    if (interrupted())
        return disableAtEnd(QStringLiteral("interrupted after moving from %1 to %2 (position actual 6064h)")
                                .arg(firstPos)
                                .arg(lastPos));
    out << "node " << *node << ": moved from " << firstPos << " to " << lastPos
        << " (position actual 6064h), stopped: " << moved.stopReason << "\n";
    return disableAtEnd({});
}

COSCOPE_CLI_VERB({QStringLiteral("ds402 state"), QStringLiteral("Read a CiA 402 drive's state."),
                  [](const QStringList& a) { return runDs402(a, QStringLiteral("state")); }});
COSCOPE_CLI_VERB({QStringLiteral("ds402 enable"), QStringLiteral("Enable a CiA 402 drive (prints every controlword)."),
                  [](const QStringList& a) { return runDs402(a, QStringLiteral("enable")); }});
COSCOPE_CLI_VERB({QStringLiteral("ds402 disable"), QStringLiteral("Disable a CiA 402 drive."),
                  [](const QStringList& a) { return runDs402(a, QStringLiteral("disable")); }});
COSCOPE_CLI_VERB({QStringLiteral("ds402 quickstop"), QStringLiteral("Quick stop a CiA 402 drive."),
                  [](const QStringList& a) { return runDs402(a, QStringLiteral("quickstop")); }});
COSCOPE_CLI_VERB({QStringLiteral("ds402 mode"), QStringLiteral("Set and verify a CiA 402 drive's mode of operation."),
                  runMode});
COSCOPE_CLI_VERB({QStringLiteral("ds402 jog"),
                  QStringLiteral("Jog a CiA 402 drive briefly (asks first; ends disabled)."), runJog});

}  // namespace coscope::cli
