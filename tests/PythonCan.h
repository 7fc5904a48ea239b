// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The python that has python-can (Debian python3-can), for tests that use it as a third-party
// peer: Debian's /usr/bin/python3 first (a pyenv/venv python3 on PATH usually lacks the Debian
// module), then python3 from PATH. Empty when there is none (the test then skips).

#include <QProcess>
#include <QString>

namespace {
// `module` is what the test needs of python-can (its socketcand interface by default).
[[maybe_unused]] QString pythonWithCan(const QString& module = QStringLiteral("can.interfaces.socketcand")) {
    for (const QString& py : {QStringLiteral("/usr/bin/python3"), QStringLiteral("python3")}) {
        QProcess p;
        p.start(py, {QStringLiteral("-c"), QStringLiteral("import ") + module});
        if (p.waitForFinished(20000) && p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0) return py;
    }
    return {};
}
}  // namespace
