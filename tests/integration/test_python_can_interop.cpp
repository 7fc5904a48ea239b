// SPDX-License-Identifier: GPL-3.0-or-later
// python-can (Debian python3-can) talks to `coscope-cli sim` through its socketcand interface:
// it reads 1018h with raw SDO frames and receives TPDOs.
#include "tests/PythonCan.h"
#include "tests/integration/SimSocketcand.h"

#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const char* kScript = R"PY(
import sys, time, can
host, port = sys.argv[1], int(sys.argv[2])
bus = can.Bus(interface='socketcand', host=host, port=port, channel='can0')

def sdo_read(node, index, sub):
    bus.send(can.Message(arbitration_id=0x600 + node, is_extended_id=False,
                         data=[0x40, index & 0xFF, index >> 8, sub, 0, 0, 0, 0]))
    end = time.time() + 2.0
    while time.time() < end:
        m = bus.recv(0.1)
        if m is not None and m.arbitration_id == 0x580 + node:
            d = m.data
            if d[0] & 0xE0 == 0x80:
                return 'abort 0x%08X' % int.from_bytes(d[4:8], 'little')
            if d[0] & 0x02:  # expedited
                n = 4 - ((d[0] >> 2) & 3) if d[0] & 0x01 else 4
                return '0x%08X' % int.from_bytes(d[4:4 + n], 'little')
            return 'segmented'
    return 'timeout'

for node in (1, 2, 3):
    print('IDENTITY %d vendor %s product %s' % (node, sdo_read(node, 0x1018, 1), sdo_read(node, 0x1018, 2)), flush=True)

bus.send(can.Message(arbitration_id=0x000, is_extended_id=False, data=[0x01, 0x00]))  # NMT start all
counts = {}
end = time.time() + 1.5
next_sync = 0.0
while time.time() < end:
    if time.time() >= next_sync:
        bus.send(can.Message(arbitration_id=0x080, is_extended_id=False, data=[]))
        next_sync = time.time() + 0.02
    m = bus.recv(0.01)
    if m is not None and 0x180 <= m.arbitration_id < 0x580 and (m.arbitration_id & 0x7F) in (1, 2, 3):
        key = '0x%03X' % m.arbitration_id
        counts[key] = counts.get(key, 0) + 1
for k in sorted(counts):
    print('TPDO %s %d' % (k, counts[k]), flush=True)
bus.shutdown()
print('DONE', flush=True)
)PY";

}  // namespace

class TestPythonCanInterop : public QObject {
    Q_OBJECT
private slots:
    void pythonCanReadsIdentityAndTpdos() {
        const QString py = pythonWithCan();
        if (py.isEmpty()) QSKIP("python3-can is not installed (Debian package python3-can)");

        QProcess sim;
        QString simError;
        const QString port = startSimSocketcand(sim, QString(), &simError);
        QVERIFY2(!port.isEmpty(), qPrintable(simError));

        QTemporaryDir dir;
        QFile script(dir.filePath(QStringLiteral("interop.py")));
        QVERIFY(script.open(QIODevice::WriteOnly));
        script.write(kScript);
        script.close();

        QProcess client;
        client.start(py, {script.fileName(), QStringLiteral("127.0.0.1"), port});
        QVERIFY(client.waitForFinished(60000));
        const QString out = QString::fromUtf8(client.readAllStandardOutput());
        const QString err = QString::fromUtf8(client.readAllStandardError());
        sim.terminate();
        sim.waitForFinished(5000);
        QVERIFY2(client.exitCode() == 0, qPrintable(out + err));
        QVERIFY2(out.contains(QStringLiteral("DONE")), qPrintable(out + err));
        // 1018h from the bundled dictionaries: Delta vendor 000001DDh product 00006000h
        // (extract-delta §9); generic CiA 402 product 00000402h.
        QVERIFY2(out.contains(QStringLiteral("IDENTITY 1 vendor 0x000001DD product 0x00006000")), qPrintable(out));
        QVERIFY2(QRegularExpression(QStringLiteral("IDENTITY 2 vendor 0x[0-9A-F]{8} product 0x[0-9A-F]{8}"))
                     .match(out)
                     .hasMatch(),
                 qPrintable(out));
        QVERIFY2(out.contains(QStringLiteral("IDENTITY 3 vendor 0x00000000 product 0x00000402")), qPrintable(out));
        // AIMOTOR (node 2) sends TPDO1/TPDO2 on every SYNC (type 1): about 75 SYNCs in 1.5 s.
        const auto tp = QRegularExpression(QStringLiteral("TPDO 0x182 (\\d+)")).match(out);
        QVERIFY2(tp.hasMatch() && tp.captured(1).toInt() >= 20, qPrintable(out));
        QVERIFY2(out.contains(QStringLiteral("TPDO 0x282")), qPrintable(out));
    }
};

QTEST_GUILESS_MAIN(TestPythonCanInterop)
#include "test_python_can_interop.moc"
