// SPDX-License-Identifier: GPL-3.0-or-later
// A third-party master programs a virtual drive: a python-can (Debian python3-can) script on the
// socketcand server of `coscope-cli sim` runs the CiA 302-3 sequence with its own SDO code, as
// CoScope's ProgramDownload does: 1F51h:01 = 0 stop program, 1F51h:01 = 3 clear, 1F50h:01 by
// segmented download (CiA 301 §7.2.4.3.4-7) of an image it builds with the README's recipe
// (struct + zlib), 1F51h:01 = 1 start program, the boot-up 700h + node-ID, then 100Ah and 1F56h
// read back. The drive must report the image's version and its payload's CRC-32.
#include "tests/PythonCan.h"
#include "tests/integration/SimSocketcand.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const char* kMaster = R"PY(
import sys, struct, zlib, time, can
host, port, node, size = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
bus = can.Bus(interface='socketcand', host=host, port=port, channel='can0')
REQ, RESP, BOOT = 0x600 + node, 0x580 + node, 0x700 + node

def send(data):
    bus.send(can.Message(arbitration_id=REQ, data=bytes(data).ljust(8, b'\0'), is_extended_id=False))

def wait(ids, timeout=3.0):
    end = time.time() + timeout
    while time.time() < end:
        m = bus.recv(0.1)
        if m is not None and m.arbitration_id in ids and not m.is_remote_frame:
            return m
    sys.exit('TIMEOUT waiting for %s' % [hex(i) for i in ids])

def check(m, cs, what):
    d = bytes(m.data)
    if d[0] == 0x80:
        sys.exit('ABORT %s %08X' % (what, struct.unpack_from('<I', d, 4)[0]))
    if d[0] != cs:
        sys.exit('UNEXPECTED %s %s' % (what, d.hex()))

def write_u8(index, sub, value, what):
    send(struct.pack('<BHBB', 0x2F, index, sub, value))      # expedited, 1 byte
    check(wait([RESP]), 0x60, what)

def download(index, sub, data):
    send(struct.pack('<BHBI', 0x21, index, sub, len(data)))  # initiate, size indicated
    check(wait([RESP]), 0x60, 'initiate 1F50h')
    toggle = 0
    for off in range(0, len(data), 7):
        chunk = data[off:off + 7]
        last = off + 7 >= len(data)
        send(bytes([(toggle << 4) | ((7 - len(chunk)) << 1) | int(last)]) + chunk)
        check(wait([RESP]), 0x20 | (toggle << 4), 'segment at %d' % off)
        toggle ^= 1

def upload(index, sub):
    send(struct.pack('<BHB', 0x40, index, sub))
    d = bytes(wait([RESP]).data)
    if d[0] == 0x80:
        sys.exit('ABORT read %04X %08X' % (index, struct.unpack_from('<I', d, 4)[0]))
    if d[0] & 0x02:                                          # expedited
        return d[4:8 - ((d[0] >> 2) & 3)] if d[0] & 1 else d[4:8]
    out, toggle = b'', 0
    while True:
        send([0x60 | (toggle << 4)])
        d = bytes(wait([RESP]).data)
        if d[0] == 0x80:
            sys.exit('ABORT segment %04X' % index)
        out += d[1:8 - ((d[0] >> 1) & 7)]
        if d[0] & 1:
            return out
        toggle ^= 1

print('BEFORE', upload(0x100A, 0).decode(), flush=True)
payload = bytes((i * 7 + (i >> 8)) & 0xFF for i in range(size))
image = b'CSPI' + struct.pack('<II16sI', len(payload), zlib.crc32(payload), b'3.1.4-py', 0) + payload
write_u8(0x1F51, 1, 0, 'stop program')
write_u8(0x1F51, 1, 3, 'clear program')
t0 = time.time()
download(0x1F50, 1, image)
print('DOWNLOADED %d bytes in %.2f s' % (len(image), time.time() - t0), flush=True)
send(struct.pack('<BHBB', 0x2F, 0x1F51, 1, 1))               # start program
answered = booted = False
while not (answered and booted):
    m = wait([RESP, BOOT], 5.0)
    if m.arbitration_id == RESP:
        check(m, 0x60, 'start program')
        answered = True
    elif bytes(m.data) == b'\x00':
        booted = True
print('BOOTUP', flush=True)
print('VERSION', upload(0x100A, 0).decode(), flush=True)
print('SWID %08X CRC %08X' % (struct.unpack('<I', upload(0x1F56, 1))[0], zlib.crc32(payload)), flush=True)
bus.shutdown()
)PY";

}  // namespace

class TestPythonCanProgram : public QObject {
    Q_OBJECT
private slots:
    void thirdPartyMasterProgramsTheVirtualDrive() {
        const QString py = pythonWithCan();
        if (py.isEmpty()) QSKIP("python3-can is not installed (Debian package python3-can)");
        QProcess sim;
        QString error;
        const QString port = startSimSocketcand(sim, QStringLiteral("5:delta-asda-a2"), &error);
        QVERIFY2(!port.isEmpty(), qPrintable(error));
        QTemporaryDir dir;
        QFile script(dir.filePath(QStringLiteral("master.py")));
        QVERIFY(script.open(QIODevice::WriteOnly));
        script.write(kMaster);
        script.close();
        QProcess master;
        master.start(
            py, {script.fileName(), QStringLiteral("127.0.0.1"), port, QStringLiteral("5"), QStringLiteral("4000")});
        QVERIFY(master.waitForFinished(60000));
        const QString out = QString::fromUtf8(master.readAllStandardOutput());
        const QString err = QString::fromUtf8(master.readAllStandardError());
        sim.terminate();
        sim.waitForFinished(5000);
        qInfo("%s", qPrintable(out.trimmed()));
        QVERIFY2(master.exitCode() == 0, qPrintable(out + err));
        QVERIFY2(out.contains(QStringLiteral("BEFORE 1.0")), qPrintable(out));
        QVERIFY2(out.contains(QStringLiteral("BOOTUP")), qPrintable(out));
        QVERIFY2(out.contains(QStringLiteral("VERSION 3.1.4-py")), qPrintable(out));
        const auto m = QRegularExpression(QStringLiteral("SWID ([0-9A-F]{8}) CRC ([0-9A-F]{8})")).match(out);
        QVERIFY2(m.hasMatch(), qPrintable(out));
        QCOMPARE(m.captured(1), m.captured(2));
    }
};

QTEST_GUILESS_MAIN(TestPythonCanProgram)
#include "test_python_can_program.moc"
