// SPDX-License-Identifier: GPL-3.0-or-later
// The ASAM MDF4 reader (core/logio/Mdf4Log.h) on files this test writes block by block
// (Mdf4TestFile.h): classic, 29-bit, FD, remote and error frames, sorted and unsorted data
// groups, DZ (deflate, transposition + deflate), DL and HL lists, VLSD data bytes in SD blocks
// and VLSD channel groups, unfinalised files, and bad or cut files.
#include "core/can/CanErrorFrame.h"
#include "core/logio/LogFormats.h"
#include "core/logio/LogProbe.h"
#include "core/logio/Mdf4Log.h"
#include "tests/unit/Mdf4TestFile.h"

#include <QBuffer>
#include <QTemporaryDir>
#include <QtTest>

#include <linux/can/error.h>

using namespace coscope;
using namespace coscope::logio;
using mdf4test::File;
using mdf4test::Frame;

namespace {
constexpr uint64_t kStart = 1700000000123456789ULL;  // 2023-11-14 22:13:20.123456789 UTC

struct Result {
    std::vector<CanFrame> frames;
    QString error;
    std::vector<LogDiagnostic> problems;
    QStringList buses;
    int64_t startNs = 0;
};

Result readBytes(const QByteArray& bytes) {
    QBuffer buf;
    buf.setData(bytes);
    buf.open(QIODevice::ReadOnly);
    Mdf4Reader reader;
    Result r;
    if (reader.open(&buf, QStringLiteral("test.mf4"))) r.frames = reader.readAll();
    r.error = reader.errorString();
    r.problems = reader.diagnostics();
    r.buses = reader.busNames();
    r.startNs = reader.startNs();
    return r;
}

QString problemText(const Result& r) {
    QStringList t;
    for (const auto& d : r.problems) t << QStringLiteral("%1: %2").arg(d.where).arg(d.message);
    return t.join(u'\n');
}

Frame frame(uint64_t ns, uint32_t id, const QByteArray& bytes, uint8_t bus = 1) {
    Frame f;
    f.ns = ns;
    f.id = id;
    f.bus = bus;
    f.bytes = bytes;
    f.len = uint8_t(bytes.size());
    f.dlc = uint8_t(fdLengthToDlc(int(bytes.size())));
    return f;
}

QByteArray payload(const CanFrame& f) {
    return QByteArray(reinterpret_cast<const char*>(f.data.data()), f.payloadSize());
}

// Three classic frames in one sorted data group, the data given by `makeData` from the
// record bytes.
template <typename MakeData>
QByteArray sortedFile(MakeData makeData, uint64_t cycles = 3) {
    File m;
    QByteArray records;
    for (int i = 0; i < 3; ++i)
        records +=
            File::record(0, 0, frame(1000000ULL * uint64_t(i + 1), 0x181 + uint32_t(i), QByteArray(8, char(0x10 + i))));
    const uint64_t cg = m.group(1, cycles, 0, 80, m.canChannels("CAN_DataFrame"));
    const uint64_t dg = m.dataGroup(0, cg, 0);
    m.setLink(dg, 2, makeData(m, records));  // the data blocks come last, as loggers write them
    return m.finish(dg, kStart);
}
}  // namespace

class TestMdf4Log : public QObject {
    Q_OBJECT
private slots:
    // One unsorted data group (1-byte record ids) with data, remote, error and a LIN group.
    void unsortedGroupReadsEveryFrameKind() {
        File m;
        const uint64_t data = m.group(1, 4, 0, 80, m.canChannels("CAN_DataFrame"));
        const uint64_t remote = m.group(2, 1, 0, 16, m.canChannels("CAN_RemoteFrame"));
        const uint64_t error = m.group(3, 2, 0, 10, m.canChannels("CAN_ErrorFrame"));
        const uint64_t lin = m.group(4, 1, 0, 5, m.channel("LIN_Frame.ID", 0, 0, 0, 0, 8), "LIN_Frame");
        m.chain({data, remote, error, lin});
        QByteArray r;
        r += File::record(1, 1, frame(1000000, 0x181, QByteArray::fromHex("0102030405060708")));
        Frame ext = frame(2000000, 0x18FF50E5, QByteArray::fromHex("AABB"), 2);
        ext.ide = true;
        ext.dir = true;
        r += File::record(1, 1, ext);
        r += QByteArray::fromHex("04") + QByteArray(5, '\x55');  // LIN record, skipped
        Frame fd = frame(3000000, 0x123, QByteArray(32, '\x5A'));
        fd.edl = fd.brs = fd.esi = true;
        fd.dlc = 13;  // 32 bytes (ISO 11898-1)
        r += File::record(1, 1, fd);
        Frame rtr = frame(4000000, 0x701, {});
        rtr.dlc = 1;  // DataLength 0: the DLC is the requested length
        r += File::record(1, 2, rtr, -1, true);
        r += File::errorRecord(1, 3, 5000000, 1, 3);  // bit stuffing error
        r += File::errorRecord(1, 3, 6000000, 2, 5);  // acknowledgment error
        Frame classicLong = frame(7000000, 0x7FF, QByteArray::fromHex("11223344556677889900"));
        classicLong.dlc = 15;
        classicLong.len = 8;  // classic DLC 15 still means 8 bytes
        r += File::record(1, 1, classicLong);
        const QByteArray bytes = m.finish(m.dataGroup(1, data, m.dt(r)), kStart);

        const Result res = readBytes(bytes);
        QVERIFY2(res.error.isEmpty(), qPrintable(res.error));
        QVERIFY2(res.problems.empty(), qPrintable(problemText(res)));
        QCOMPARE(res.startNs, int64_t(kStart));
        QCOMPARE(res.frames.size(), size_t(7));
        const auto& f = res.frames;
        QCOMPARE(f[0].timestampNs, int64_t(kStart + 1000000));
        QCOMPARE(f[0].id, 0x181u);
        QCOMPARE(f[0].flags, uint8_t(0));
        QCOMPARE(payload(f[0]), QByteArray::fromHex("0102030405060708"));
        QCOMPARE(f[0].bus, uint8_t(0));  // BusChannel 1 -> can0
        QCOMPARE(f[1].id, 0x18FF50E5u);
        QCOMPARE(f[1].flags, uint8_t(CanFrame::Extended | CanFrame::Tx));
        QCOMPARE(f[1].bus, uint8_t(1));
        QCOMPARE(payload(f[1]), QByteArray::fromHex("AABB"));
        QCOMPARE(f[2].flags, uint8_t(CanFrame::Fd | CanFrame::BitRateSwitch | CanFrame::ErrorState));
        QCOMPARE(f[2].len, uint8_t(32));
        QCOMPARE(payload(f[2]), QByteArray(32, '\x5A'));
        QCOMPARE(f[3].flags, uint8_t(CanFrame::Remote));
        QCOMPARE(f[3].id, 0x701u);
        QCOMPARE(f[3].len, uint8_t(1));
        QVERIFY(f[4].isError());
        const CanErrorReport stuff = decodeCanError(f[4]);
        QVERIFY(stuff.classes & CAN_ERR_PROT);
        QVERIFY2(stuff.summary().contains(QStringLiteral("stuff")), qPrintable(stuff.summary()));
        QVERIFY(f[5].isError());
        QVERIFY(decodeCanError(f[5]).classes & CAN_ERR_ACK);
        QCOMPARE(f[5].bus, uint8_t(1));
        QCOMPARE(f[6].len, uint8_t(8));
        QCOMPARE(f[6].flags, uint8_t(0));
        QCOMPARE(res.buses, (QStringList{QStringLiteral("can0"), QStringLiteral("can1")}));
    }

    // Sorted data groups (no record ids) are merged by time; their cycle counts are checked.
    void sortedGroupsMergeByTime() {
        File m;
        QByteArray a, b;
        for (uint64_t t : {1, 3, 5})
            a += File::record(0, 0, frame(t * 1000000, 0x100 + uint32_t(t), QByteArray(1, char(t))));
        for (uint64_t t : {2, 4})
            b += File::record(0, 0, frame(t * 1000000, 0x100 + uint32_t(t), QByteArray(1, char(t)), 2));
        const uint64_t dg1 = m.dataGroup(0, m.group(1, 3, 0, 80, m.canChannels("CAN_DataFrame")), m.dt(a));
        const uint64_t dg2 = m.dataGroup(0, m.group(1, 2, 0, 80, m.canChannels("CAN_DataFrame")), m.dt(b));
        m.chain({dg1, dg2});
        const Result res = readBytes(m.finish(dg1, kStart));
        QVERIFY2(res.problems.empty(), qPrintable(problemText(res)));
        QCOMPARE(res.frames.size(), size_t(5));
        for (int i = 0; i < 5; ++i) QCOMPARE(res.frames[size_t(i)].id, uint32_t(0x101 + i));

        // A finalised file whose cycle count disagrees with its records says so.
        const Result wrong = readBytes(sortedFile([](File& f, const QByteArray& r) { return f.dt(r); }, 4));
        QCOMPARE(wrong.frames.size(), size_t(3));
        QVERIFY2(problemText(wrong).contains(QStringLiteral("declares 4 records, 3 were read")),
                 qPrintable(problemText(wrong)));
    }

    // Channel groups of one data group written apart (CANedge's Tx and Rx groups) come out in
    // time order; equal times keep the file's order.
    void oneDataGroupComesInTimeOrder() {
        File m;
        const uint64_t rx = m.group(1, 3, 0, 80, m.canChannels("CAN_DataFrame"));
        const uint64_t tx = m.group(2, 2, 0, 80, m.canChannels("CAN_DataFrame"));
        m.chain({rx, tx});
        QByteArray r;
        for (uint64_t t : {10, 30, 50}) r += File::record(1, 1, frame(t * 1000, uint32_t(t), {}));
        for (uint64_t t : {20, 30}) r += File::record(1, 2, frame(t * 1000, uint32_t(t + 1), {}));
        const Result res = readBytes(m.finish(m.dataGroup(1, rx, m.dt(r)), kStart));
        QVERIFY2(res.problems.empty(), qPrintable(problemText(res)));
        QList<uint32_t> ids;
        for (const auto& f : res.frames) ids << f.id;
        QCOMPARE(ids, (QList<uint32_t>{10, 21, 30, 31, 50}));
    }

    // The same records stored plainly, in a DZ block, transposed in a DZ under an HL, and in a
    // DL of two DT blocks that splits a record read the same frames.
    void compressedAndListedDataReadTheSame() {
        const Result plain = readBytes(sortedFile([](File& f, const QByteArray& r) { return f.dt(r); }));
        QCOMPARE(plain.frames.size(), size_t(3));
        const Result deflated = readBytes(sortedFile([](File& f, const QByteArray& r) { return f.dz(r); }));
        const Result transposed = readBytes(sortedFile([](File& f, const QByteArray& r) {
            return f.hl(f.dl({f.dz(r.left(200), 80), f.dz(r.mid(200), 80)}));  // 2 rows and 40 bytes, then 40
        }));
        const Result split = readBytes(sortedFile([](File& f, const QByteArray& r) {
            const uint64_t second = f.dl({f.dt(r.mid(150))});
            return f.dl({f.dt(r.left(37)), f.dt(r.mid(37, 113))}, second);
        }));
        for (const Result* r : {&deflated, &transposed, &split}) {
            QVERIFY2(r->error.isEmpty() && r->problems.empty(), qPrintable(r->error + problemText(*r)));
            QCOMPARE(r->frames, plain.frames);
        }
        QCOMPARE(payload(plain.frames[2]), QByteArray(8, '\x12'));
    }

    // FD data bytes stored as VLSD: in an SD block (a finalised file) and in a VLSD channel
    // group of the same data group (CANedge while logging).
    void vlsdDataBytes() {
        const QByteArray d1(64, '\x33'), d2 = QByteArray::fromHex("0102030405060708090A0B0C");
        Frame f1 = frame(1000000, 0x200, d1), f2 = frame(2000000, 0x201, d2);
        f1.edl = f2.edl = true;
        {
            File m;
            const uint64_t sd = m.sd(mdf4test::vlsdSample(d1) + mdf4test::vlsdSample(d2));
            const uint64_t cg = m.group(1, 2, 0, 24, m.canChannels("CAN_DataFrame", true, sd));
            const QByteArray recs = File::record(0, 0, f1, 0) + File::record(0, 0, f2, 4 + 64);
            const Result r = readBytes(m.finish(m.dataGroup(0, cg, m.dt(recs)), kStart));
            QVERIFY2(r.problems.empty(), qPrintable(problemText(r)));
            QCOMPARE(r.frames.size(), size_t(2));
            QCOMPARE(payload(r.frames[0]), d1);
            QCOMPARE(payload(r.frames[1]), d2);
            QVERIFY(r.frames[1].isFd());
        }
        {
            File m;
            const uint64_t cg = m.group(1, 2, 0, 24, m.canChannels("CAN_DataFrame", true));
            const uint64_t vlsd = m.group(2, 2, 1, 0, 0);
            m.setLink(m.lastDataBytes(), 5, vlsd);
            m.chain({cg, vlsd});
            QByteArray recs = QByteArray::fromHex("02") + mdf4test::vlsdSample(d1) + File::record(1, 1, f1, 0);
            recs += File::record(1, 1, f2, 4 + 64) + QByteArray::fromHex("02") +
                    mdf4test::vlsdSample(d2);  // CANedge's order
            const Result r = readBytes(m.finish(m.dataGroup(1, cg, m.dt(recs)), kStart));
            QVERIFY2(r.problems.empty(), qPrintable(problemText(r)));
            QCOMPARE(r.frames.size(), size_t(2));
            QCOMPARE(payload(r.frames[0]), d1);
            QCOMPARE(payload(r.frames[1]), d2);
        }
    }

    // An unfinalised file as a logger leaves it after a power loss: "UnFinMF ", the last DT
    // length not updated (its header says 24 bytes), cycle counts 0, the last record cut.
    void unfinalisedFileReadsWhatIsThere() {
        File m(true, 0x0025);
        QByteArray recs;
        for (int i = 0; i < 4; ++i)
            recs += File::record(1, 1, frame(uint64_t(i + 1) * 1000000, 0x300 + uint32_t(i), QByteArray(8, char(i))));
        const uint64_t cg = m.group(1, 0, 0, 80, m.canChannels("CAN_DataFrame"));
        const uint64_t dg = m.dataGroup(1, cg, 0);
        const uint64_t dt = m.dt(recs, 24);
        m.setLink(dg, 2, dt);
        QByteArray bytes = m.finish(dg, kStart);
        bytes.chop(30);  // the logger lost power inside the last record
        const Result r = readBytes(bytes);
        QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
        QCOMPARE(r.frames.size(), size_t(3));
        QCOMPARE(r.frames[2].id, 0x302u);
        QCOMPARE(r.problems.size(), size_t(1));
        QVERIFY2(r.problems[0].message.contains(QStringLiteral("cut short")) &&
                     r.problems[0].message.contains(
                         QStringLiteral("(at byte %1 of the file, 51 of 81 bytes)").arg(dt + 24 + 243)),
                 qPrintable(problemText(r)));
    }

    // Bad files: a clear error naming where, and what was read before the damage is kept.
    void badFilesSayWhere() {
        QCOMPARE(readBytes(QByteArray(100, 'x')).error,
                 QStringLiteral("not an MDF file (no \"MDF\" identification at byte 0)"));
        QByteArray mdf3 = sortedFile([](File& f, const QByteArray& r) { return f.dt(r); });
        mdf3[28] = char(330 & 0xFF);
        mdf3[29] = char(330 >> 8);
        QVERIFY(readBytes(mdf3).error.contains(QStringLiteral("MDF version 3.30 is not MDF 4")));
        QByteArray badHd = sortedFile([](File& f, const QByteArray& r) { return f.dt(r); });
        badHd[66] = 'X';
        QCOMPARE(readBytes(badHd).error, QStringLiteral("HD block at byte 64: found a XD block instead"));
        const QByteArray good = sortedFile([](File& f, const QByteArray& r) { return f.dt(r); });
        QVERIFY(readBytes(good.left(120)).error.contains(QStringLiteral("HD block at byte 64")));

        // A finalised file cut inside its data: the whole records before the cut are read.
        const Result cut = readBytes(good.left(good.size() - 100));
        QCOMPARE(cut.frames.size(), size_t(1));
        QVERIFY2(problemText(cut).contains(QStringLiteral("claims 240 bytes, the file ends after 140")),
                 qPrintable(problemText(cut)));
        QVERIFY2(problemText(cut).contains(QStringLiteral("cut short")), qPrintable(problemText(cut)));

        // A record id no channel group has: the frames before it are kept.
        File m;
        const uint64_t cg = m.group(1, 0, 0, 80, m.canChannels("CAN_DataFrame"));
        QByteArray recs = File::record(1, 1, frame(1000, 0x181, QByteArray(1, 'a'))) +
                          File::record(1, 9, frame(2000, 0x182, QByteArray(1, 'b')));
        const uint64_t dt = m.dt(recs);
        const Result unknown = readBytes(m.finish(m.dataGroup(1, cg, dt), kStart));
        QCOMPARE(unknown.frames.size(), size_t(1));
        QVERIFY2(problemText(unknown).contains(QStringLiteral("record id 9 at byte %1 of the file").arg(dt + 24 + 81)),
                 qPrintable(problemText(unknown)));

        // A DZ block that does not inflate.
        QByteArray dz = sortedFile([](File& f, const QByteArray& r) { return f.dz(r); });
        const qsizetype packed = dz.lastIndexOf("##DZ") + 48;
        for (qsizetype i = packed + 4; i < packed + 12; ++i) dz[i] = char(dz[i] ^ 0x5A);
        const Result broken = readBytes(dz);
        QVERIFY2(problemText(broken).contains(QStringLiteral("does not inflate")), qPrintable(problemText(broken)));

        // No CAN group at all.
        File lin;
        const uint64_t linGroup = lin.group(1, 0, 0, 5, lin.channel("LIN_Frame.ID", 0, 0, 0, 0, 8));
        QVERIFY(readBytes(lin.finish(lin.dataGroup(0, linGroup, lin.dt(QByteArray(5, 'x'))), kStart))
                    .error.contains(QStringLiteral("no CAN bus-logging channel group")));
    }

    // The registry finds the format by content and name; File > Open's probe and openReader
    // read it from a file, and an error names the file.
    void registryAndProbe() {
        const QByteArray good = sortedFile([](File& f, const QByteArray& r) { return f.dz(r, 80); });
        QCOMPARE(LogFormats::detectContent(good.left(64)), QStringLiteral("mf4"));
        QCOMPARE(LogFormats::formatForExtension(QStringLiteral("/x/LOG/00000001.MF4")), QStringLiteral("mf4"));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("00000001.MF4"));
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(good);
        out.close();
        const LogProbe probe = probeLog(path);
        QVERIFY2(probe.usable, qPrintable(probe.error));
        QCOMPARE(probe.format, QStringLiteral("mf4"));
        QString error;
        auto reader = LogFormats::openReader(path, &error);
        QVERIFY2(reader, qPrintable(error));
        QCOMPARE(reader->readAll().size(), size_t(3));

        const QString bad = dir.filePath(QStringLiteral("cut.mf4"));
        QFile cut(bad);
        QVERIFY(cut.open(QIODevice::WriteOnly));
        cut.write(good.left(100));
        cut.close();
        QVERIFY(!LogFormats::openReader(bad, &error));
        QVERIFY2(error.startsWith(bad + QStringLiteral(": HD block at byte 64")), qPrintable(error));
        QVERIFY(!probeLog(bad).usable);
    }
};

QTEST_GUILESS_MAIN(TestMdf4Log)
#include "test_mdf4_log.moc"
