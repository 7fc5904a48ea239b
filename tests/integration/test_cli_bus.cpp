// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli listen / send / record, run as a user would (QProcess).
#include "core/can/CanFrame.h"
#include "integration/FakeSocketcandServer.h"
#include "tests/CliRun.h"

#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace coscope;

namespace {
// "(1700000000.123456) sim 701#7F": the line's three fields, the frame parseable by cansend rules.
bool isCandumpL(const QString& line, const QString& iface, QString* why) {
    static const QRegularExpression re(QStringLiteral(R"(^\((\d+)\.(\d{6})\) (\S+) (\S+)$)"));
    const auto m = re.match(line);
    if (!m.hasMatch()) {
        *why = QStringLiteral("not a candump -L line: '%1'").arg(line);
        return false;
    }
    if (m.captured(3) != iface) {
        *why = QStringLiteral("interface '%1', expected '%2'").arg(m.captured(3), iface);
        return false;
    }
    return parseCansend(m.captured(4), why).has_value();
}

QStringList lines(const QString& text) { return text.split(u'\n', Qt::SkipEmptyParts); }
}  // namespace

class TestCliBus : public QObject {
    Q_OBJECT
private slots:
    void listenPrintsCandumpLines() {
        const Run r =
            cli({QStringLiteral("listen"), QStringLiteral("sim://"), QStringLiteral("--count"), QStringLiteral("3")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QStringList l = lines(r.out);
        QCOMPARE(l.size(), 3);
        QString why;
        for (const QString& line : l) QVERIFY2(isCandumpL(line, QStringLiteral("sim"), &why), qPrintable(why));
        QVERIFY2(l[0].endsWith(QStringLiteral("#00")), qPrintable(l[0]));  // boot-up (CiA 301 7.2.8.3.3)
    }
    void listenDurationStops() {
        QElapsedTimer t;
        t.start();
        const Run r = cli(
            {QStringLiteral("listen"), QStringLiteral("sim://"), QStringLiteral("--duration"), QStringLiteral("0.5")});
        QCOMPARE(r.code, 0);
        QVERIFY(t.elapsed() < 5000);
        QVERIFY(lines(r.out).size() >= 3);
    }
    void sendBadSyntaxIsUsageError() {
        const Run r = cli({QStringLiteral("send"), QStringLiteral("sim://"), QStringLiteral("12#zz")});
        QCOMPARE(r.code, 2);
        QCOMPARE(lines(r.err).size(), 1);
        QVERIFY2(r.err.startsWith(QStringLiteral("coscope-cli send: invalid frame '12#zz'")), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
    }
    void sendWorks() {
        const Run r = cli({QStringLiteral("send"), QStringLiteral("sim://"), QStringLiteral("123#R")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
    }
    void sendReachesSocketcand() {
        FakeSocketcandServer server;
        QVERIFY(server.listen());
        QProcess p;
        p.start(QStringLiteral(COSCOPE_CLI_PATH),
                {QStringLiteral("send"), server.url(), QStringLiteral("1F334455#11.22")});
        QTRY_VERIFY_WITH_TIMEOUT(p.state() == QProcess::NotRunning, 10000);
        QCOMPARE(p.exitCode(), 0);
        QCOMPARE(server.afterHandshake, QByteArray("< send 1F334455 2 11 22 >"));
    }
    void unknownSchemeIsUsageError() {
        const Run r = cli({QStringLiteral("listen"), QStringLiteral("sockcan://x")});
        QCOMPARE(r.code, 2);
        QCOMPARE(lines(r.err).size(), 1);
        QVERIFY2(r.err.startsWith(QStringLiteral("coscope-cli listen: unknown scheme 'sockcan'; known: ")),
                 qPrintable(r.err));
        const Run s =
            cli({QStringLiteral("record"), QStringLiteral("sockcan://x"), QStringLiteral("/nonexistent/x.log")});
        QCOMPARE(s.code, 2);
    }
    void unreachableBusFails() {
        quint16 port = 0;
        {
            QTcpServer probe;
            QVERIFY(probe.listen(QHostAddress::LocalHost, 0));
            port = probe.serverPort();
        }
        const Run r = cli({QStringLiteral("listen"), QStringLiteral("socketcand://127.0.0.1:%1/can0").arg(port)});
        QCOMPARE(r.code, 1);
        QVERIFY2(lines(r.err).last() ==
                     QStringLiteral("coscope-cli listen: cannot reach socketcand at 127.0.0.1:%1: connection refused")
                         .arg(port),
                 qPrintable(r.err));
    }
    void recordWritesParseableLog() {
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("out.log"));
        const Run r = cli({QStringLiteral("record"), QStringLiteral("sim://"), out, QStringLiteral("--duration"),
                           QStringLiteral("1.5")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QFile f(out);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray all = f.readAll();
        QVERIFY(all.endsWith('\n'));
        const QStringList l = lines(QString::fromUtf8(all));
        QVERIFY2(l.size() >= 3, qPrintable(QString::number(l.size())));
        QString why;
        for (const QString& line : l) QVERIFY2(isCandumpL(line, QStringLiteral("sim"), &why), qPrintable(why));
    }
    void recordSurvivesSigterm() {
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("term.log"));
        QProcess p;
        p.start(QStringLiteral(COSCOPE_CLI_PATH), {QStringLiteral("record"), QStringLiteral("sim://"), out});
        QVERIFY(p.waitForStarted());
        // Lines reach the file while recording (flushed every 100 ms), before any signal.
        QTRY_VERIFY_WITH_TIMEOUT(QFileInfo(out).size() > 0, 3000);
        QTest::qWait(1200);  // heartbeats after the boot-ups
        p.terminate();       // SIGTERM
        QVERIFY(p.waitForFinished(5000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 0);
        QFile f(out);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray all = f.readAll();
        QVERIFY(all.endsWith('\n'));
        const QStringList l = lines(QString::fromUtf8(all));
        QVERIFY(l.size() >= 3);
        QString why;
        for (const QString& line : l) QVERIFY2(isCandumpL(line, QStringLiteral("sim"), &why), qPrintable(why));
    }
    // A server that drops the connection is a lost adapter (issue 16): record keeps what it has,
    // says so, and goes on waiting for the bus to come back until it is stopped.
    void recordKeepsFramesWhenTheBusDies() {
        FakeSocketcandServer server;
        QVERIFY(server.listen());
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("dies.log"));
        QProcess p;
        p.start(QStringLiteral(COSCOPE_CLI_PATH), {QStringLiteral("record"), server.url(), out});
        QTRY_VERIFY_WITH_TIMEOUT(server.handshakeDone, 5000);
        QTest::qWait(100);
        server.write(
            "< frame 181 1700000000.000001 0102 >< frame 12345678 1700000000.000002 >< frame 701 1700000000.000003 05 "
            ">");
        server.closeClient();
        QString err;
        QTRY_VERIFY_WITH_TIMEOUT((err += QString::fromUtf8(p.readAllStandardError()))
                                     .contains(QStringLiteral("coscope-cli record: bus lost")),
                                 5000);
        QVERIFY2(err.contains(QStringLiteral("retrying")), qPrintable(err));
        QCOMPARE(p.state(), QProcess::Running);
        const QString expected = QStringLiteral(
            "(1700000000.000001) can0 181#0102\n(1700000000.000002) can0 12345678#\n(1700000000.000003) can0 701#05\n");
        auto written = [&] {
            QFile f(out);
            return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
        };
        QTRY_COMPARE_WITH_TIMEOUT(written(), expected, 3000);  // on disk while it waits
        p.terminate();
        QVERIFY(p.waitForFinished(5000));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), 0);
        QCOMPARE(written(), expected);
    }
};

QTEST_GUILESS_MAIN(TestCliBus)
#include "test_cli_bus.moc"
