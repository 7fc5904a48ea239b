// SPDX-License-Identifier: GPL-3.0-or-later
// `coscope-cli sdo read` against an SDO server from another stack that uses what CiA 301 §7.2.4
// allows a server to send: a minimal server written with python-can (Debian python3-can) as node
// 43 on the bus `coscope-cli sim` serves over socketcand. Each object answers one way:
//   1017h  expedited upload without the size indicated (command 42h, §7.2.4.3.6: 4 data bytes)
//   1000h  expedited upload without the size indicated, UNSIGNED32
//   1009h  (segmented read) expedited without size: "HW1" and a padding NUL
//   1008h  segmented upload without the size indicated (command 40h), then segments
//   1009h  block upload whose last segment carries 3 bytes (end frame n = 4, §7.2.4.3.15)
//   100Ah  block upload aborted by the server after two segments; segmented: the server falls
//          silent after the first segment (the client must time out, not hang)
#include "tests/CliRun.h"
#include "tests/PythonCan.h"
#include "tests/integration/SimSocketcand.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const char* kServer = R"PY(
import sys, time, can
host, port, node = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
bus = can.Bus(interface='socketcand', host=host, port=port, channel='can0')
def reply(data):
    bus.send(can.Message(arbitration_id=0x580 + node, is_extended_id=False, data=bytes(data).ljust(8, b'\0')))
NAME = b'Peer 43 without size'      # 1008h, 20 bytes: 2 full segments and one of 6
HW = b'HW rev 1.2'                  # 1009h, 10 bytes: block segments of 7 and 3 bytes
SW = b'firmware 0.9.8 build 1234'   # 100Ah
print('READY', flush=True)
upload = None       # bytes left of a segmented upload
block = None        # (index, sub, data) of a block upload
end = time.time() + 120
while time.time() < end:
    m = bus.recv(0.1)
    if m is None or m.arbitration_id != 0x600 + node or len(m.data) != 8:
        continue
    d = bytes(m.data)
    ccs, i, s = d[0] >> 5, d[1] | d[2] << 8, d[3]
    if ccs == 2:  # initiate upload
        if (i, s) == (0x1017, 0):
            reply([0x42, d[1], d[2], s, 0xE8, 0x03, 0x00, 0x00])   # e=1, s=0: 4 bytes, UNSIGNED16 1000
        elif (i, s) == (0x1000, 0):
            reply([0x42, d[1], d[2], s, 0x92, 0x01, 0x02, 0x00])   # 00020192h
        elif (i, s) == (0x1009, 0):
            reply([0x42, d[1], d[2], s] + list(b'HW1\0'))          # a short string, no size
        elif (i, s) == (0x1008, 0):
            upload = NAME
            reply([0x40, d[1], d[2], s])                           # e=0, s=0: no size
        elif (i, s) == (0x100A, 0):
            upload = SW[:7]                                        # one segment, then silence
            reply([0x41, d[1], d[2], s] + list(len(SW).to_bytes(4, 'little')))
        else:
            reply([0x80, d[1], d[2], s, 0x00, 0x00, 0x02, 0x06])
    elif ccs == 3:  # upload segment
        if upload is None:
            continue                                               # silent server
        seg, upload = upload[:7], upload[7:]
        last = not upload and seg != SW[:7]
        reply([(d[0] & 0x10) | ((7 - len(seg)) << 1) | (1 if last else 0)] + list(seg))
        if not upload:
            upload = None
    elif ccs == 5 and d[0] & 0x03 == 0:  # block upload initiate
        data = {(0x1009, 0): HW, (0x100A, 0): SW}.get((i, s))
        if data is None:
            reply([0x80, d[1], d[2], s, 0x01, 0x00, 0x04, 0x05])   # no block transfer here
            continue
        block = (i, s, data, d[4])
        reply([0xC2, d[1], d[2], s] + list(len(data).to_bytes(4, 'little')))  # size indicated, no CRC
    elif ccs == 5 and d[0] & 0x03 == 3 and block is not None:  # start: send the sub-block
        i, s, data, blksize = block
        segs = [data[k:k + 7] for k in range(0, len(data), 7)]
        for n, seg in enumerate(segs, 1):
            if i == 0x100A and n == 3:
                reply([0x80, i & 0xFF, i >> 8, s, 0x00, 0x00, 0x00, 0x08])  # abort mid-block: 08000000h
                block = None
                break
            reply([(0x80 if n == len(segs) else 0) | n] + list(seg))
    elif ccs == 5 and d[0] & 0x03 == 2 and block is not None:  # ack: end of transfer
        i, s, data, blksize = block
        unused = (7 - len(data) % 7) % 7
        reply([0xC1 | (unused << 2), 0, 0])
    elif ccs == 5 and d[0] & 0x03 == 1:  # client's end response
        print('BLOCK END %04X' % block[0], flush=True)
        block = None
    elif ccs == 4:
        print('ABORT FROM CLIENT %04X:%02X %08X' % (i, s, int.from_bytes(d[4:8], 'little')), flush=True)
        upload = None
        block = None
bus.shutdown()
)PY";

}  // namespace

class TestCliSdoVariations : public QObject {
    Q_OBJECT

    QProcess sim_, peer_;
    QTemporaryDir dir_;
    QString bus_;
    QString peerOut_;

    Run read(const QString& ref, const QStringList& extra = {}) {
        return cli(QStringList{QStringLiteral("sdo"), QStringLiteral("read"), bus_, QStringLiteral("43"), ref} + extra);
    }

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
                                 {QStringLiteral("127.0.0.1"), port, QStringLiteral("43")}, &peerOut_),
                 qPrintable(peerOut_));
        QTest::qWait(300);  // python-can's socketcand client takes frames 50 ms after "< ok >"
    }

    void cleanupTestCase() { stopProcesses({&peer_, &sim_}); }

    // §7.2.4.3.6: e = 1, s = 0: the data bytes hold the value, their count is not given. 1017h
    // is UNSIGNED16 (CiA 301 §7.5.2.24): the value is the first two bytes.
    void expeditedWithoutSize() {
        Run r = read(QStringLiteral("1017:00"));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("(UNSIGNED16) = 1000")), qPrintable(r.out));
        r = read(QStringLiteral("1000:00"));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("0x00020192")), qPrintable(r.out));
        // A VISIBLE_STRING (CiA 301 §7.5.2.10) in 4 bytes without size: the NUL is padding.
        r = read(QStringLiteral("1009:00"));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.endsWith(QStringLiteral("(VISIBLE_STRING) = HW1\n")), qPrintable(r.out.toUtf8().toHex(' ')));
    }

    // §7.2.4.3.6: e = 0, s = 0: segmented, the size comes only from the last segment.
    void segmentedWithoutSize() {
        const Run r = read(QStringLiteral("1008:00"));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("(VISIBLE_STRING) = Peer 43 without size\n")), qPrintable(r.out));
    }

    // §7.2.4.3.15: the end frame's n says how many bytes of the last segment hold no data.
    void blockUploadShortLastSegment() {
        const Run r = read(QStringLiteral("1009:00"), {QStringLiteral("--block")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.out.contains(QStringLiteral("(VISIBLE_STRING) = HW rev 1.2\n")), qPrintable(r.out));
        QTRY_VERIFY_WITH_TIMEOUT(
            (peerOut_ += QString::fromUtf8(peer_.readAllStandardOutput())).contains(QStringLiteral("BLOCK END 1009")),
            5000);
    }

    // The server aborts in the middle of a sub-block: the read fails at once with its code.
    void abortInTheMiddleOfABlock() {
        QElapsedTimer t;
        t.start();
        // A timeout far longer than any start-up of the command (a sanitizer build, a loaded machine).
        const Run r = read(QStringLiteral("100A:00"),
                           {QStringLiteral("--block"), QStringLiteral("--timeout"), QStringLiteral("60000")});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("aborted 100A:00")) && r.err.contains(QStringLiteral("0x08000000")),
                 qPrintable(r.err));
        QVERIFY2(t.elapsed() < 40000, qPrintable(QString::number(t.elapsed())));  // not by the timeout
    }

    // The server falls silent after the first segment: the read ends with the SDO timeout
    // (05040000h), sent to the server as an abort, and the command does not hang.
    void silentServerTimesOut() {
        QElapsedTimer t;
        t.start();
        const Run r = read(QStringLiteral("100A:00"), {QStringLiteral("--timeout"), QStringLiteral("500")});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("did not answer")) && r.err.contains(QStringLiteral("0x05040000")),
                 qPrintable(r.err));
        QVERIFY2(t.elapsed() < 15000, qPrintable(QString::number(t.elapsed())));
        QTRY_VERIFY_WITH_TIMEOUT((peerOut_ += QString::fromUtf8(peer_.readAllStandardOutput()))
                                     .contains(QStringLiteral("ABORT FROM CLIENT 100A:00 05040000")),
                                 5000);
    }
};

QTEST_GUILESS_MAIN(TestCliSdoVariations)
#include "test_cli_sdo_variations.moc"
