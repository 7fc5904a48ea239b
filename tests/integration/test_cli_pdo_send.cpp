// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli pdo send (issue 35): the AIMOTOR's RPDO1 composed from its dictionary's default
// mapping (extract-aimotor §2: 6040h/16, 6060h/8, 607Ah/32 at 200h + node), the motion question,
// the end with halt and Disable voltage, and the usage errors.
#include "tests/CliRun.h"

#include <QProcess>
#include <QtTest>

namespace {
const QString kBus = QStringLiteral("sim://?nodes=2:aimotor");
}

class TestCliPdoSend : public QObject {
    Q_OBJECT
private slots:
    void composesAndEndsDisabled() {
        const Run r = cli({QStringLiteral("pdo"), QStringLiteral("send"), kBus, QStringLiteral("2"),
                           QStringLiteral("RPDO1"), QStringLiteral("6040=0x000F"), QStringLiteral("6060=3"),
                           QStringLiteral("607A=3E8h"), QStringLiteral("--every"), QStringLiteral("20ms"),
                           QStringLiteral("--duration"), QStringLiteral("0.3"), QStringLiteral("--yes")});
        QVERIFY2(r.code == 0, qPrintable(r.err + r.out));
        QVERIFY2(r.out.contains(QStringLiteral("frame 202#0F0003E8030000")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("Disable voltage")), qPrintable(r.out));
        const QRegularExpression sent(QStringLiteral("sent (\\d+) frame"));
        const auto m = sent.match(r.out);
        QVERIFY2(m.hasMatch() && m.captured(1).toInt() >= 8, qPrintable(r.out));
    }

    void motionAsksFirst() {
        QProcess p;
        p.start(QStringLiteral(COSCOPE_CLI_PATH),
                {QStringLiteral("pdo"), QStringLiteral("send"), kBus, QStringLiteral("2"), QStringLiteral("RPDO2"),
                 QStringLiteral("60FF=100")});
        QVERIFY(p.waitForStarted());
        p.write("no\n");
        p.closeWriteChannel();
        QVERIFY(p.waitForFinished(30000));
        QCOMPARE(p.exitCode(), 1);
        const QString out = QString::fromUtf8(p.readAllStandardOutput());
        QVERIFY2(out.contains(QStringLiteral("frame 302#640000000000")), qPrintable(out));  // 60FFh = 100, 6071h = 0
        QVERIFY(QString::fromUtf8(p.readAllStandardError()).contains(QStringLiteral("not confirmed")));
    }

    void usageErrors() {
        QCOMPARE(cli({QStringLiteral("pdo"), QStringLiteral("send"), kBus, QStringLiteral("2"), QStringLiteral("TPDO1"),
                      QStringLiteral("6040=1")})
                     .code,
                 2);
        QCOMPARE(cli({QStringLiteral("pdo"), QStringLiteral("send"), kBus, QStringLiteral("2"), QStringLiteral("RPDO1"),
                      QStringLiteral("6040")})
                     .code,
                 2);
        const Run r = cli({QStringLiteral("pdo"), QStringLiteral("send"), kBus, QStringLiteral("2"),
                           QStringLiteral("RPDO1"), QStringLiteral("6041=1"), QStringLiteral("--yes")});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("not mapped")), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(TestCliPdoSend)
#include "test_cli_pdo_send.moc"
