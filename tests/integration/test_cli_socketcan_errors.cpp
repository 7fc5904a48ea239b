// SPDX-License-Identifier: GPL-3.0-or-later
// Opening a SocketCAN interface that cannot be opened says what it means and what to do, whatever
// this machine's kernel has: without CAN support the socket call fails (EAFNOSUPPORT), with it the
// interface is missing (ENODEV). Either way the message names a remedy, never only strerror.
#include "CliRun.h"
#include "core/can/BusUrl.h"
#include "core/can/SocketCanLinkJob.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

class TestCliSocketcanErrors : public QObject {
    Q_OBJECT
private slots:
    void missingInterfaceIsExplained() {
        if (!coscope::qtCanPlugins().contains(QStringLiteral("socketcan")))
            QSKIP("Qt's socketcan plugin is not installed");
        qputenv("COSCOPE_IP", "/nonexistent/ip");  // so the advice does not depend on this machine's interfaces
        const Run r = cli({QStringLiteral("listen"), QStringLiteral("socketcan://nosuchcan9"),
                           QStringLiteral("--duration"), QStringLiteral("2")});
        qunsetenv("COSCOPE_IP");
        QCOMPARE(r.code, 1);
        const QString last = r.err.trimmed().section(u'\n', -1);
        QVERIFY2(last.contains(QStringLiteral("socketcan://nosuchcan9")), qPrintable(r.err));
        const bool noKernelCan = last.contains(QStringLiteral("modprobe can_raw"));
        const bool noInterface = last.contains(QStringLiteral("no CAN interface named 'nosuchcan9'"));
        QVERIFY2(noKernelCan || noInterface, qPrintable(r.err));
    }

    // `buses --bring-up` runs the command the Connect dialog shows (ip-link(8) "type can"),
    // setting an interface that is up down first to change its rate.
    void bringUpRunsIpLink() {
        if (!coscope::mayConfigureLinks()) QSKIP("runs without CAP_NET_ADMIN");
        QTemporaryDir dir;
        const QString ip = dir.filePath(QStringLiteral("ip")), calls = dir.filePath(QStringLiteral("calls"));
        QFile f(ip);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QStringLiteral("#!/bin/sh\nif [ \"$1\" = -details ]; then\n"
                               "echo "
                               "'[{\"ifname\":\"can1\",\"flags\":[\"UP\"],\"link_type\":\"can\",\"linkinfo\":{\"info_"
                               "kind\":\"can\",\"info_data\":{\"bittiming\":{\"bitrate\":500000}}}}]'\n"
                               "exit 0\nfi\necho \"$*\" >> '%1'\n")
                    .arg(calls)
                    .toUtf8());
        f.close();
        f.setPermissions(f.permissions() | QFileDevice::ExeOwner);
        qputenv("COSCOPE_IP", ip.toLocal8Bit());
        const Run r = cli({QStringLiteral("buses"), QStringLiteral("--bring-up"), QStringLiteral("can1"),
                           QStringLiteral("--bitrate"), QStringLiteral("250000"), QStringLiteral("--data-bitrate"),
                           QStringLiteral("2000000")});
        const Run missing = cli({QStringLiteral("buses"), QStringLiteral("--bring-up"), QStringLiteral("can7")});
        qunsetenv("COSCOPE_IP");
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QFile log(calls);
        QVERIFY(log.open(QIODevice::ReadOnly));
        QCOMPARE(QString::fromUtf8(log.readAll()),
                 QStringLiteral("link set can1 down\nlink set can1 up type can bitrate 250000 dbitrate 2000000 fd on "
                                "restart-ms 100\n"));
        QCOMPARE(missing.code, 1);
        QVERIFY2(missing.err.contains(QStringLiteral("no CAN interface named 'can7'")), qPrintable(missing.err));
    }

    // A bus-off error frame (CAN_ERR_BUSOFF) is reported on stderr and capture goes on; with
    // --restart-on-bus-off a backend that cannot restart says why.
    void busOffIsReportedAndRestartAsked() {
        QTemporaryDir dir;
        const QString log = dir.filePath(QStringLiteral("busoff.log"));
        QFile f(log);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(
            "(1700000000.000000) can0 701#05\n(1700000000.100000) can0 20000040#0000000000000000\n(1700000000.200000) "
            "can0 702#05\n");
        f.close();
        const QString url = QStringLiteral("replay://%1?speed=0").arg(log);
        Run r = cli({QStringLiteral("listen"), url});
        QCOMPARE(r.code, 0);
        QCOMPARE(r.out.count(u'\n'), 3);  // nothing lost
        QVERIFY2(r.err.contains(QStringLiteral("is bus-off")) && r.err.contains(QStringLiteral("--restart-on-bus-off")),
                 qPrintable(r.err));
        r = cli({QStringLiteral("listen"), url, QStringLiteral("--restart-on-bus-off")});
        QCOMPARE(r.code, 0);
        QVERIFY2(r.err.contains(QStringLiteral("could not be restarted")) &&
                     r.err.contains(QStringLiteral("cannot restart")),
                 qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliSocketcanErrors)
#include "test_cli_socketcan_errors.moc"
