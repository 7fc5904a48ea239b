// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli guard (issue 35 item 1): node guarding of the generic drive of sim:// (no
// heartbeat: 1017h = 0) every 100 ms for 1 s: about ten RTRs on 703h, answered with the right
// toggle (CiA 301 §7.2.8.3.2.1), no guarding error, exit 0; a node that is not there is lost
// after guard time x life time factor, exit 1 with one line; --heartbeat watches a heartbeat
// instead; listen-only refuses guarding; usage errors exit 2.
#include "tests/CliRun.h"

#include <QRegularExpression>
#include <QtTest>

class TestCliGuard : public QObject {
    Q_OBJECT
private slots:
    void guardsAnAnsweringNode() {
        const Run r =
            cli({QStringLiteral("guard"), QStringLiteral("sim://?nodes=3:generic-cia402"), QStringLiteral("3"),
                 QStringLiteral("--guard-time"), QStringLiteral("100ms"), QStringLiteral("--life"), QStringLiteral("3"),
                 QStringLiteral("--duration"), QStringLiteral("1")});
        QVERIFY2(r.code == 0, qPrintable(r.err + r.out));
        QVERIFY2(r.out.contains(QStringLiteral("guarding node 3: RTR on 0x703 every 100 ms, lost after 300 ms")),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("node 3: ok (NMT state Pre-operational)")), qPrintable(r.out));
        const auto m =
            QRegularExpression(QStringLiteral("node 3: ok; (\\d+) guarding requests, 0 guarding errors, lost 0 time"))
                .match(r.out);
        QVERIFY2(m.hasMatch() && m.captured(1).toInt() >= 8 && m.captured(1).toInt() <= 12, qPrintable(r.out));
    }

    void absentNodeIsLost() {
        const Run r =
            cli({QStringLiteral("guard"), QStringLiteral("sim://?nodes=3:generic-cia402"), QStringLiteral("9"),
                 QStringLiteral("--guard-time"), QStringLiteral("50"), QStringLiteral("--life"), QStringLiteral("2"),
                 QStringLiteral("--duration"), QStringLiteral("0.5")});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.out.contains(QStringLiteral("node 9: lost")), qPrintable(r.out));
        QVERIFY2(r.err.contains(QStringLiteral("node 9 was lost")), qPrintable(r.err));
    }

    void heartbeatWatchSendsNothing() {
        // The generic drive sends no heartbeat: lost after the consumer time.
        const Run r = cli({QStringLiteral("guard"), QStringLiteral("sim://?nodes=3:generic-cia402&listen-only=1"),
                           QStringLiteral("3"), QStringLiteral("--heartbeat"), QStringLiteral("200ms"),
                           QStringLiteral("--duration"), QStringLiteral("0.5")});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.out.contains(QStringLiteral("watching node 3's heartbeat")) &&
                     r.out.contains(QStringLiteral("node 3: lost")),
                 qPrintable(r.out));
        const Run g = cli({QStringLiteral("guard"), QStringLiteral("sim://?nodes=3:generic-cia402&listen-only=1"),
                           QStringLiteral("3"), QStringLiteral("--duration"), QStringLiteral("0.2")});
        QCOMPARE(g.code, 1);
        QVERIFY2(g.err.contains(QStringLiteral("listen-only")), qPrintable(g.err));
    }

    void usageErrors() {
        QCOMPARE(cli({QStringLiteral("guard"), QStringLiteral("sim://")}).code, 2);
        QCOMPARE(cli({QStringLiteral("guard"), QStringLiteral("sim://"), QStringLiteral("0")}).code, 2);
        QCOMPARE(cli({QStringLiteral("guard"), QStringLiteral("sim://"), QStringLiteral("3"), QStringLiteral("--life"),
                      QStringLiteral("0")})
                     .code,
                 2);
        QCOMPARE(cli({QStringLiteral("guard"), QStringLiteral("sim://"), QStringLiteral("3"),
                      QStringLiteral("--guard-time"), QStringLiteral("1500us")})
                     .code,
                 2);
    }
};

QTEST_GUILESS_MAIN(TestCliGuard)
#include "test_cli_guard.moc"
