// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/SocketCanLinkJob.h"

#include <QFile>
#include <QProcess>
#include <QProcessEnvironment>

#include <spdlog/spdlog.h>

namespace coscope {

QString ipProgram() {
    return QProcessEnvironment::systemEnvironment().value(QStringLiteral("COSCOPE_IP"), QStringLiteral("ip"));
}

QList<QStringList> bringUpSteps(const SocketCanLink& link, int bitrate, int dataBitrate) {
    const QString n = link.name;
    // ip-link(8): a virtual link has no bit timing; a real one takes "type can bitrate N" only
    // while down, so an interface that is up is set down first.
    if (link.isVirtual() || bitrate <= 0)
        return {{QStringLiteral("link"), QStringLiteral("set"), n, QStringLiteral("up")}};
    QList<QStringList> steps;
    if (link.up) steps.append({QStringLiteral("link"), QStringLiteral("set"), n, QStringLiteral("down")});
    QStringList up{QStringLiteral("link"),    QStringLiteral("set"),   n,
                   QStringLiteral("up"),      QStringLiteral("type"),  QStringLiteral("can"),
                   QStringLiteral("bitrate"), QString::number(bitrate)};
    if (dataBitrate > 0)
        up << QStringLiteral("dbitrate") << QString::number(dataBitrate) << QStringLiteral("fd")
           << QStringLiteral("on");
    // restart-ms: the kernel restarts the controller itself 100 ms after bus-off.
    up << QStringLiteral("restart-ms") << QStringLiteral("100");
    steps.append(up);
    return steps;
}

bool mayConfigureLinks() {
    // /proc/self/status "CapEff:" is a hex mask; CAP_NET_ADMIN is bit 12 (linux/capability.h).
    QFile f(QStringLiteral("/proc/self/status"));
    if (!f.open(QIODevice::ReadOnly)) return false;
    for (const QByteArray& line : f.readAll().split('\n')) {
        if (!line.startsWith("CapEff:")) continue;
        bool ok = false;
        const qulonglong caps = line.mid(7).trimmed().toULongLong(&ok, 16);
        return ok && (caps & (1ull << 12));
    }
    return false;
}

bool bringUpLink(const SocketCanLink& link, int bitrate, int dataBitrate, QString* error) {
    for (const QStringList& args : bringUpSteps(link, bitrate, dataBitrate)) {
        QProcess p;
        p.start(ipProgram(), args);
        if (!p.waitForFinished(5000) || p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0) {
            if (error) {
                const QString why = QString::fromLocal8Bit(p.readAllStandardError()).trimmed();
                *error =
                    QStringLiteral("`ip %1` failed: %2").arg(args.join(u' '), why.isEmpty() ? p.errorString() : why);
            }
            return false;
        }
    }
    return true;
}

SocketCanLinkJob::SocketCanLinkJob(QObject* parent) : QObject(parent) {}

SocketCanLinkJob::~SocketCanLinkJob() { cancel(); }

void SocketCanLinkJob::cancel() {
    if (!process_) return;
    process_->disconnect(this);
    // SIGKILL and no wait on the GUI thread: ~QProcess, run later by deleteLater, reaps it.
    process_->kill();
    process_->deleteLater();
    process_ = nullptr;
    steps_.clear();
}

void SocketCanLinkJob::list() {
    cancel();
    listing_ = true;
    steps_ = {{QStringLiteral("-details"), QStringLiteral("-json"), QStringLiteral("link"), QStringLiteral("show")}};
    runNextStep();
}

void SocketCanLinkJob::bringUp(const SocketCanLink& link, int bitrate, int dataBitrate) {
    cancel();
    listing_ = false;
    steps_ = bringUpSteps(link, bitrate, dataBitrate);
    spdlog::info("bringing up {} at {} bit/s", link.name.toStdString(), bitrate);
    runNextStep();
}

void SocketCanLinkJob::runNextStep() {
    const QStringList args = steps_.takeFirst();
    process_ = new QProcess(this);
    const QString program = ipProgram();
    connect(process_, &QProcess::finished, this, [this, args, program](int code, QProcess::ExitStatus status) {
        QProcess* p = process_;
        process_ = nullptr;
        p->deleteLater();
        const bool ok = status == QProcess::NormalExit && code == 0;
        const QString why = QString::fromLocal8Bit(p->readAllStandardError()).trimmed();
        if (listing_) {
            QList<SocketCanLink> links;
            QString error;
            if (!ok) {
                error = QStringLiteral("`%1 %2` failed: %3").arg(program, args.join(u' '), why);
            } else {
                parseIpLinkJson(p->readAllStandardOutput(), &links, &error);
            }
            emit listed(links, error);
            return;
        }
        if (!ok) {
            steps_.clear();
            spdlog::warn("ip {} failed: {}", args.join(u' ').toStdString(), why.toStdString());
            emit broughtUp(false, QStringLiteral("`ip %1` failed: %2").arg(args.join(u' '), why));
            return;
        }
        if (steps_.isEmpty()) emit broughtUp(true, {});
        else runNextStep();
    });
    connect(process_, &QProcess::errorOccurred, this, [this, program](QProcess::ProcessError e) {
        if (e != QProcess::FailedToStart || !process_) return;
        process_->deleteLater();
        process_ = nullptr;
        steps_.clear();
        const QString error = QStringLiteral("cannot run `%1` (Debian package iproute2)").arg(program);
        if (listing_) emit listed({}, error);
        else emit broughtUp(false, error);
    });
    process_->start(program, args);
}

}  // namespace coscope
