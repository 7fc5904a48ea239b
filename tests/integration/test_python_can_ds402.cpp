// SPDX-License-Identifier: GPL-3.0-or-later
// A third-party CiA 402 master written with python-can (Debian python3-can) drives each CiA 402
// personality of `coscope-cli sim` over socketcand the way python-canopen's BaseNode402 does:
// it reads the PDO configuration by SDO (and, where the manual says the host must configure the
// PDOs, maps 6040h/6041h itself), starts the node with NMT, writes controlwords by RPDO and
// follows 6041h only from TPDOs. It must reach Operation enabled and come back to Switch on
// disabled on Delta ASDA-A2 (no default mapping, extract-delta §5), AIMOTOR (synchronous type 1
// PDOs, extract-aimotor §3.6) and the generic CiA 402 drive (event-driven type FFh).
#include "tests/PythonCan.h"
#include "tests/integration/SimSocketcand.h"

#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const char* kMaster = R"PY(
import sys, time, can
host, port = sys.argv[1], int(sys.argv[2])
nodes = [int(n) for n in sys.argv[3].split(',')]
bus = can.Bus(interface='socketcand', host=host, port=port, channel='can0')

def send(cob, data):
    bus.send(can.Message(arbitration_id=cob, is_extended_id=False, data=bytes(data)))

def sdo(node, req, index, sub, data=b''):
    # One expedited SDO request; returns (scs byte, 4 data bytes) or None on timeout.
    send(0x600 + node, bytes([req, index & 0xFF, index >> 8, sub]) + bytes(data).ljust(4, b'\0'))
    end = time.time() + 1.0
    while time.time() < end:
        m = bus.recv(0.05)
        if m is not None and m.arbitration_id == 0x580 + node and m.data[1] | m.data[2] << 8 == index:
            return m.data[0], bytes(m.data[4:8])
    return None

def read(node, index, sub):
    r = sdo(node, 0x40, index, sub)
    if r is None or r[0] & 0xE0 == 0x80:
        return None
    return int.from_bytes(r[1], 'little')

def write(node, index, sub, value, size):
    r = sdo(node, 0x23 | ((4 - size) << 2), index, sub, value.to_bytes(size, 'little'))
    if r is None or r[0] != 0x60:
        raise SystemExit('write %04X:%02X refused on node %d: %s' % (index, sub, node, r))

def pdos(node, comm, mapping):
    # [(cob, type, [(index, sub, bits)])] of the valid PDOs, as BaseNode402 reads them by SDO.
    out = []
    for n in range(4):
        cob = read(node, comm + n, 1)
        if cob is None or cob & 0x80000000:
            continue
        count = read(node, mapping + n, 0) or 0
        entries = [read(node, mapping + n, s) for s in range(1, count + 1)]
        out.append((cob & 0x7FF, read(node, comm + n, 2), [(e >> 16, (e >> 8) & 0xFF, e & 0xFF) for e in entries]))
    return out

def find(table, index):
    for cob, ttype, entries in table:
        if any(e[0] == index and e[1] == 0 for e in entries):
            return cob, ttype, entries
    return None

def configure(node, comm, mapping, index, cob):
    # CiA 301 7.5.2.36 procedure: invalidate, clear the mapping, map, count, type FFh, validate.
    write(node, comm, 1, 0x80000000 | cob, 4)
    write(node, mapping, 0, 0, 1)
    write(node, mapping, 1, (index << 16) | 0x10, 4)
    write(node, mapping, 0, 1, 1)
    write(node, comm, 2, 0xFF, 1)
    write(node, comm, 1, cob, 4)

def state(sw):
    if sw & 0x4F == 0x40: return 'SWITCH ON DISABLED'
    if sw & 0x6F == 0x21: return 'READY TO SWITCH ON'
    if sw & 0x6F == 0x23: return 'SWITCHED ON'
    if sw & 0x6F == 0x27: return 'OPERATION ENABLED'
    if sw & 0x4F == 0x08: return 'FAULT'
    if sw & 0x4F == 0x0F: return 'FAULT REACTION ACTIVE'
    if sw & 0x6F == 0x07: return 'QUICK STOP ACTIVE'
    return 'NOT READY TO SWITCH ON'

# Next controlword on the way to a target state (CiA 402-2 state machine, python-canopen's table).
TO_ENABLED = {'SWITCH ON DISABLED': 0x06, 'READY TO SWITCH ON': 0x07, 'SWITCHED ON': 0x0F, 'FAULT': 0x80,
              'QUICK STOP ACTIVE': 0x00}
TO_DISABLED = {'OPERATION ENABLED': 0x00, 'SWITCHED ON': 0x00, 'READY TO SWITCH ON': 0x00, 'FAULT': 0x80,
               'QUICK STOP ACTIVE': 0x00}

def drive(node):
    send(0x000, [0x80, node])  # Pre-operational: configuration
    tpdos, rpdos = pdos(node, 0x1800, 0x1A00), pdos(node, 0x1400, 0x1600)
    if find(tpdos, 0x6041) is None:
        configure(node, 0x1800, 0x1A00, 0x6041, 0x180 + node)
        tpdos = pdos(node, 0x1800, 0x1A00)
        print('NODE %d mapped 6041h to TPDO1' % node, flush=True)
    if find(rpdos, 0x6040) is None:
        configure(node, 0x1400, 0x1600, 0x6040, 0x200 + node)
        rpdos = pdos(node, 0x1400, 0x1600)
        print('NODE %d mapped 6040h to RPDO1' % node, flush=True)
    tcob, ttype, tmap = find(tpdos, 0x6041)
    rcob, rtype, rmap = find(rpdos, 0x6040)
    # The other objects in the RPDO keep the values the drive has (read once by SDO).
    values = {(i, s): (read(node, i, s) or 0) for i, s, b in rmap if i >= 0x1000 and i != 0x6040}
    use_sync = ttype <= 240 or rtype <= 240
    print('NODE %d TPDO %03X type %d RPDO %03X type %d sync %s' % (node, tcob, ttype, rcob, rtype, use_sync), flush=True)

    def rpdo(cw):
        bits, pos = 0, 0
        for i, s, b in rmap:
            v = cw if i == 0x6040 else values.get((i, s), 0)
            bits |= (v & ((1 << b) - 1)) << pos
            pos += b
        send(rcob, bits.to_bytes((pos + 7) // 8, 'little'))

    status = [None]
    next_sync = [0.0]
    def pump(seconds):
        end = time.time() + seconds
        while time.time() < end:
            if use_sync and time.time() >= next_sync[0]:
                send(0x080, [])
                next_sync[0] = time.time() + 0.01
            m = bus.recv(0.005)
            if m is not None and m.arbitration_id == tcob:
                pos = 0
                for i, s, b in tmap:
                    if i == 0x6041 and s == 0:
                        status[0] = int.from_bytes(bytes(m.data), 'little') >> pos & 0xFFFF
                    pos += b

    send(0x000, [0x01, node])  # NMT start
    pump(0.3)
    if status[0] is None:
        print('NODE %d no TPDO with 6041h after NMT start' % node, flush=True)
        return
    print('NODE %d first statusword %04Xh %s' % (node, status[0], state(status[0])), flush=True)
    for target, table in (('OPERATION ENABLED', TO_ENABLED), ('SWITCH ON DISABLED', TO_DISABLED)):
        path = [state(status[0])]
        end = time.time() + 5.0
        while state(status[0]) != target and time.time() < end:
            cw = table.get(state(status[0]))
            if cw is None:
                pump(0.05)
                continue
            before = status[0]
            rpdo(cw)
            deadline = time.time() + 0.5
            while status[0] == before and time.time() < deadline:
                pump(0.01)
            if path[-1] != state(status[0]):
                path.append(state(status[0]))
        print('NODE %d %s: %s' % (node, 'REACHED' if state(status[0]) == target else 'FAILED', ' -> '.join(path)), flush=True)
    send(0x000, [0x80, node])

for node in nodes:
    drive(node)
bus.shutdown()
print('DONE', flush=True)
)PY";

}  // namespace

class TestPythonCanDs402 : public QObject {
    Q_OBJECT
private slots:
    void thirdPartyMasterEnablesEachPersonality() {
        const QString py = pythonWithCan();
        if (py.isEmpty()) QSKIP("python3-can is not installed (Debian package python3-can)");

        QProcess sim;
        QString simError;
        const QString port = startSimSocketcand(sim, QString(), &simError);
        QVERIFY2(!port.isEmpty(), qPrintable(simError));

        QTemporaryDir dir;
        QFile script(dir.filePath(QStringLiteral("master402.py")));
        QVERIFY(script.open(QIODevice::WriteOnly));
        script.write(kMaster);
        script.close();

        // Default virtual network: 1 Delta ASDA-A2, 2 AIMOTOR, 3 generic CiA 402.
        QProcess master;
        master.start(py, {script.fileName(), QStringLiteral("127.0.0.1"), port, QStringLiteral("1,2,3")});
        QVERIFY(master.waitForFinished(120000));
        const QString out = QString::fromUtf8(master.readAllStandardOutput());
        const QString err = QString::fromUtf8(master.readAllStandardError());
        sim.terminate();
        sim.waitForFinished(5000);
        QVERIFY2(master.exitCode() == 0 && out.contains(QStringLiteral("DONE")), qPrintable(out + err));
        // Delta maps nothing by default (the host configures the PDOs, extract-delta §5).
        QVERIFY2(out.contains(QStringLiteral("NODE 1 mapped 6041h to TPDO1")), qPrintable(out));
        // AIMOTOR: TPDO1/RPDO1 of type 1 by default (extract-aimotor §3.6), no mapping needed.
        QVERIFY2(out.contains(QStringLiteral("NODE 2 TPDO 182 type 1 RPDO 202 type 1 sync True")), qPrintable(out));
        QVERIFY2(!out.contains(QStringLiteral("NODE 2 mapped")), qPrintable(out));
        // Generic: event-driven TPDO1 with 6041h, sent once on entering OPERATIONAL.
        QVERIFY2(out.contains(QStringLiteral("NODE 3 TPDO 183 type 255 RPDO 203 type 255 sync False")),
                 qPrintable(out));
        for (int node : {1, 2, 3}) {
            QVERIFY2(out.contains(QStringLiteral("NODE %1 first statusword").arg(node)), qPrintable(out));
            QVERIFY2(QRegularExpression(
                         QStringLiteral("NODE %1 REACHED: SWITCH ON DISABLED -> READY TO SWITCH ON -> SWITCHED ON -> "
                                        "OPERATION ENABLED\\n")
                             .arg(node))
                         .match(out)
                         .hasMatch(),
                     qPrintable(out));
            QVERIFY2(QRegularExpression(
                         QStringLiteral("NODE %1 REACHED: OPERATION ENABLED -> SWITCH ON DISABLED\\n").arg(node))
                         .match(out)
                         .hasMatch(),
                     qPrintable(out));
        }
    }
};

QTEST_GUILESS_MAIN(TestPythonCanDs402)
#include "test_python_can_ds402.moc"
