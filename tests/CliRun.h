// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Runs coscope-cli (COSCOPE_CLI_PATH) with arguments for tests: exit code (-1 when it crashed or
// did not end within `timeoutMs`, then killed), stdout and stderr.

#include <QProcess>
#include <QString>
#include <QStringList>

namespace {
struct Run {
    int code = -1;
    QString out, err;
};
[[maybe_unused]] Run cli(const QStringList& args, int timeoutMs = 120000) {
    QProcess p;
    p.start(QStringLiteral(COSCOPE_CLI_PATH), args);
    Run r;
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
        r.err = QStringLiteral("timed out");
        return r;
    }
    r.code = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}
}  // namespace
