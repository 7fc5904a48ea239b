// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli as the master of a device from another stack that no dictionary describes: a
// minimal SDO server written with python-can (Debian python3-can) as node 42 on the bus that
// `coscope-cli sim` serves over socketcand. `sdo read`, `sdo write` and `pdo show` know the CiA
// 301 communication objects and the CiA 402 objects by name and type without a dictionary
// (expectations from CiA 301 7.5.2 and CiA 402-2, not from CoScope's output); a device's own
// EDS still wins where it differs (AIMOTOR's 1017h is UNSIGNED32 in its bundled EDS).
#include "tests/CliRun.h"
#include "tests/PythonCan.h"
#include "tests/integration/SimSocketcand.h"

#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

namespace {

// A CiA 301 SDO server (expedited and segmented, 7.2.4.3) with raw bytes per object and no
// notion of types, like a small slave stack; every download is printed as it arrived.
const char* kServer = R"PY(
import sys, time, can
host, port, node = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
bus = can.Bus(interface='socketcand', host=host, port=port, channel='can0')
u8 = lambda v: v.to_bytes(1, 'little')
u16 = lambda v: v.to_bytes(2, 'little')
u32 = lambda v: v.to_bytes(4, 'little')
od = {
    (0x1000, 0): u32(0x00020192),
    (0x1001, 0): u8(0),
    (0x1008, 0): b'Peer drive 42',
    (0x1017, 0): u16(0),
    (0x1018, 0): u8(4), (0x1018, 1): u32(0x12345678), (0x1018, 2): u32(0x0000ABCD),
    (0x1018, 3): u32(0x00010002), (0x1018, 4): u32(42),
    (0x1400, 0): u8(2), (0x1400, 1): u32(0x200 + node), (0x1400, 2): u8(0xFF),
    (0x1600, 0): u8(1), (0x1600, 1): u32(0x60400010),
    (0x1800, 0): u8(5), (0x1800, 1): u32(0x180 + node), (0x1800, 2): u8(0xFE),
    (0x1800, 3): u16(0), (0x1800, 5): u16(100),
    (0x1A00, 0): u8(2), (0x1A00, 1): u32(0x60410010), (0x1A00, 2): u32(0x60640020),
    (0x6041, 0): u16(0x0250),
    (0x6061, 0): u8(0xFD),
    (0x6064, 0): (-5000).to_bytes(4, 'little', signed=True),
}
def reply(data):
    bus.send(can.Message(arbitration_id=0x580 + node, is_extended_id=False, data=bytes(data).ljust(8, b'\0')))
def abort(i, s, code):
    reply([0x80, i & 0xFF, i >> 8, s] + list(u32(code)))
print('READY', flush=True)
upload = None  # bytes left of a segmented upload
end = time.time() + 90
while time.time() < end:
    m = bus.recv(0.1)
    if m is None or m.arbitration_id != 0x600 + node or len(m.data) != 8:
        continue
    d = bytes(m.data)
    ccs, i, s = d[0] >> 5, d[1] | d[2] << 8, d[3]
    if ccs == 2:  # initiate upload
        v = od.get((i, s))
        if v is None:
            abort(i, s, 0x06090011 if any(k[0] == i for k in od) else 0x06020000)
        elif len(v) <= 4:
            reply([0x43 | ((4 - len(v)) << 2), d[1], d[2], s] + list(v))
        else:
            upload = v
            reply([0x41, d[1], d[2], s] + list(u32(len(v))))
    elif ccs == 3 and upload is not None:  # upload segment
        seg, upload = upload[:7], upload[7:]
        reply([(d[0] & 0x10) | ((7 - len(seg)) << 1) | (0 if upload else 1)] + list(seg))
        if not upload:
            upload = None
    elif ccs == 1 and d[0] & 0x02:  # expedited download
        n = 4 - ((d[0] >> 2) & 3) if d[0] & 0x01 else 4
        od[(i, s)] = d[4:4 + n]
        print('DOWNLOAD %04X:%02X %02x %s' % (i, s, d[0], d[4:4 + n].hex()), flush=True)
        reply([0x60, d[1], d[2], s])
    elif ccs == 4:
        upload = None
    else:
        abort(i, s, 0x05040001)  # command specifier not valid (no block transfer here)
bus.shutdown()
)PY";

const QString kSimNodes = QStringLiteral("sim://?nodes=1:delta-asda-a2,2:aimotor,3:generic-cia402");

}  // namespace

class TestCliStandardObjects : public QObject {
    Q_OBJECT

    QProcess sim_, peer_;
    QTemporaryDir dir_;
    QString bus_;
    QString peerOut_;

    Run sdo(const QStringList& args) { return cli(QStringList{QStringLiteral("sdo")} + args); }

private slots:
    void initTestCase() {
        const QString py = pythonWithCan();
        if (py.isEmpty()) QSKIP("python3-can is not installed (Debian package python3-can)");
        QString simError;
        const QString port = startSimSocketcand(sim_, QString(), &simError);
        QVERIFY2(!port.isEmpty(), qPrintable(simError));
        bus_ = QStringLiteral("socketcand://127.0.0.1:%1/can0").arg(port);

        QFile script(dir_.filePath(QStringLiteral("server.py")));
        QVERIFY(script.open(QIODevice::WriteOnly));
        script.write(kServer);
        script.close();
        QVERIFY2(startPythonPeer(peer_, py, script.fileName(),
                                 {QStringLiteral("127.0.0.1"), port, QStringLiteral("42")}, &peerOut_),
                 qPrintable(peerOut_));
        QTest::qWait(300);  // python-can's socketcand client takes frames 50 ms after "< ok >"
    }

    void cleanupTestCase() { stopProcesses({&peer_, &sim_}); }

    // CiA 301 7.5.2.9: 1008h manufacturer device name is a VISIBLE_STRING.
    void deviceNameIsText() {
        const Run r = sdo({QStringLiteral("read"), bus_, QStringLiteral("42"), QStringLiteral("1008:00")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("(VISIBLE_STRING) = Peer drive 42")), qPrintable(r.out));
    }

    // CiA 301 7.5.2.24: 1017h producer heartbeat time is UNSIGNED16: the write is an expedited
    // download of 2 bytes (command 2Bh: e=1, s=1, n=2), and it reads back as 1000.
    void heartbeatWriteIsUnsigned16() {
        Run r = sdo(
            {QStringLiteral("write"), bus_, QStringLiteral("42"), QStringLiteral("1017:00"), QStringLiteral("1000")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("(UNSIGNED16)")), qPrintable(r.out));
        QTRY_VERIFY_WITH_TIMEOUT((peerOut_ += QString::fromUtf8(peer_.readAllStandardOutput()))
                                     .contains(QStringLiteral("DOWNLOAD 1017:00 2b e803")),
                                 5000);
        r = sdo({QStringLiteral("read"), bus_, QStringLiteral("42"), QStringLiteral("1017:00")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("(UNSIGNED16) = 1000")), qPrintable(r.out));
        // 70000 does not fit UNSIGNED16: refused before anything is sent.
        r = sdo(
            {QStringLiteral("write"), bus_, QStringLiteral("42"), QStringLiteral("1017:00"), QStringLiteral("70000")});
        QCOMPARE(r.code, 1);
    }

    // CiA 301 7.5.2.22 (1018h sub 1 UNSIGNED32), CiA 402-2: 6064h INTEGER32, 6061h INTEGER8,
    // 6041h UNSIGNED16.
    void cia402TypesWithoutDictionary() {
        Run r = sdo({QStringLiteral("read"), bus_, QStringLiteral("42"), QStringLiteral("6064:00")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("(INTEGER32) = -5000")), qPrintable(r.out));
        r = sdo({QStringLiteral("read"), bus_, QStringLiteral("42"), QStringLiteral("6061:00")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("(INTEGER8) = -3")), qPrintable(r.out));
        r = sdo({QStringLiteral("read"), bus_, QStringLiteral("42"), QStringLiteral("1018:01")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("(UNSIGNED32)")) && r.out.contains(QStringLiteral("0x12345678")),
                 qPrintable(r.out));
        // TPDO communication parameter (CiA 301 7.5.2.37) of a PDO beyond the fourth: sub 2
        // transmission type UNSIGNED8; the peer has no TPDO9, so it aborts (exit 1, one line).
        r = sdo({QStringLiteral("read"), bus_, QStringLiteral("42"), QStringLiteral("1808:02")});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("0x06020000")), qPrintable(r.err));
    }

    void pdoShowNamesMappedObjects() {
        const Run r = cli({QStringLiteral("pdo"), QStringLiteral("show"), bus_, QStringLiteral("42")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("TPDO1  COB-ID 0x1AA")) &&
                     r.out.contains(QStringLiteral("type FEh (event, manufacturer)")),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("6041:00/16  Statusword (UNSIGNED16)")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("6064:00/32  Position actual value (INTEGER32)")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("RPDO1  COB-ID 0x22A")) &&
                     r.out.contains(QStringLiteral("6040:00/16  Controlword (UNSIGNED16)")),
                 qPrintable(r.out));
    }

    // CiA 301 §7.5.2.9-11: 1008h, 1009h and 100Ah are optional. The peer has only 1008h: the
    // scan shows the name, says the others are not present, and reports no error for the node.
    void scanReadsOptionalObjectsQuietly() {
        const Run r = cli({QStringLiteral("scan"), bus_, QStringLiteral("--nodes"), QStringLiteral("40-44")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("1 node(s) found")), qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral(
                     "device name \"Peer drive 42\", hardware version not present, software version not present")),
                 qPrintable(r.out));
        QVERIFY2(!r.out.contains(u'['), qPrintable(r.out));  // no "[error]" on the node's line
    }

    // A device's EDS wins over the standard: AIMOTOR's bundled EDS gives 1017h as UNSIGNED32,
    // the generic drive (as CiA 301) UNSIGNED16.
    void deviceDictionaryOverridesStandard() {
        Run r = sdo({QStringLiteral("read"), kSimNodes, QStringLiteral("2"), QStringLiteral("1017:00")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("(UNSIGNED32)")), qPrintable(r.out));
        r = sdo({QStringLiteral("read"), kSimNodes, QStringLiteral("3"), QStringLiteral("1017:00")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("(UNSIGNED16)")), qPrintable(r.out));
    }
};

QTEST_GUILESS_MAIN(TestCliStandardObjects)
#include "test_cli_standard_objects.moc"
