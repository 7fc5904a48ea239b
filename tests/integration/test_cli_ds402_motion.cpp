// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli ds402 home / ds402 move on sim://: --help, the refusal without a terminal and
// without --yes (nothing sent), homing and moving with every controlword printed, a method the
// drive lacks refused before anything moves, and the end with the drive disabled after success,
// failure and Ctrl+C (SIGINT).
#include "tests/CliRun.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QtTest>

#include <csignal>

namespace {
const QString kBus = QStringLiteral("sim://?nodes=1:delta-asda-a2,2:aimotor,3:generic-cia402");
QStringList args(std::initializer_list<const char*> words) {
    QStringList out;
    for (const char* w : words) out << QString::fromLatin1(w);
    return out;
}
// The last controlword the CLI printed, e.g. "0x0000".
QString lastControlword(const QString& out) {
    QString last;
    const auto it = QRegularExpression(QStringLiteral("6040h = (0x[0-9A-F]{4})")).globalMatch(out);
    for (auto i = it; i.hasNext();) last = i.next().captured(1);
    return last;
}
}  // namespace

class TestCliDs402Motion : public QObject {
    Q_OBJECT
private slots:
    void help_data() {
        QTest::addColumn<QString>("verb");
        QTest::newRow("home") << QStringLiteral("home");
        QTest::newRow("move") << QStringLiteral("move");
    }
    void help() {
        QFETCH(QString, verb);
        const Run r = cli({QStringLiteral("ds402"), verb, QStringLiteral("--help")});
        QCOMPARE(r.code, 0);
        QVERIFY(r.out.contains(QStringLiteral("Usage")));
        QVERIFY(r.out.contains(QStringLiteral("--yes")));
        QVERIFY(r.out.contains(QStringLiteral("disabled")));
    }

    void refusesWithoutTerminalOrYes() {
        // QProcess gives stdin as a pipe: no terminal to ask on.
        const Run r = cli({QStringLiteral("ds402"), QStringLiteral("home"), kBus, QStringLiteral("3")});
        QCOMPARE(r.code, 1);
        QCOMPARE(r.err.count(u'\n'), 1);
        QVERIFY2(r.err.contains(QStringLiteral("no terminal")) && r.err.contains(QStringLiteral("--yes")),
                 qPrintable(r.err));
        QVERIFY(!r.out.contains(QStringLiteral("send ")));
        const Run m =
            cli({QStringLiteral("ds402"), QStringLiteral("move"), kBus, QStringLiteral("3"), QStringLiteral("1000")});
        QCOMPARE(m.code, 1);
        QVERIFY2(m.err.contains(QStringLiteral("no terminal")), qPrintable(m.err));
    }

    void homeOnEachDriveEndsDisabled_data() {
        QTest::addColumn<QStringList>("extra");
        QTest::newRow("generic 35") << args({"3"});
        QTest::newRow("aimotor 35") << args({"2", "--method", "35"});
        QTest::newRow("generic 1 with speeds") << args({"3", "--method", "1", "--fast", "50000", "--slow", "10000",
                                                        "--acceleration", "500000", "--offset", "100"});
        QTest::newRow("delta 17 in 0.1 rpm")
            << args({"1", "--method", "17", "--fast", "2000", "--slow", "500", "--acceleration", "20"});
    }
    void homeOnEachDriveEndsDisabled() {
        QFETCH(QStringList, extra);
        const Run r = cli(QStringList{QStringLiteral("ds402"), QStringLiteral("home"), kBus} + extra +
                          QStringList{QStringLiteral("--yes")});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains(QStringLiteral("6040h = 0x001F (Homing operation start")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("homing attained, position actual 6064h = ")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("target reached, homing attained")),
                 qPrintable(r.out));                                 // bit names in homing mode
        QCOMPARE(lastControlword(r.out), QStringLiteral("0x0000"));  // disabled at the end
        QVERIFY2(r.out.trimmed().endsWith(QStringLiteral("disabled")), qPrintable(r.out));
        if (extra.contains(QStringLiteral("--offset")))
            QVERIFY2(r.out.contains(QStringLiteral("6064h = 100 ")), qPrintable(r.out));
    }

    void methodTheDriveLacksIsRefused() {
        // AIMOTOR has no method 3 (extract-aimotor §4.7): refused before anything is sent.
        Run r = cli({QStringLiteral("ds402"), QStringLiteral("home"), kBus, QStringLiteral("2"),
                     QStringLiteral("--method"), QStringLiteral("3"), QStringLiteral("--yes")});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral(
                     "no homing method 3; its methods are 1, 2, 4, 6, 17, 18, 24, 28, 33, 34, 35, 37, 38")),
                 qPrintable(r.err));
        QVERIFY(!r.out.contains(QStringLiteral("6040h")));
        // --methods lists the drive's own table.
        r = cli(
            {QStringLiteral("ds402"), QStringLiteral("home"), kBus, QStringLiteral("2"), QStringLiteral("--methods")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral(" 37  Mechanical end stop in the positive direction")),
                 qPrintable(r.out));
    }

    void moveAndFailureEndDisabled() {
        Run r = cli({QStringLiteral("ds402"), QStringLiteral("move"), kBus, QStringLiteral("3"), QStringLiteral("1000"),
                     QStringLiteral("--velocity"), QStringLiteral("5000"), QStringLiteral("--yes")});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains(QStringLiteral("6040h = 0x001F (New set-point")) &&
                     r.out.contains(QStringLiteral("Set-point acknowledged: new set-point (bit 4) low")),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("target reached, position actual 6064h = 1000 ")), qPrintable(r.out));
        QCOMPARE(lastControlword(r.out), QStringLiteral("0x0000"));
        // Relative on the AIMOTOR (a fresh simulator: from 0).
        r = cli({QStringLiteral("ds402"), QStringLiteral("move"), kBus, QStringLiteral("2"), QStringLiteral("-1000"),
                 QStringLiteral("--relative"), QStringLiteral("--velocity"), QStringLiteral("5000"),
                 QStringLiteral("--yes")});
        QVERIFY2(r.code == 0, qPrintable(r.out + r.err));
        QVERIFY2(r.out.contains(QStringLiteral("6040h = 0x005F")) && r.out.contains(QStringLiteral("6064h = -1000 ")),
                 qPrintable(r.out));
        // A failure (homing not done in time) still ends disabled.
        r = cli({QStringLiteral("ds402"), QStringLiteral("home"), kBus, QStringLiteral("3"), QStringLiteral("--method"),
                 QStringLiteral("1"), QStringLiteral("--fast"), QStringLiteral("1000"), QStringLiteral("--timeout"),
                 QStringLiteral("300"), QStringLiteral("--yes")});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("did not finish homing within 300 ms")) &&
                     r.err.contains(QStringLiteral("drive disabled")),
                 qPrintable(r.err));
        QCOMPARE(lastControlword(r.out), QStringLiteral("0x0000"));
    }

    void interruptStopsAndDisables() {
        QProcess p;
        p.start(QStringLiteral(COSCOPE_CLI_PATH),
                {QStringLiteral("ds402"), QStringLiteral("home"), kBus, QStringLiteral("3"), QStringLiteral("--method"),
                 QStringLiteral("1"), QStringLiteral("--fast"), QStringLiteral("1000"), QStringLiteral("--yes")});
        QVERIFY(p.waitForStarted(5000));
        QString out;
        QElapsedTimer t;
        t.start();
        while (!out.contains(QStringLiteral("ms: statusword")) && t.elapsed() < 20000) {
            p.waitForReadyRead(100);
            out += QString::fromUtf8(p.readAllStandardOutput());
        }
        QVERIFY2(out.contains(QStringLiteral("ms: statusword")), qPrintable(out));
        ::kill(pid_t(p.processId()), SIGINT);
        QVERIFY(p.waitForFinished(20000));
        out += QString::fromUtf8(p.readAllStandardOutput());
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QCOMPARE(p.exitCode(), 1);
        QVERIFY2(out.contains(QStringLiteral("interrupted: stopping node 3")) &&
                     out.contains(QStringLiteral("Halt: interrupted")),
                 qPrintable(out));
        QVERIFY2(err.contains(QStringLiteral("stopped (interrupted (Ctrl+C))")) &&
                     err.contains(QStringLiteral("drive disabled")),
                 qPrintable(err));
        QCOMPARE(lastControlword(out), QStringLiteral("0x0000"));
    }
};

QTEST_GUILESS_MAIN(TestCliDs402Motion)
#include "test_cli_ds402_motion.moc"
