// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 35, "when CoScope dies, nothing can be sent": `coscope-cli ds402 jog ... --watchdog`
// turns a virtual drive (served by `coscope-cli sim` over socketcand) and is killed with
// SIGKILL mid-move. A third-party observer (python-can on the same socketcand server) sees
// CoScope's heartbeat (77Fh) stop, the drive's EMCY 8130h (CiA 301 Table 21) about 3 heartbeat
// periods later, and, by SDO, the statusword 6041h leave Operation enabled and the velocity
// 606Ch go to 0 within 2 s: generic CiA 402 drive by 6007h = 3 (quick stop), Delta ASDA-A2 by
// its alarm AL170 (extract-delta §6.3).
#include "tests/PythonCan.h"

#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

namespace {

// Watches the bus; after a line on stdin (the kill) polls 6041h and 606Ch by SDO every 20 ms for
// 2.5 s. Times are ms since that line.
const char* kObserver = R"PY(
import sys, time, threading, can
host, port, node = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
bus = can.Bus(interface='socketcand', host=host, port=port, channel='can0')
killed = [None]
def wait_kill():
    sys.stdin.readline()
    killed[0] = time.time()
threading.Thread(target=wait_kill, daemon=True).start()
print('READY', flush=True)
last_hb, emcy, samples = None, [], []
order, step, pending, sent_at, sw = (0x6041, 0x606C), 0, None, 0.0, None
while killed[0] is None or time.time() < killed[0] + 2.5:
    now = time.time()
    if killed[0] is not None and (now - sent_at > (0.5 if pending else 0.02)):
        pending = order[step % 2]
        step += 1
        bus.send(can.Message(arbitration_id=0x600 + node, is_extended_id=False, data=bytes([0x40, pending & 0xFF, pending >> 8, 0, 0, 0, 0, 0])))
        sent_at = now
    m = bus.recv(0.005)
    if m is None:
        continue
    t = time.time()
    if m.arbitration_id == 0x77F:
        last_hb = t
    elif m.arbitration_id == 0x80 + node and len(m.data) == 8:
        emcy.append((t, m.data[0] | m.data[1] << 8, m.data[3] | m.data[4] << 8))
    elif m.arbitration_id == 0x580 + node and pending and (m.data[1] | m.data[2] << 8) == pending:
        if m.data[0] & 0xE0 == 0x40:
            raw = int.from_bytes(bytes(m.data[4:8]), 'little')
            if pending == 0x6041:
                sw = raw & 0xFFFF
            elif sw is not None:
                samples.append((t, sw, raw - (1 << 32) if raw & 0x80000000 else raw))
        pending = None
k = killed[0]
ms = lambda t: int(round((t - k) * 1000))
print('LAST_HB %d' % (ms(last_hb) if last_hb else -99999), flush=True)
for t, code, vendor in emcy:
    print('EMCY %04X %04X %d' % (code, vendor, ms(t)), flush=True)
left = [t for t, sw, v in samples if sw & 0x6F != 0x27]
stopped = [t for t, sw, v in samples if sw & 0x6F != 0x27 and v == 0]
print('SAMPLES %d' % len(samples), flush=True)
if samples:
    print('FIRST %04X %d' % (samples[0][1], samples[0][2]), flush=True)
    print('FINAL %04X %d' % (samples[-1][1], samples[-1][2]), flush=True)
if left:
    print('LEFT_ENABLED %d' % ms(left[0]), flush=True)
if stopped:
    print('STOPPED %d' % ms(stopped[0]), flush=True)
bus.shutdown()
)PY";

int field(const QString& out, const QString& key) {
    const auto m =
        QRegularExpression(QStringLiteral("^%1 (-?\\d+)$").arg(key), QRegularExpression::MultilineOption).match(out);
    return m.hasMatch() ? m.captured(1).toInt() : INT_MIN;
}

bool readUntil(QProcess& p, QString* text, const QString& needle, int ms) {
    QElapsedTimer t;
    t.start();
    while (!text->contains(needle) && t.elapsed() < ms) {
        p.waitForReadyRead(100);
        *text += QString::fromUtf8(p.readAllStandardOutput());
        if (p.state() != QProcess::Running) {
            *text += QString::fromUtf8(p.readAllStandardOutput());
            break;
        }
    }
    return text->contains(needle);
}

}  // namespace

class TestHeartbeatGuardSigkill : public QObject {
    Q_OBJECT
private slots:
    void driveStopsWhenTheCliIsKilled_data() {
        QTest::addColumn<QString>("nodes");
        QTest::addColumn<int>("node");
        QTest::addColumn<int>("velocity");
        QTest::addColumn<int>("vendorAlarm");
        QTest::newRow("generic CiA 402, 6007h quick stop") << QStringLiteral("3:generic-cia402") << 3 << 5000 << 0;
        QTest::newRow("Delta ASDA-A2, AL170") << QStringLiteral("1:delta-asda-a2") << 1 << 300 << 0x0170;
    }
    void driveStopsWhenTheCliIsKilled() {
        QFETCH(QString, nodes);
        QFETCH(int, node);
        QFETCH(int, velocity);
        QFETCH(int, vendorAlarm);
        const QString py = pythonWithCan();
        if (py.isEmpty()) QSKIP("python3-can is not installed (Debian package python3-can)");

        QProcess sim;
        sim.start(QStringLiteral(COSCOPE_CLI_PATH),
                  {QStringLiteral("sim"), QStringLiteral("--nodes"), nodes, QStringLiteral("--listen"),
                   QStringLiteral("socketcand://127.0.0.1:0")});
        QVERIFY2(sim.waitForStarted(5000), qPrintable(sim.errorString()));
        QString banner;
        QVERIFY2(readUntil(sim, &banner, QStringLiteral("\n"), 15000),
                 qPrintable(banner + QString::fromUtf8(sim.readAllStandardError())));
        const auto m = QRegularExpression(QStringLiteral("socketcand://127\\.0\\.0\\.1:(\\d+)/")).match(banner);
        QVERIFY2(m.hasMatch(), qPrintable(banner));
        const QString port = m.captured(1);

        QTemporaryDir dir;
        QFile script(dir.filePath(QStringLiteral("observer.py")));
        QVERIFY(script.open(QIODevice::WriteOnly));
        script.write(kObserver);
        script.close();
        QProcess observer;
        observer.start(py, {script.fileName(), QStringLiteral("127.0.0.1"), port, QString::number(node)});
        QString seen;
        QVERIFY2(readUntil(observer, &seen, QStringLiteral("READY"), 20000),
                 qPrintable(seen + QString::fromUtf8(observer.readAllStandardError())));

        QProcess jog;
        jog.start(QStringLiteral(COSCOPE_CLI_PATH),
                  {QStringLiteral("ds402"), QStringLiteral("jog"),
                   QStringLiteral("socketcand://127.0.0.1:%1/can0").arg(port), QString::number(node),
                   QString::number(velocity), QStringLiteral("--for"), QStringLiteral("20000"), QStringLiteral("--yes"),
                   QStringLiteral("--watchdog"), QStringLiteral("--heartbeat-ms"), QStringLiteral("100")});
        QString jogOut;
        QVERIFY2(readUntil(jog, &jogOut, QStringLiteral("operation enabled"), 15000),
                 qPrintable(jogOut + QString::fromUtf8(jog.readAllStandardError())));
        QVERIFY2(jogOut.contains(QStringLiteral("1016h:01 = 0x007F012C")), qPrintable(jogOut));
        QVERIFY2(jogOut.contains(QStringLiteral("watchdog: node %1 watches CoScope's heartbeat (node 127)").arg(node)),
                 qPrintable(jogOut));
        QTest::qWait(800);  // turning
        QCOMPARE(jog.state(), QProcess::Running);
        jog.kill();  // SIGKILL: nothing more comes from coscope-cli
        observer.write("killed\n");
        QVERIFY(jog.waitForFinished(5000));
        QCOMPARE(jog.exitStatus(), QProcess::CrashExit);

        QVERIFY(observer.waitForFinished(15000));
        const QString out = seen + QString::fromUtf8(observer.readAllStandardOutput());
        const QString err = QString::fromUtf8(observer.readAllStandardError());
        sim.terminate();
        sim.waitForFinished(5000);
        QVERIFY2(observer.exitCode() == 0, qPrintable(out + err));
        // CoScope's heartbeat ran until the kill.
        const int lastHb = field(out, QStringLiteral("LAST_HB"));
        QVERIFY2(lastHb > -300 && lastHb <= 50, qPrintable(out));
        // Right after the kill the drive still turns: it waits for its consumer time.
        QVERIFY2(field(out, QStringLiteral("SAMPLES")) > 10, qPrintable(out));
        const auto first =
            QRegularExpression(QStringLiteral("^FIRST ([0-9A-F]{4}) (-?\\d+)$"), QRegularExpression::MultilineOption)
                .match(out);
        QVERIFY2(
            first.hasMatch() && (first.captured(1).toUInt(nullptr, 16) & 0x6F) == 0x27 && first.captured(2).toInt() > 0,
            qPrintable(out));
        // EMCY 8130h about 300 ms after the last heartbeat (consumer time 3 x 100 ms).
        const auto e = QRegularExpression(QStringLiteral("^EMCY 8130 ([0-9A-F]{4}) (-?\\d+)$"),
                                          QRegularExpression::MultilineOption)
                           .match(out);
        QVERIFY2(e.hasMatch(), qPrintable(out));
        QCOMPARE(e.captured(1).toInt(nullptr, 16), vendorAlarm);
        const int emcyAfterHb = e.captured(2).toInt() - lastHb;
        QVERIFY2(emcyAfterHb >= 250 && emcyAfterHb < 1000, qPrintable(out));
        // Out of Operation enabled and standing still within 2 s of the kill.
        const int left = field(out, QStringLiteral("LEFT_ENABLED"));
        const int stopped = field(out, QStringLiteral("STOPPED"));
        QVERIFY2(left != INT_MIN && left < 2000, qPrintable(out));
        QVERIFY2(stopped != INT_MIN && stopped < 2000, qPrintable(out));
        const auto fin =
            QRegularExpression(QStringLiteral("^FINAL ([0-9A-F]{4}) (-?\\d+)$"), QRegularExpression::MultilineOption)
                .match(out);
        QVERIFY2(fin.hasMatch(), qPrintable(out));
        QVERIFY2((fin.captured(1).toUInt(nullptr, 16) & 0x6F) != 0x27 && fin.captured(2).toInt() == 0, qPrintable(out));
    }
};

QTEST_GUILESS_MAIN(TestHeartbeatGuardSigkill)
#include "test_heartbeat_guard_sigkill.moc"
