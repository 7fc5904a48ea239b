// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli ds402 home BUS NODE [--method N] [--fast V] [--slow V] [--acceleration A] [--offset O] [--yes]
//             ds402 move BUS NODE TARGET [--relative] [--velocity V] [--acceleration A] [--deceleration D] [--yes]
// Both can move a motor: they ask unless --yes (and refuse without a terminal), print every
// object and controlword sent and the progress, and always end with the drive disabled
// (success, failure, timeout, Ctrl+C).
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "app/cli/Ds402Cli.h"
#include "core/canopen/Ds402Controller.h"
#include "core/canopen/HomingMethods.h"
#include "core/canopen/ServiceWait.h"

#include <QElapsedTimer>
#include <QRegularExpression>
#include <QTextStream>

#include <optional>

namespace coscope::cli {

namespace {

using SampleFn = std::function<void(const canopen::Ds402MotionSample&)>;

// Options both verbs have.
struct MotionOptions {
    QCommandLineOption axis{QStringLiteral("axis"),
                            QStringLiteral("Axis of a multi-axis device, 0-7 (objects at +N*800h; default 0)."),
                            QStringLiteral("N"), QStringLiteral("0")};
    QCommandLineOption timeout{QStringLiteral("timeout"),
                               QStringLiteral("Time allowed for the whole motion in ms (default 60000)."),
                               QStringLiteral("MS"), QStringLiteral("60000")};
    QCommandLineOption yes{QStringLiteral("yes"),
                           QStringLiteral("Do not ask for confirmation (needed without a terminal)."), QString()};
    void addTo(QCommandLineParser& p) const { p.addOptions({axis, timeout, yes}); }
};

std::optional<uint32_t> unsignedOption(const QCommandLineParser& p, const QCommandLineOption& o, bool* bad) {
    if (!p.isSet(o)) return std::nullopt;
    bool ok = false;
    const uint v = p.value(o).toUInt(&ok, 0);
    if (!ok) *bad = true;
    return v;
}

// Runs one motion on `ctl` and ends with the drive disabled. `start` begins it with the
// progress and result callbacks; `mode` names the statusword bits in the progress lines.
int runMotion(const QString& verb, canopen::SdoClient& sdo, canopen::Ds402Controller& ctl, uint8_t node, int8_t mode,
              int timeoutMs, const std::function<void(SampleFn, canopen::Ds402Callback)>& start,
              const QString& doneText, QTextStream& out) {
    installInterruptHandler();
    bool finished = false, stopAsked = false;
    canopen::Ds402Result result;
    canopen::Ds402MotionSample last;
    uint16_t shownStatus = 0xFFFF;
    QElapsedTimer shown;
    shown.start();
    start(
        [&](const canopen::Ds402MotionSample& s) {
            last = s;
            // A line when the statusword changes, else every half second.
            if (s.statusword == shownStatus && shown.elapsed() < 500) return;
            shownStatus = s.statusword;
            shown.restart();
            out << QStringLiteral("%1 ms: statusword 0x%2 (%3), position %4, velocity %5\n")
                       .arg(s.ms, 6)
                       .arg(s.statusword, 4, 16, QChar(u'0'))
                       .arg(canopen::ds402::statuswordBits(s.statusword, mode).join(QStringLiteral(", ")))
                       .arg(s.position)
                       .arg(s.velocity);
            out.flush();
        },
        [&](const canopen::Ds402Result& r) {
            result = r;
            finished = true;
        });
    canopen::waitUntil(
        [&] {
            if (!finished && !stopAsked && interrupted()) {
                stopAsked = true;
                out << "interrupted: stopping node " << node << "\n";
                out.flush();
                ctl.stopMotion(false, QStringLiteral("interrupted (Ctrl+C)"));
            }
            return finished;
        },
        timeoutMs + 20000);
    if (!finished) {
        ctl.stopMotion(true, QStringLiteral("no result in time"));
        return endDisabled(ctl, verb, node, QStringLiteral("node %1 gave no result in time").arg(node), out);
    }
    if (!result.ok) return endDisabled(ctl, verb, node, result.error, out);
    // The last position, read after the end.
    auto pos = canopen::waitForResult<canopen::SdoResult>(
        [&](canopen::SdoCallback cb) { sdo.upload(node, ctl.objectIndex(0x6064), 0, cb); }, 5000);
    if (pos && pos->ok && pos->data.size() >= 4)
        last.position = int32_t(uint32_t(uint8_t(pos->data[0])) | uint32_t(uint8_t(pos->data[1])) << 8 |
                                uint32_t(uint8_t(pos->data[2])) << 16 | uint32_t(uint8_t(pos->data[3])) << 24);
    out << QStringLiteral("node %1: %2, position actual 6064h = %3 (statusword 0x%4: %5)\n")
               .arg(node)
               .arg(doneText)
               .arg(last.position)
               .arg(result.statusword, 4, 16, QChar(u'0'))
               .arg(canopen::ds402::statuswordBits(result.statusword, mode).join(QStringLiteral(", ")));
    return endDisabled(ctl, verb, node, {}, out);
}

int runHome(const QStringList& args) {
    const QString verb = QStringLiteral("ds402 home");
    QCommandLineParser p;
    p.setApplicationDescription(
        QStringLiteral("Home a CiA 402 drive (homing mode 6060h = 6): writes 607Ch, 6098h, 6099h:01/02 and 609Ah, "
                       "enables the drive, starts homing "
                       "(6040h 0Fh -> 1Fh) and waits for homing attained (statusword bit 12) or homing error (bit 13). "
                       "THIS CAN MOVE A MOTOR: asks "
                       "for confirmation unless --yes (without a terminal it refuses). Prints every object and "
                       "controlword sent and the progress; "
                       "always ends with the drive disabled, also on failure, timeout or Ctrl+C. Values are in the "
                       "drive's units (Delta: speeds in "
                       "0.1 rpm, acceleration in ms from 0 to 3000 rpm; AIMOTOR: pulse/s and pulse/s^2). --methods "
                       "lists the drive's methods."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL"));
    p.addPositionalArgument(QStringLiteral("NODE"), QStringLiteral("Node-ID 1-127"));
    const QCommandLineOption method(
        QStringLiteral("method"),
        QStringLiteral("Homing method 6098h (default 35: the current position is home, no movement)."),
        QStringLiteral("N"), QStringLiteral("35"));
    const QCommandLineOption fast(QStringLiteral("fast"), QStringLiteral("Speed during search for switch 6099h:01."),
                                  QStringLiteral("V"));
    const QCommandLineOption slow(QStringLiteral("slow"), QStringLiteral("Speed during search for zero 6099h:02."),
                                  QStringLiteral("V"));
    const QCommandLineOption accel(QStringLiteral("acceleration"), QStringLiteral("Homing acceleration 609Ah."),
                                   QStringLiteral("A"));
    const QCommandLineOption offset(QStringLiteral("offset"),
                                    QStringLiteral("Home offset 607Ch (signed): the position the drive shows at home."),
                                    QStringLiteral("O"));
    const QCommandLineOption methods(QStringLiteral("methods"),
                                     QStringLiteral("List the drive's homing methods and exit (nothing moves)."));
    const QCommandLineOption dict(
        QStringLiteral("dict"),
        QStringLiteral(
            "The drive's dictionary (name or file) for its list of methods; default: matched by its identity 1018h."),
        QStringLiteral("NAME"));
    MotionOptions common;
    p.addOptions({method, fast, slow, accel, offset, methods, dict});
    common.addTo(p);
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2) return usageError(verb, QStringLiteral("expects BUS NODE"));
    const auto node = parseNodeId(pos[1]);
    if (!node) return usageError(verb, QStringLiteral("node-ID '%1' must be 1-127").arg(pos[1]));
    bool ok = false, bad = false;
    canopen::Ds402HomingRequest req;
    const int m = p.value(method).toInt(&ok, 0);
    if (!ok || m < -128 || m > 127) return usageError(verb, QStringLiteral("--method must be -128..127"));
    req.method = static_cast<int8_t>(m);
    req.fastSpeed = unsignedOption(p, fast, &bad);
    req.slowSpeed = unsignedOption(p, slow, &bad);
    req.acceleration = unsignedOption(p, accel, &bad);
    if (bad) return usageError(verb, QStringLiteral("--fast, --slow and --acceleration must be unsigned numbers"));
    if (p.isSet(offset)) {
        const int o = p.value(offset).toInt(&ok, 0);
        if (!ok) return usageError(verb, QStringLiteral("--offset must be a signed 32-bit number"));
        req.offset = o;
    }
    const int ax = p.value(common.axis).toInt(&ok);
    if (!ok || ax < 0 || ax > 7) return usageError(verb, QStringLiteral("--axis must be 0-7"));
    req.timeoutMs = p.value(common.timeout).toInt(&ok);
    if (!ok || req.timeoutMs <= 0) return usageError(verb, QStringLiteral("--timeout must be a positive number of ms"));
    QString why;
    if (!p.isSet(methods) && !mayConfirmMotion(p.isSet(common.yes), &why)) return failure(verb, why);

    BusSession s;
    QString error;
    if (!s.open(pos[0], &error)) return failure(verb, error);
    QTextStream out(stdout);
    // The drive's own methods (canopen::homing), by its dictionary.
    QString dictName;
    s.nodeDictionary(*node, p.value(dict), &dictName, &why);
    const auto& table = canopen::homing::drive(dictName);
    const bool known = table.dictionary == dictName;
    if (p.isSet(methods)) {
        out << "node " << *node << " ("
            << (known ? table.title : QStringLiteral("dictionary not known: CiA 402-2 methods"))
            << "), homing methods 6098h, " << table.source << ":\n";
        for (const auto& hm : table.methods) out << QStringLiteral("%1  %2\n").arg(hm.number, 3).arg(hm.description);
        return Ok;
    }
    if (known && !table.supports(req.method))
        return failure(verb,
                       QStringLiteral("node %1 (%2) has no homing method %3; its methods are %4 (%5); nothing was sent")
                           .arg(*node)
                           .arg(table.title)
                           .arg(req.method)
                           .arg(table.numbers(), table.source));
    req.methodOnlyWhileDisabled = known && table.changeOnlyWhileDisabled;
    if (!confirmMotion(
            p.isSet(common.yes),
            QStringLiteral("This enables node %1 and homes it with %2.").arg(*node).arg(table.describe(req.method)),
            &why))
        return failure(verb, why);
    out << "node " << *node << ": homing with " << table.describe(req.method) << "\n";
    canopen::Ds402Controller ctl(s.sdo(), *node, ax);
    printSends(ctl, out);
    return runMotion(
        verb, s.sdo(), ctl, *node, 6, req.timeoutMs,
        [&](SampleFn progress, canopen::Ds402Callback done) { ctl.home(req, progress, done); },
        QStringLiteral("homing attained"), out);
}

int runMove(const QStringList& args) {
    const QString verb = QStringLiteral("ds402 move");
    QCommandLineParser p;
    p.setApplicationDescription(QStringLiteral(
        "Move a CiA 402 drive to a position in profile position mode (6060h = 1): writes 6081h/6083h/6084h and 607Ah, "
        "enables the "
        "drive, gives the set-point (6040h bit 4 rising, bit 6 relative, bit 5 change set immediately), waits for "
        "set-point "
        "acknowledge (statusword bit 12), clears bit 4 and waits for target reached (bit 10). THIS MOVES A MOTOR: asks "
        "for "
        "confirmation unless --yes (without a terminal it refuses). Prints every object and controlword sent and the "
        "progress; "
        "always ends with the drive disabled, also on failure, timeout or Ctrl+C. Values are in the drive's units."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL"));
    p.addPositionalArgument(QStringLiteral("NODE"), QStringLiteral("Node-ID 1-127"));
    p.addPositionalArgument(QStringLiteral("TARGET"), QStringLiteral("Target position 607Ah (signed, position units)"));
    const QCommandLineOption relative(QStringLiteral("relative"),
                                      QStringLiteral("TARGET is relative to the last target (controlword bit 6)."));
    const QCommandLineOption immediate(QStringLiteral("immediate"),
                                       QStringLiteral("Change set immediately (controlword bit 5)."));
    const QCommandLineOption velocity(QStringLiteral("velocity"), QStringLiteral("Profile velocity 6081h."),
                                      QStringLiteral("V"));
    const QCommandLineOption accel(QStringLiteral("acceleration"), QStringLiteral("Profile acceleration 6083h."),
                                   QStringLiteral("A"));
    const QCommandLineOption decel(QStringLiteral("deceleration"), QStringLiteral("Profile deceleration 6084h."),
                                   QStringLiteral("D"));
    MotionOptions common;
    p.addOptions({relative, immediate, velocity, accel, decel});
    common.addTo(p);
    // A negative TARGET is not an option: it goes after "--".
    QStringList argv = args;
    static const QRegularExpression negative(QStringLiteral("^-(0x[0-9a-fA-F]+|[0-9]+)$"));
    for (qsizetype i = 1; i < argv.size() && !args.contains(QStringLiteral("--")); ++i)
        if (negative.match(argv[i]).hasMatch()) {
            argv << QStringLiteral("--") << argv.takeAt(i);
            break;
        }
    int code = 0;
    if (!parseArgs(p, verb, argv, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 3) return usageError(verb, QStringLiteral("expects BUS NODE TARGET"));
    const auto node = parseNodeId(pos[1]);
    if (!node) return usageError(verb, QStringLiteral("node-ID '%1' must be 1-127").arg(pos[1]));
    bool ok = false, bad = false;
    canopen::Ds402PositionMove move;
    move.target = pos[2].toInt(&ok, 0);
    if (!ok) return usageError(verb, QStringLiteral("TARGET '%1' is not a signed 32-bit number").arg(pos[2]));
    move.relative = p.isSet(relative);
    move.immediate = p.isSet(immediate);
    move.velocity = unsignedOption(p, velocity, &bad);
    move.acceleration = unsignedOption(p, accel, &bad);
    move.deceleration = unsignedOption(p, decel, &bad);
    if (bad)
        return usageError(verb,
                          QStringLiteral("--velocity, --acceleration and --deceleration must be unsigned numbers"));
    const int ax = p.value(common.axis).toInt(&ok);
    if (!ok || ax < 0 || ax > 7) return usageError(verb, QStringLiteral("--axis must be 0-7"));
    move.timeoutMs = p.value(common.timeout).toInt(&ok);
    if (!ok || move.timeoutMs <= 0)
        return usageError(verb, QStringLiteral("--timeout must be a positive number of ms"));
    QString why;
    if (!mayConfirmMotion(p.isSet(common.yes), &why)) return failure(verb, why);
    const QString what = move.relative ? QStringLiteral("by %1 (relative)").arg(move.target)
                                       : QStringLiteral("to position %1").arg(move.target);
    if (!confirmMotion(p.isSet(common.yes),
                       QStringLiteral("This enables node %1 and moves it %2.").arg(*node).arg(what), &why))
        return failure(verb, why);

    BusSession s;
    QString error;
    if (!s.open(pos[0], &error)) return failure(verb, error);
    QTextStream out(stdout);
    out << "node " << *node << ": moving " << what << "\n";
    canopen::Ds402Controller ctl(s.sdo(), *node, ax);
    printSends(ctl, out);
    return runMotion(
        verb, s.sdo(), ctl, *node, 1, move.timeoutMs,
        [&](SampleFn progress, canopen::Ds402Callback done) { ctl.moveTo(move, progress, done); },
        QStringLiteral("target reached"), out);
}

}  // namespace

COSCOPE_CLI_VERB({QStringLiteral("ds402 home"), QStringLiteral("Home a CiA 402 drive (asks first; ends disabled)."),
                  runHome});
COSCOPE_CLI_VERB({QStringLiteral("ds402 move"),
                  QStringLiteral("Profile position move of a CiA 402 drive (asks first; ends disabled)."), runMove});

}  // namespace coscope::cli
