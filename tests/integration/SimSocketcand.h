// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Starts `coscope-cli sim --listen socketcand://127.0.0.1:0 [--nodes SPEC]` and reads the port
// from its banner, for tests that reach the virtual drives over socketcand (CoScope's CLI or a
// python-can peer). Empty port and *error when it did not come up within 15 s.

#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QString>
#include <QStringList>

namespace {
[[maybe_unused]] QString startSimSocketcand(QProcess& sim, const QString& nodes, QString* error) {
    QStringList args{QStringLiteral("sim"), QStringLiteral("--listen"), QStringLiteral("socketcand://127.0.0.1:0")};
    if (!nodes.isEmpty()) args << QStringLiteral("--nodes") << nodes;
    sim.setProcessChannelMode(QProcess::SeparateChannels);
    sim.start(QStringLiteral(COSCOPE_CLI_PATH), args);
    if (!sim.waitForStarted(5000)) {
        *error = sim.errorString();
        return {};
    }
    QString banner;
    QElapsedTimer t;
    t.start();
    while (!banner.contains(u'\n') && t.elapsed() < 15000 && sim.state() == QProcess::Running) {
        sim.waitForReadyRead(200);
        banner += QString::fromUtf8(sim.readAllStandardOutput());
    }
    const auto m = QRegularExpression(QStringLiteral("socketcand://127\\.0\\.0\\.1:(\\d+)/")).match(banner);
    if (!m.hasMatch()) {
        *error = banner + QString::fromUtf8(sim.readAllStandardError());
        return {};
    }
    return m.captured(1);
}
}  // namespace
