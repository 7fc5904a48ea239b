// SPDX-License-Identifier: GPL-3.0-or-later
// A third-party master written with python-can (Debian python3-can) homes the virtual drives of
// `coscope-cli sim` over socketcand and makes a profile position move, the way a PLC's CiA 402
// function blocks do it over SDO: the AIMOTOR manual's homing sequence with method 35
// (extract-aimotor §4.6 C: 6060h = 6, 6098h, 6040h 06 07 0F 1F, statusword bit 12 and bit 15,
// position cleared to zero), a switch method on the generic drive (6098h = 17, CiA 402-2 §13:
// out to the negative limit switch and back), and PP moves with the set-point handshake
// (CiA 402-2 §12.2: bit 4 rising, wait for bit 12, bit 4 low, wait for bit 10).
#include "tests/PythonCan.h"
#include "tests/integration/SimSocketcand.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const char* kPlc = R"PY(
import sys, time, can
host, port = sys.argv[1], int(sys.argv[2])
bus = can.Bus(interface='socketcand', host=host, port=port, channel='can0')

def sdo(node, req, index, sub, data=b''):
    bus.send(can.Message(arbitration_id=0x600 + node, is_extended_id=False,
                         data=bytes([req, index & 0xFF, index >> 8, sub]) + bytes(data).ljust(4, b'\0')))
    end = time.time() + 1.0
    while time.time() < end:
        m = bus.recv(0.05)
        if m is not None and m.arbitration_id == 0x580 + node and m.data[1] | m.data[2] << 8 == index:
            return m.data[0], bytes(m.data[4:8])
    raise SystemExit('no SDO answer from node %d for %04X' % (node, index))

def read(node, index, sub=0, signed=False):
    scs, data = sdo(node, 0x40, index, sub)
    if scs == 0x80:
        raise SystemExit('read %04X refused by node %d' % (index, node))
    size = 4 - ((scs >> 2) & 3) if scs & 1 else 4
    return int.from_bytes(data[:size], 'little', signed=signed)

def write(node, index, sub, value, size):
    scs, data = sdo(node, 0x23 | ((4 - size) << 2), index, sub, (value & ((1 << (8 * size)) - 1)).to_bytes(size, 'little'))
    if scs != 0x60:
        raise SystemExit('write %04X:%02X = %d refused by node %d: %s' % (index, sub, value, node, data.hex()))

def cw(node, value):
    write(node, 0x6040, 0, value, 2)

def wait(node, mask, value, seconds, watch=None):
    end = time.time() + seconds
    while time.time() < end:
        sw = read(node, 0x6041)
        if watch:
            watch()
        if sw & mask == value:
            return sw
        time.sleep(0.005)
    raise SystemExit('node %d: statusword %04X, wanted bits %04X = %04X' % (node, read(node, 0x6041), mask, value))

def enable(node):
    for c in (0x06, 0x07, 0x0F):
        cw(node, c)
    wait(node, 0x6F, 0x27, 1.0)

# AIMOTOR (node 2): the manual's homing sequence, method 35 after a move away from zero.
write(2, 0x6060, 0, 1, 1)
write(2, 0x6081, 0, 5000, 4)
write(2, 0x607A, 0, 700, 4)
enable(2)
cw(2, 0x1F)
wait(2, 0x0400, 0x0400, 5.0)
cw(2, 0x00)
write(2, 0x6060, 0, 6, 1)
write(2, 0x6098, 0, 35, 1)
cw(2, 0x06); cw(2, 0x07); cw(2, 0x0F); cw(2, 0x1F)
sw = wait(2, 0x1000, 0x1000, 2.0)
print('HOMED 2 method 35 sw=%04X pos=%d' % (sw, read(2, 0x6064, signed=True)), flush=True)
cw(2, 0x0F)
cw(2, 0x00)

# Generic drive (node 3): method 17, negative limit switch without index pulse.
write(3, 0x6060, 0, 6, 1)
write(3, 0x6098, 0, 17, 1)
write(3, 0x6099, 1, 50000, 4)
write(3, 0x6099, 2, 10000, 4)
write(3, 0x609A, 0, 500000, 4)
enable(3)
cw(3, 0x1F)
lowest = [0]
def track():
    lowest[0] = min(lowest[0], read(3, 0x6064, signed=True))
sw = wait(3, 0x3000, 0x1000, 10.0, track)
print('HOMED 3 method 17 lowest=%d pos=%d sw=%04X' % (lowest[0], read(3, 0x6064, signed=True), sw), flush=True)
cw(3, 0x0F)

# Profile position with the set-point handshake, absolute then relative.
write(3, 0x6060, 0, 1, 1)
write(3, 0x6081, 0, 5000, 4)
for target, bits in ((1000, 0x00), (500, 0x40)):
    write(3, 0x607A, 0, target, 4)
    cw(3, 0x0F | bits)
    cw(3, 0x1F | bits)
    wait(3, 0x1000, 0x1000, 1.0)      # set-point acknowledge
    cw(3, 0x0F | bits)
    wait(3, 0x1000, 0x0000, 1.0)      # acknowledge drops with bit 4
    sw = wait(3, 0x0400, 0x0400, 5.0) # target reached
    print('MOVED 3 %s %d pos=%d sw=%04X' % ('relative' if bits else 'absolute', target, read(3, 0x6064, signed=True), sw), flush=True)
cw(3, 0x00)
bus.shutdown()
print('DONE', flush=True)
)PY";

}  // namespace

class TestPythonCanHoming : public QObject {
    Q_OBJECT
private slots:
    void plcHomesAndMovesTheVirtualDrives() {
        const QString py = pythonWithCan();
        if (py.isEmpty()) QSKIP("python3-can is not installed (Debian package python3-can)");

        QProcess sim;
        QString simError;
        const QString port = startSimSocketcand(sim, QString(), &simError);
        QVERIFY2(!port.isEmpty(), qPrintable(simError));

        QTemporaryDir dir;
        QFile script(dir.filePath(QStringLiteral("plc_homing.py")));
        QVERIFY(script.open(QIODevice::WriteOnly));
        script.write(kPlc);
        script.close();

        // Default virtual network: 1 Delta ASDA-A2, 2 AIMOTOR, 3 generic CiA 402.
        QProcess plc;
        plc.start(py, {script.fileName(), QStringLiteral("127.0.0.1"), port});
        QVERIFY(plc.waitForFinished(120000));
        const QString out = QString::fromUtf8(plc.readAllStandardOutput());
        const QString err = QString::fromUtf8(plc.readAllStandardError());
        sim.terminate();
        sim.waitForFinished(5000);
        QVERIFY2(plc.exitCode() == 0 && out.contains(QStringLiteral("DONE")), qPrintable(out + err));
        // AIMOTOR: operation enabled + target reached + homing attained + home found (9637h),
        // the position cleared to zero.
        QVERIFY2(out.contains(QStringLiteral("HOMED 2 method 35 sw=9637 pos=0")), qPrintable(out));
        // Generic: out to the negative limit switch (-1 rev = -10000 inc) and home there.
        const auto h =
            QRegularExpression(QStringLiteral("HOMED 3 method 17 lowest=(-?\\d+) pos=0 sw=(\\w+)")).match(out);
        QVERIFY2(h.hasMatch(), qPrintable(out));
        QVERIFY2(h.captured(1).toInt() <= -9000, qPrintable(out));
        QVERIFY2(out.contains(QStringLiteral("MOVED 3 absolute 1000 pos=1000")), qPrintable(out));
        QVERIFY2(out.contains(QStringLiteral("MOVED 3 relative 500 pos=1500")), qPrintable(out));
    }
};

QTEST_GUILESS_MAIN(TestPythonCanHoming)
#include "test_python_can_homing.moc"
