// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli script run BUS FILE [--dry-run] / script check FILE: replay a command script saved
// by a wizard ("Save as script…") or written by hand (grammar in core/canopen/CommandScript.h).
#include "app/cli/BusSession.h"
#include "app/cli/CliVerb.h"
#include "core/can/BusUrl.h"
#include "core/canopen/CommandScript.h"
#include "core/canopen/ScriptRunner.h"
#include "core/canopen/ServiceWait.h"
#include "core/sim/BusAtBitRate.h"

#include <QTextStream>

namespace coscope::cli {

namespace {

void printPlan(QTextStream& out, const canopen::CommandScript& script) {
    if (!script.title.isEmpty()) out << script.title << "\n";
    const int n = static_cast<int>(script.steps.size());
    for (int i = 0; i < n; ++i) {
        const auto& s = script.steps[static_cast<size_t>(i)];
        out << QStringLiteral("%1/%2  %3").arg(i + 1).arg(n).arg(s.toLine()) << "\n";
        out << "      " << s.describe() << "\n";
        if (!s.why.isEmpty())
            out << "      why: " << QString(s.why).replace(u'\n', QStringLiteral("\n           ")) << "\n";
    }
}

int runCheck(const QStringList& args) {
    const QString verb = QStringLiteral("script check");
    QCommandLineParser p;
    p.setApplicationDescription(QStringLiteral(
        "Check a command script (parse only, nothing is sent); prints FILE:LINE: error for each bad line."));
    p.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("Command script"));
    QCommandLineOption list(QStringLiteral("list"), QStringLiteral("Also print the steps with their reasons."));
    p.addOption(list);
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 1) return usageError(verb, QStringLiteral("expects FILE"));
    QString error;
    const auto script = canopen::CommandScript::load(pos[0], &error);
    if (!script) {
        // One line per bad line, compiler style; the exit code says it failed.
        QTextStream err(stderr);
        for (const QString& line : error.split(u'\n')) err << line << "\n";
        return Failure;
    }
    QTextStream out(stdout);
    if (p.isSet(list)) printPlan(out, *script);
    out << QStringLiteral("%1: %2 step(s), ok").arg(pos[0]).arg(script->steps.size()) << "\n";
    return Ok;
}

int runRun(const QStringList& args) {
    const QString verb = QStringLiteral("script run");
    QCommandLineParser p;
    p.setApplicationDescription(
        QStringLiteral("Run a command script on a bus, step by step; stops at the first failure and names the step. "
                       "Writes are never retried."));
    p.addPositionalArgument(QStringLiteral("BUS"), QStringLiteral("Bus URL, e.g. socketcan://can0 or sim://"));
    p.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("Command script"));
    QCommandLineOption dry(QStringLiteral("dry-run"),
                           QStringLiteral("Print the steps and their reasons; open nothing, send nothing."));
    QCommandLineOption timeout(QStringLiteral("timeout"),
                               QStringLiteral("SDO timeout per response in ms (default 1000)."), QStringLiteral("MS"),
                               QStringLiteral("1000"));
    p.addOptions({dry, timeout});
    int code = 0;
    if (!parseArgs(p, verb, args, &code)) return code;
    const QStringList pos = p.positionalArguments();
    if (pos.size() != 2) return usageError(verb, QStringLiteral("expects BUS FILE"));
    bool numOk = false;
    const int timeoutMs = p.value(timeout).toInt(&numOk);
    if (!numOk || timeoutMs <= 0)
        return usageError(verb, QStringLiteral("--timeout '%1' must be a positive number of ms").arg(p.value(timeout)));
    QString error;
    if (!BusUrl::parse(pos[0], &error)) return usageError(verb, error);
    const auto script = canopen::CommandScript::load(pos[1], &error);
    if (!script) return failure(verb, error.section(u'\n', 0, 0));

    QTextStream out(stdout);
    if (p.isSet(dry)) {
        out << "Dry run: nothing is sent.\n";
        printPlan(out, *script);
        return Ok;
    }

    installInterruptHandler();
    auto s = std::make_unique<BusSession>();
    if (!s->open(pos[0], &error)) return failure(verb, error);
    s->sdo().setDefaultTimeout(timeoutMs);
    canopen::ScriptRunner runner(s->context(), s->sdo());
    // "reconnect BITS": close the adapter, open it again at the new rate (a virtual network
    // keeps its devices meanwhile), go on with the new session.
    std::shared_ptr<sim::SimNetwork> keepNetwork;
    runner.setReconnector([&](int bitRate, const canopen::ScriptRunner::Opened& opened) {
        const QString url = sim::urlAtBitRate(*s->bus(), bitRate, &keepNetwork);
        canopen::waitUntil([] { return false; }, 100);  // let the last frames leave first
        s.reset();
        s = std::make_unique<BusSession>();
        QString why;
        if (!s->open(url, &why))
            return opened(nullptr, nullptr, QStringLiteral("cannot reopen at %1 bit/s: %2").arg(bitRate).arg(why));
        s->sdo().setDefaultTimeout(timeoutMs);
        opened(&s->context(), &s->sdo(), {});
    });
    const int total = static_cast<int>(script->steps.size());
    QObject::connect(&runner, &canopen::ScriptRunner::stepFinished, &runner,
                     [&](int step, bool ok, const QString& detail) {
                         out << QStringLiteral("%1/%2 %3 %4  %5")
                                    .arg(step + 1)
                                    .arg(total)
                                    .arg(ok ? QStringLiteral("ok  ") : QStringLiteral("FAIL"),
                                         script->steps[static_cast<size_t>(step)].toLine(), detail)
                             << "\n";
                         out.flush();
                     });
    std::optional<canopen::ScriptRunResult> result;
    if (!runner.run(*script, [&](const canopen::ScriptRunResult& r) { result = r; }))
        return failure(verb, QStringLiteral("could not start"));
    while (!result) {
        canopen::waitUntil([&] { return result.has_value() || interrupted(); }, 200);
        if (!result && interrupted()) runner.cancel();
    }
    // Unconfirmed last steps (NMT, LSS switch/activate): let the frame leave before the bus closes.
    canopen::waitUntil([] { return false; }, 100);
    if (!result->ok) return failure(verb, result->error);
    out << QStringLiteral("%1 step(s) done").arg(result->stepsDone) << "\n";
    return Ok;
}

}  // namespace

COSCOPE_CLI_VERB({QStringLiteral("script run"),
                  QStringLiteral("Run a command script (saved by a wizard) on a bus; --dry-run only prints it."),
                  runRun});
COSCOPE_CLI_VERB({QStringLiteral("script check"), QStringLiteral("Check a command script's syntax (nothing is sent)."),
                  runCheck});

}  // namespace coscope::cli
