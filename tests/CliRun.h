// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Runs coscope-cli (COSCOPE_CLI_PATH) with arguments for tests: exit code (-1 when it crashed or
// did not end within `timeoutMs`, then killed), stdout and stderr.

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QProcess>
#include <QString>
#include <QStringList>

#include <algorithm>

namespace {
struct Run {
    int code = -1;
    QString out, err;
};
// `serveEvents`: this thread's event loop keeps turning while it waits (a socketcand server or
// virtual network in the test process answers the program).
[[maybe_unused]] Run cli(const QStringList& args, int timeoutMs = 120000, bool serveEvents = false) {
    QProcess p;
    p.start(QStringLiteral(COSCOPE_CLI_PATH), args);
    Run r;
    QElapsedTimer t;
    t.start();
    if (serveEvents) {
        while (p.state() != QProcess::NotRunning && t.elapsed() < timeoutMs) {
            QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
            p.waitForFinished(5);
        }
    }
    if (p.state() != QProcess::NotRunning && !p.waitForFinished(int(std::max<qint64>(0, timeoutMs - t.elapsed())))) {
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
