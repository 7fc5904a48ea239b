// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 35: the coscope-cli ds402 verbs that can move a motor end with the drive disabled,
// whatever happens — the jog run to its end, and the jog stopped by SIGTERM (as Ctrl+C does)
// while the motor turns: it halts, disables and says so, instead of dying with the motor on.
#include "tests/CliRun.h"

#include <QProcess>
#include <QtTest>

namespace {
const QString kBus = QStringLiteral("sim://?nodes=3:generic-cia402");
// The line index of the first "send" of 6040h = `cw` after line `from`, or -1.
int sentAfter(const QStringList& lines, int from, const QString& cw) {
    for (int i = from + 1; i < lines.size(); ++i)
        if (lines[i].startsWith(QStringLiteral("send node 3: 6040h = ") + cw)) return i;
    return -1;
}
int lineWith(const QStringList& lines, const QString& text) {
    for (int i = 0; i < lines.size(); ++i)
        if (lines[i].contains(text)) return i;
    return -1;
}
}  // namespace

class TestCliDs402EndsDisabled : public QObject {
    Q_OBJECT
private slots:
    void jogEndsDisabled() {
        const Run r =
            cli({QStringLiteral("ds402"), QStringLiteral("jog"), kBus, QStringLiteral("3"), QStringLiteral("2000"),
                 QStringLiteral("--for"), QStringLiteral("400"), QStringLiteral("--yes")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QStringList lines = r.out.split(u'\n');
        const int target = lineWith(lines, QStringLiteral("60FFh = 2000"));
        QVERIFY2(target >= 0, qPrintable(r.out));
        QVERIFY2(sentAfter(lines, target, QStringLiteral("0x0000")) > target, qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("node 3: disabled")), qPrintable(r.out));
    }

    void interruptedJogEndsDisabled() {
        QProcess p;
        p.start(QStringLiteral(COSCOPE_CLI_PATH),
                {QStringLiteral("ds402"), QStringLiteral("jog"), kBus, QStringLiteral("3"), QStringLiteral("2000"),
                 QStringLiteral("--for"), QStringLiteral("20000"), QStringLiteral("--yes")});
        QVERIFY(p.waitForStarted());
        QString out;
        QTRY_VERIFY_WITH_TIMEOUT(
            (out += QString::fromUtf8(p.readAllStandardOutput())).contains(QStringLiteral("60FFh = 2000")), 10000);
        QTest::qWait(300);  // turning
        p.terminate();      // SIGTERM
        QVERIFY(p.waitForFinished(15000));
        out += QString::fromUtf8(p.readAllStandardOutput());
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 1);
        QVERIFY2(err.contains(QStringLiteral("interrupted")) && err.contains(QStringLiteral("drive disabled")),
                 qPrintable(err));
        const QStringList lines = out.split(u'\n');
        const int target = lineWith(lines, QStringLiteral("60FFh = 2000"));
        QVERIFY2(sentAfter(lines, target, QStringLiteral("0x010F")) > target, qPrintable(out));  // halt
        QVERIFY2(sentAfter(lines, target, QStringLiteral("0x0000")) > target, qPrintable(out));  // disable voltage
    }
};

QTEST_GUILESS_MAIN(TestCliDs402EndsDisabled)
#include "test_cli_ds402_ends_disabled.moc"
