// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The python that has python-can (Debian python3-can), for tests that use it as a third-party
// peer: Debian's /usr/bin/python3 first (a pyenv/venv python3 on PATH usually lacks the Debian
// module), then python3 from PATH. Empty when there is none (the test then skips).

#include <QElapsedTimer>
#include <QProcess>
#include <QString>
#include <QStringList>

#include <initializer_list>

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

// Starts a python-can peer script (`py script args...`) and waits until it prints READY (it has
// joined the bus); false with what it printed in *out when it did not within 20 s.
[[maybe_unused]] bool startPythonPeer(QProcess& peer, const QString& py, const QString& script, const QStringList& args,
                                      QString* out) {
    peer.setProcessChannelMode(QProcess::SeparateChannels);
    peer.start(py, QStringList{script} + args);
    QElapsedTimer t;
    t.start();
    while (!out->contains(QStringLiteral("READY")) && t.elapsed() < 20000 && peer.state() != QProcess::NotRunning) {
        peer.waitForReadyRead(200);
        *out += QString::fromUtf8(peer.readAllStandardOutput());
    }
    if (out->contains(QStringLiteral("READY"))) return true;
    *out += QString::fromUtf8(peer.readAllStandardError());
    return false;
}

// Ends the processes a test started: terminate, then kill after 5 s.
[[maybe_unused]] void stopProcesses(std::initializer_list<QProcess*> processes) {
    for (QProcess* p : processes) {
        if (p->state() == QProcess::NotRunning) continue;
        p->terminate();
        if (!p->waitForFinished(5000)) {
            p->kill();
            p->waitForFinished();
        }
    }
}
}  // namespace
