// SPDX-License-Identifier: GPL-3.0-or-later
// A third party's view of CoScope as the bus's master: a python-can (Debian python3-can) script
// on the socketcand server of `coscope-cli sim` records the SYNC that `coscope-cli sync ...
// --period 10ms --duration 3` produces and the frame `coscope-cli send ... --every 10ms
// --duration 3` repeats (both at once, as two masters would), with the timestamps the server
// gives each frame, and reports their mean period and p99 jitter. The mean must be within 2 % of
// 10 ms; the p99 bound (6 ms) is loose for a loaded CI host, yet frames sent in pairs or skipped
// exceed it (10 ms). DESIGN.md's 1 ms budget on an idle machine is for
// tests/bench/bench_master_jitter.
#include "tests/PythonCan.h"
#include "tests/integration/SimSocketcand.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const char* kObserver = R"PY(
import sys, time, can
host, port, seconds = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
ids = [int(x, 16) for x in sys.argv[4].split(',')]
period = 0.010
bus = can.Bus(interface='socketcand', host=host, port=port, channel='can0')
print('READY', flush=True)
stamps = {i: [] for i in ids}
first = {i: None for i in ids}
end = time.time() + seconds
while time.time() < end:
    m = bus.recv(0.05)
    if m is None or m.arbitration_id not in stamps:
        continue
    if first[m.arbitration_id] is None:
        first[m.arbitration_id] = bytes(m.data).hex()
    stamps[m.arbitration_id].append(m.timestamp)
bus.shutdown()
for i in ids:
    t = stamps[i]
    if len(t) < 3:
        print('ID %03X n %d' % (i, len(t)), flush=True)
        continue
    gaps = [b - a for a, b in zip(t, t[1:])]
    jitter = sorted(abs(g - period) for g in gaps)
    p99 = jitter[min(len(jitter) - 1, int(round(0.99 * (len(jitter) - 1))))]
    mean = (t[-1] - t[0]) / (len(t) - 1)
    print('ID %03X n %d mean_ms %.4f p99_jitter_ms %.4f max_jitter_ms %.4f first %s'
          % (i, len(t), mean * 1e3, p99 * 1e3, jitter[-1] * 1e3, first[i]), flush=True)
)PY";

struct Figures {
    int n = 0;
    double meanMs = 0, p99Ms = 0, maxMs = 0;
    QString first;
};

Figures figuresFor(const QString& out, const QString& id) {
    const auto m =
        QRegularExpression(
            QStringLiteral(
                "ID %1 n (\\d+) mean_ms ([0-9.]+) p99_jitter_ms ([0-9.]+) max_jitter_ms ([0-9.]+) first (\\S*)")
                .arg(id))
            .match(out);
    if (!m.hasMatch()) return {};
    return {m.captured(1).toInt(), m.captured(2).toDouble(), m.captured(3).toDouble(), m.captured(4).toDouble(),
            m.captured(5)};
}

}  // namespace

class TestPythonCanMaster : public QObject {
    Q_OBJECT
private slots:
    void thirdPartySeesSyncAndPeriodicFrameAtTheirPeriod() {
        const QString py = pythonWithCan();
        if (py.isEmpty()) QSKIP("python3-can is not installed (Debian package python3-can)");

        // A small virtual network: one drive, pre-operational (no PDOs on our SYNC).
        QProcess sim;
        QString simError;
        const QString port = startSimSocketcand(sim, QStringLiteral("3:generic-cia402"), &simError);
        QVERIFY2(!port.isEmpty(), qPrintable(simError));
        const QString url = QStringLiteral("socketcand://127.0.0.1:%1/can0").arg(port);

        QTemporaryDir dir;
        QFile script(dir.filePath(QStringLiteral("observer.py")));
        QVERIFY(script.open(QIODevice::WriteOnly));
        script.write(kObserver);
        script.close();
        QProcess observer;
        QString seen;
        QVERIFY2(
            startPythonPeer(observer, py, script.fileName(),
                            {QStringLiteral("127.0.0.1"), port, QStringLiteral("6"), QStringLiteral("080,321")}, &seen),
            qPrintable(seen));

        // Two masters at once, each ending by itself after 3 s.
        QProcess sync, send;
        sync.start(
            QStringLiteral(COSCOPE_CLI_PATH),
            {QStringLiteral("sync"), url, QStringLiteral("--period"), QStringLiteral("10ms"),
             QStringLiteral("--counter"), QStringLiteral("240"), QStringLiteral("--duration"), QStringLiteral("3")});
        send.start(QStringLiteral(COSCOPE_CLI_PATH),
                   {QStringLiteral("send"), url, QStringLiteral("321#DEADBEEF"), QStringLiteral("--every"),
                    QStringLiteral("10ms"), QStringLiteral("--duration"), QStringLiteral("3")});
        QVERIFY(sync.waitForFinished(20000));
        QVERIFY(send.waitForFinished(20000));
        const QString syncOut = QString::fromUtf8(sync.readAllStandardOutput());
        const QString sendOut = QString::fromUtf8(send.readAllStandardOutput());
        QVERIFY2(sync.exitCode() == 0, qPrintable(QString::fromUtf8(sync.readAllStandardError())));
        QVERIFY2(send.exitCode() == 0, qPrintable(QString::fromUtf8(send.readAllStandardError())));
        QVERIFY(observer.waitForFinished(30000));
        seen += QString::fromUtf8(observer.readAllStandardOutput());
        const QString err = QString::fromUtf8(observer.readAllStandardError());
        sim.terminate();
        sim.waitForFinished(5000);
        QVERIFY2(observer.exitCode() == 0, qPrintable(err));
        qInfo("coscope-cli sync: %s", qPrintable(syncOut.trimmed()));
        qInfo("coscope-cli send: %s", qPrintable(sendOut.trimmed()));

        // How many went out, as each verb says: about 300 in 3 s.
        const auto count = [](const QString& out) {
            return QRegularExpression(QStringLiteral("^(\\d+) ")).match(out).captured(1).toInt();
        };
        QVERIFY2(count(syncOut) >= 280 && count(syncOut) <= 302, qPrintable(syncOut));
        QVERIFY2(count(sendOut) >= 280 && count(sendOut) <= 302, qPrintable(sendOut));

        for (const auto& [id, what] :
             {std::pair{QStringLiteral("080"), "SYNC"}, std::pair{QStringLiteral("321"), "321#DEADBEEF"}}) {
            const Figures f = figuresFor(seen, id);
            qInfo("python-can saw %s: %d frames, mean period %.3f ms, p99 jitter %.3f ms, max %.3f ms", what, f.n,
                  f.meanMs, f.p99Ms, f.maxMs);
            QVERIFY2(f.n >= 250, qPrintable(seen));
            QVERIFY2(std::abs(f.meanMs - 10.0) <= 0.2, qPrintable(seen));  // within 2 %
            QVERIFY2(f.p99Ms <= 6.0, qPrintable(seen));  // bunched (Nagle) or skipped frames give 10 ms
        }
        // The SYNC counter starts at 1 (CiA 301 §7.2.5.2.1); the frame is sent as typed.
        QCOMPARE(figuresFor(seen, QStringLiteral("080")).first, QStringLiteral("01"));
        QCOMPARE(figuresFor(seen, QStringLiteral("321")).first, QStringLiteral("deadbeef"));
    }
};

QTEST_GUILESS_MAIN(TestPythonCanMaster)
#include "test_python_can_master.moc"
