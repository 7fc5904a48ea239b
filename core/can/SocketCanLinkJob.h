// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/can/SocketCanLinks.h"

#include <QObject>
#include <QStringList>

class QProcess;

namespace coscope {

// The `ip` runs behind the Connect dialog, without blocking the caller's thread: list the CAN
// interfaces, and bring one up at a bit rate (ip-link(8) "type can"). The program is `ip`, or
// the environment variable COSCOPE_IP (tests). One run at a time; a new one cancels the last.
class SocketCanLinkJob : public QObject {
    Q_OBJECT
public:
    explicit SocketCanLinkJob(QObject* parent = nullptr);
    ~SocketCanLinkJob() override;

    void list();
    void bringUp(const SocketCanLink& link, int bitrate, int dataBitrate);
    bool busy() const { return process_ != nullptr; }

signals:
    void listed(const QList<SocketCanLink>& links, const QString& error);
    // ok = every step exited 0; error is `ip`'s own message otherwise.
    void broughtUp(bool ok, const QString& error);

private:
    void runNextStep();
    void cancel();

    QProcess* process_ = nullptr;
    QList<QStringList> steps_;
    bool listing_ = false;
};

// The `ip` arguments that bring `link` up at the bit rate (set down first when it is up and
// the rate changes): what bringUpCommand() prints after "sudo ip ".
QList<QStringList> bringUpSteps(const SocketCanLink& link, int bitrate, int dataBitrate);

// Whether this process may configure network interfaces: CAP_NET_ADMIN in its effective set
// (capabilities(7); root has it). Without it the Connect dialog only shows the command.
bool mayConfigureLinks();

// Runs the steps and waits (CLI); false with `ip`'s message on failure.
bool bringUpLink(const SocketCanLink& link, int bitrate, int dataBitrate, QString* error);

QString ipProgram();

}  // namespace coscope
