// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/Ds402Cli.h"

#include "app/cli/CliVerb.h"
#include "core/canopen/ServiceWait.h"

#include <unistd.h>
#include <cstdio>

namespace coscope::cli {

void printSends(canopen::Ds402Controller& ctl, QTextStream& out) {
    ctl.setSendObserver([&out](const QString& line) {
        out << "send " << line << "\n";
        out.flush();
    });
}

canopen::Ds402Result waitDs402(const std::function<void(canopen::Ds402Callback)>& start, int timeoutMs) {
    auto r = canopen::waitForResult<canopen::Ds402Result>(start, timeoutMs);
    if (!r) {
        canopen::Ds402Result none;
        none.error = QStringLiteral("no answer in time");
        return none;
    }
    return *r;
}

bool mayConfirmMotion(bool yes, QString* why) {
    if (yes || isatty(fileno(stdin))) return true;
    *why = QStringLiteral(
        "this can move a motor and there is no terminal to ask for confirmation on: refused, nothing was sent (add "
        "--yes to confirm)");
    return false;
}

bool confirmMotion(bool yes, const QString& question, QString* why) {
    if (!mayConfirmMotion(yes, why)) return false;
    if (yes) return true;
    QTextStream out(stdout);
    out << question << "\nMake sure the axis is free to move. Type yes to continue: ";
    out.flush();
    char line[64] = {};
    if (!std::fgets(line, sizeof line, stdin) || QString::fromLatin1(line).trimmed().toLower() != u"yes") {
        *why = QStringLiteral("not confirmed; nothing was sent (use --yes to skip the question)");
        return false;
    }
    return true;
}

int endDisabled(canopen::Ds402Controller& ctl, const QString& verb, uint8_t node, const QString& failed,
                QTextStream& out) {
    const auto d = waitDs402([&](auto cb) { ctl.disable(cb); }, 10000);
    if (!d.ok) {
        const auto v = waitDs402([&](auto cb) { ctl.disableVoltage(cb); }, 5000);
        if (!v.ok)
            return failure(verb, (failed.isEmpty() ? QString() : failed + QStringLiteral("; ")) +
                                     QStringLiteral("DISABLING FAILED: ") + v.error);
    }
    if (!failed.isEmpty()) return failure(verb, failed + QStringLiteral("; drive disabled"));
    out << "node " << node << ": disabled\n";
    out.flush();
    return Ok;
}

}  // namespace coscope::cli
