// SPDX-License-Identifier: GPL-3.0-or-later
// Readers of other tools' logs (candump -L line forms, BUSMASTER, IXXAT, SavvyCAN GVRET, Kvaser) and CoScope's own CSV,
// from the hand-written fixtures in tests/data/logs: frames, times, flags, bad lines by number,
// and detection by content (a .trc or .log name alone says nothing).
#include "core/logio/BusmasterLog.h"
#include "core/logio/CandumpLog.h"
#include "core/logio/CsvReader.h"
#include "core/logio/CsvWriter.h"
#include "core/logio/LogFormats.h"

#include <QBuffer>
#include <QDateTime>
#include <QtTest>

using namespace coscope;
using namespace coscope::logio;

namespace {
QString fixture(const char* name) {
    return QStringLiteral(COSCOPE_SOURCE_DIR "/tests/data/logs/") + QLatin1String(name);
}

struct Read {
    QString format;
    std::vector<CanFrame> frames;
    std::vector<LogDiagnostic> diagnostics;
    int64_t lines = 0;
};

Read readFixture(const char* name) {
    Read r;
    QString error;
    auto reader = LogFormats::openReader(fixture(name), &error);
    if (!reader) {
        qWarning() << error;
        return r;
    }
    r.format = reader->formatName();
    r.frames = reader->readAll();
    r.diagnostics = reader->diagnostics();
    r.lines = reader->linesRead();
    if (reader->hasError()) qWarning() << reader->errorString();
    return r;
}

QList<int64_t> badLines(const Read& r) {
    QList<int64_t> v;
    for (const auto& d : r.diagnostics) v << d.where;
    return v;
}

QByteArray bytesOf(const CanFrame& f) {
    return QByteArray(reinterpret_cast<const char*>(f.data.data()), f.payloadSize()).toHex(' ').toUpper();
}

int64_t localNs(int y, int mo, int d, int h, int mi, int s, int ms) {
    return QDateTime(QDate(y, mo, d), QTime(h, mi, s, ms)).toMSecsSinceEpoch() * 1000000;
}

std::vector<CanFrame> readBytes(LogReader& r, const QByteArray& bytes) {
    QBuffer buf;
    buf.setData(bytes);
    buf.open(QIODevice::ReadOnly);
    if (!r.open(&buf)) return {};
    return r.readAll();
}
}  // namespace

class TestLogioReaders : public QObject {
    Q_OBJECT
private slots:
    // candump -L lines (can-utils log.c: "(sec.frac) iface id#data", optional " T"/" R"): the
    // plain form is read in one pass, every other form by the general path; both must give the
    // frame the line says, and a faulty line a diagnostic with its number.
    void candumpLogLineForms() {
        const QByteArray text =
            "(1700000000.123456) can0 181#0102030405060708\n"       // 1: plain, 8 bytes
            "(1700000000.1) can1 7ff#\n"                            // 2: lower case, no data, 1 fraction digit
            "(1700000000.123456789) can0 18FF0001#AABB\n"           // 3: 29-bit, ns fraction
            "(1700000000.1234567891) can0 123#00\n"                 // 4: digits beyond 1 ns ignored
            "(1700000000.000001) can0 20000004#0004000000000000\n"  // 5: error frame (CAN_ERR_FLAG)
            "(1700000000.000002) can0 0123#11\n"                    // 6: 4 digits: 29-bit id 123h
            "(1700000000.000003) can0 123#11 T\n"                   // 7: transmitted
            "(1700000000.000004)\tcan0\t123#22\n"                   // 8: tabs
            "(1700000000.000005) can0 800#11\n"                     // 9: bad: 11-bit id above 7FF
            "(1700000000.000006) can0 123#112233445566778899\n"     // 10: bad: 9 bytes
            "(1700000000.000007) can0 123#11 X\n"                   // 11: bad: text after the frame
            "(9223372036.999999999) can0 123#11\n"                  // 12: bad: beyond int64 ns
            "(1700000000.000008) can0 123#11.22\n"                  // 13: '.' separator
            "(12345678901234567890123.5) can0 123#11\n";            // 14: bad: 23-digit seconds (fuzzer)
        CandumpReader r;
        const auto f = readBytes(r, text);
        QCOMPARE(badLines(Read{{}, {}, r.diagnostics(), 0}), QList<int64_t>({9, 10, 11, 12, 14}));
        QCOMPARE(f.size(), size_t(9));
        QVERIFY(f[0].id == 0x181 && f[0].len == 8 && f[0].data[7] == 0x08 && f[0].flags == 0 && f[0].bus == 0);
        QCOMPARE(f[0].timestampNs, 1700000000123456000LL);
        QVERIFY(f[1].id == 0x7FF && f[1].len == 0 && f[1].bus == 1);
        QCOMPARE(f[1].timestampNs, 1700000000100000000LL);
        QVERIFY(f[2].isExtended() && f[2].id == 0x18FF0001 && f[2].len == 2 && f[2].data[1] == 0xBB);
        QCOMPARE(f[2].timestampNs, 1700000000123456789LL);
        QCOMPARE(f[3].timestampNs, 1700000000123456789LL);
        QVERIFY(f[4].isError() && !f[4].isExtended() && f[4].id == 0x4 && f[4].data[1] == 0x04);
        QVERIFY(f[5].isExtended() && f[5].id == 0x123);
        QVERIFY(f[6].isTx() && f[6].id == 0x123 && f[6].len == 1);
        QVERIFY(f[7].id == 0x123 && f[7].data[0] == 0x22 && !f[7].isTx());
        QVERIFY(f[8].id == 0x123 && f[8].len == 2 && f[8].data[1] == 0x22);
        QCOMPARE(r.busNames(), QStringList({QStringLiteral("can0"), QStringLiteral("can1")}));
    }

    void busmasterV3HexSystemTime() {
        const Read r = readFixture("busmaster_v3_hex_system.log");
        QCOMPARE(r.format, QStringLiteral("busmaster"));
        QCOMPARE(r.frames.size(), size_t(5));
        QCOMPARE(badLines(r), QList<int64_t>({18, 19}));
        QCOMPARE(r.lines, int64_t(22));
        const auto& f = r.frames;
        QCOMPARE(f[0].id, 0x701u);
        QCOMPARE(bytesOf(f[0]), QByteArray("7F"));
        QCOMPARE(f[0].timestampNs, localNs(2023, 3, 14, 23, 59, 59, 600));
        QVERIFY(f[1].isTx() && f[1].bus == 1 && f[1].len == 8);
        QCOMPARE(f[1].timestampNs, localNs(2023, 3, 14, 23, 59, 59, 999));
        // Past midnight: the next day, 1.2 ms (the time column counts 1/10 ms).
        QVERIFY(f[2].isExtended() && f[2].id == 0x18FF1001 && f[2].bus == 0);
        QCOMPARE(f[2].timestampNs, localNs(2023, 3, 15, 0, 0, 0, 1) + 200000);
        QVERIFY(f[3].isRemote() && f[3].len == 1 && f[3].id == 0x701);
        QCOMPARE(bytesOf(f[4]), QByteArray("01 02"));
    }

    void busmasterV2DecimalAbsoluteTime() {
        const Read r = readFixture("busmaster_v2_dec_absolute.log");
        QCOMPARE(r.format, QStringLiteral("busmaster"));
        QCOMPARE(r.frames.size(), size_t(3));
        QCOMPARE(badLines(r), QList<int64_t>({17}));
        const int64_t start = localNs(2014, 8, 8, 11, 49, 7, 965);
        QCOMPARE(r.frames[0].id, 1793u);  // 0x701
        QCOMPARE(bytesOf(r.frames[0]), QByteArray("7F"));
        QCOMPARE(r.frames[0].timestampNs, start + 12000000);
        QCOMPARE(bytesOf(r.frames[1]), QByteArray("01 02 FF 10"));
        QCOMPARE(r.frames[1].timestampNs, start + 1000500000);
        QVERIFY(r.frames[2].isExtended() && r.frames[2].isTx() && r.frames[2].id == 419430401u && r.frames[2].len == 0);
    }

    void busmasterRelativeTimeAddsUp() {
        const QByteArray text =
            "***BUSMASTER Ver 3.2.2***\n***START DATE AND TIME 1:2:2018 10:0:0:0***\n***HEX***\n***RELATIVE MODE***\n"
            "0:0:0:0100 Rx 1 0x100 s 0\n0:0:0:0100 Rx 1 0x100 s 0\n0:0:1:0000 Rx 1 0x100 s 0\n"
            "252000000:0:0:0000 Rx 1 0x100 s 0\n";  // hours beyond reason (found by fuzzing: overflowed)
        BusmasterReader r;
        const auto f = readBytes(r, text);
        QCOMPARE(f.size(), size_t(3));
        QCOMPARE(r.timeMode(), BusmasterReader::TimeMode::Relative);
        QCOMPARE(r.diagnostics().size(), size_t(1));
        QCOMPARE(r.diagnostics()[0].where, int64_t(8));
        const int64_t start = localNs(2018, 2, 1, 10, 0, 0, 0);
        QCOMPARE(f[0].timestampNs, start + 10000000);
        QCOMPARE(f[1].timestampNs, start + 20000000);
        QCOMPARE(f[2].timestampNs, start + 1020000000);
    }

    // "22:20:14:992" counts milliseconds (three digits; issue 37: read as tenths, 30 ms showed as
    // 0.903 s); four digits count tenths of a millisecond.
    void busmasterThreeDigitTimeIsMilliseconds() {
        const QByteArray text =
            "***BUSMASTER Ver 3.2.2***\n***START DATE AND TIME 28:11:2026 22:20:14:000***\n***HEX***\n***SYSTEM "
            "MODE***\n"
            "22:20:14:992 Rx 1 0x701 s 1 05\n22:20:15:022 Rx 1 0x701 s 1 05\n22:20:15:0300 Rx 1 0x701 s 1 05\n"
            "22:20:15:1000 Rx 1 0x701 s 1 05\n";
        BusmasterReader r;
        const auto f = readBytes(r, text);
        QCOMPARE(f.size(), size_t(4));
        QVERIFY(r.diagnostics().empty());
        QCOMPARE(f[1].timestampNs - f[0].timestampNs, int64_t(30000000));  // 30 ms
        QCOMPARE(f[0].timestampNs, localNs(2026, 11, 28, 22, 20, 14, 992));
        QCOMPARE(f[2].timestampNs, localNs(2026, 11, 28, 22, 20, 15, 30));   // 0300 = 30.0 ms
        QCOMPARE(f[3].timestampNs, localNs(2026, 11, 28, 22, 20, 15, 100));  // 1000 = 100.0 ms
    }

    void ixxatMiniMon() {
        const Read r = readFixture("ixxat_minimon_v3.csv");
        QCOMPARE(r.format, QStringLiteral("ixxat"));
        QCOMPARE(r.frames.size(), size_t(5));
        QCOMPARE(badLines(r), QList<int64_t>({11}));
        const auto& f = r.frames;
        QCOMPARE(f[0].timestampNs, 1250000000LL);
        QCOMPARE(f[1].id, 0x581u);
        QCOMPARE(bytesOf(f[1]), QByteArray("43 00 10 00 92 01 02 00"));
        QVERIFY(f[2].isExtended() && f[2].id == 0x1ABCDEF0);
        QVERIFY(f[3].isRemote() && f[3].len == 1 && f[3].id == 0x701);
        QCOMPARE(f[4].timestampNs, 64007000000LL);
        QCOMPARE(f[4].len, uint8_t(0));
    }

    void ixxatCanAnalyserSemicolonsByColumnName() {
        const Read r = readFixture("ixxat_cananalyser.trc");
        QCOMPARE(r.format, QStringLiteral("ixxat"));  // a .trc, but not PEAK's
        QCOMPARE(r.frames.size(), size_t(3));
        QCOMPARE(badLines(r), QList<int64_t>({6}));  // DLC 8 with 5 bytes
        QCOMPARE(r.frames[0].timestampNs, 120000LL);
        QCOMPARE(bytesOf(r.frames[0]), QByteArray("01 05"));
        QVERIFY(r.frames[1].isExtended() && r.frames[1].bus == 1);
        QVERIFY(r.frames[2].isTx() && r.frames[2].len == 8);
    }

    void gvretV2() {
        const Read r = readFixture("savvycan_gvret_v2.csv");
        QCOMPARE(r.format, QStringLiteral("gvret"));
        QCOMPARE(r.frames.size(), size_t(4));
        QCOMPARE(badLines(r), QList<int64_t>({5}));
        const auto& f = r.frames;
        QCOMPARE(f[0].timestampNs, 39747828000LL);  // microseconds
        QCOMPARE(f[0].id, 0x5EBu);
        QVERIFY(!f[0].isExtended());
        QCOMPARE(bytesOf(f[0]), QByteArray("E8 45 85 4B 4A 28 36 69"));
        QVERIFY(f[1].isExtended() && f[1].isTx() && f[1].bus == 1 && f[1].len == 3);
        QCOMPARE(f[3].len, uint8_t(0));
    }

    void gvretV1WithoutDir() {
        const Read r = readFixture("savvycan_gvret_v1.csv");
        QCOMPARE(r.format, QStringLiteral("gvret"));
        QCOMPARE(r.frames.size(), size_t(2));
        QCOMPARE(badLines(r), QList<int64_t>({3}));  // LEN 9
        QCOMPARE(bytesOf(r.frames[0]), QByteArray("AA BB"));
        QCOMPARE(r.frames[1].bus, uint8_t(1));
    }

    void kvaserCanKing() {
        const Read r = readFixture("kvaser_canking.txt");
        QCOMPARE(r.format, QStringLiteral("kvaser"));
        QCOMPARE(r.frames.size(), size_t(5));
        QCOMPARE(badLines(r), QList<int64_t>({7}));
        const auto& f = r.frames;
        QVERIFY(f[0].isTx() && f[0].id == 0x14B && !f[0].isExtended());
        QCOMPARE(f[0].timestampNs, 1675570498000LL);
        QCOMPARE(bytesOf(f[1]), QByteArray("01 00 00 00 00"));
        QVERIFY(f[2].isExtended() && f[2].bus == 1 && !f[2].isTx());
        QVERIFY(f[3].isRemote() && f[3].len == 1);
        QVERIFY(f[4].isError());
        QCOMPARE(f[4].timestampNs, 46055200000000LL);
    }

    // What CsvWriter (coscope-cli convert x.csv) writes reads back as the same frames.
    void coscopeCsvRoundTrip() {
        std::vector<CanFrame> frames;
        const int64_t t0 = 1700000000123456000LL;
        frames.push_back(CanFrame::classic(0x123, {0x11, 0x22, 0x33}));
        frames.back().timestampNs = t0;
        frames.push_back(CanFrame::classic(0x1ABCDEF0, {0xDE, 0xAD}, true));
        frames.back().timestampNs = t0 + 1000;
        frames.back().flags |= CanFrame::Tx;
        frames.back().bus = 1;
        CanFrame rtr = CanFrame::classic(0x701, {});
        rtr.flags |= CanFrame::Remote;
        rtr.len = 4;
        rtr.timestampNs = t0 + 2000;
        frames.push_back(rtr);
        CanFrame fd = CanFrame::classic(0x181, {});
        fd.flags |= CanFrame::Fd;
        fd.len = 12;
        for (int i = 0; i < 12; ++i) fd.data[size_t(i)] = uint8_t(i * 19);
        fd.timestampNs = t0 + 3000000;
        frames.push_back(fd);
        CanFrame err = CanFrame::classic(0x004, {0, 4, 0, 0, 0, 0, 0, 0});
        err.flags = CanFrame::Error;
        err.timestampNs = t0 + 4000000;
        frames.push_back(err);
        CanFrame early = CanFrame::classic(0x080, {});
        early.timestampNs = -1500000000LL;  // before the epoch: the sign goes with the whole number
        frames.push_back(early);

        QBuffer out;
        out.open(QIODevice::WriteOnly);
        CsvWriter w;
        w.setBusNames({QStringLiteral("can0"), QStringLiteral("my,bus")});
        w.open(&out);
        for (const auto& f : frames) w.write(f, QStringLiteral("a \"quoted\", summary"));
        w.close();
        QCOMPARE(LogFormats::detectContent(out.data()), QStringLiteral("csv"));
        CsvReader r;
        const auto back = readBytes(r, out.data());
        QVERIFY2(r.diagnostics().empty(), r.diagnostics().empty() ? "" : qPrintable(r.diagnostics()[0].message));
        QCOMPARE(back.size(), frames.size());
        for (size_t i = 0; i < frames.size(); ++i)
            QVERIFY2(back[i] == frames[i], qPrintable(QStringLiteral("frame %1 differs").arg(i)));
        QCOMPARE(r.busNames(), QStringList({QStringLiteral("can0"), QStringLiteral("my,bus")}));
    }

    void coscopeCsvBadLines() {
        const QByteArray text =
            "number,time,bus,id,ext,rtr,fd,dir,len,data,summary\n"
            "1,1.000000,can0,0x181,0,0,0,rx,2,01 02,\n"
            "2,1.1,can0,0x181,0,0,0,rx,3,01 02,\n"
            "3,x,can0,0x181,0,0,0,rx,0,,\n"
            "4,1.2,can0,0x181,0,0,0,sideways,0,,\n"
            "5,1.300000,can0,0x182,0,0,0,rx,1,FF,\"NMT, boot\"\n";
        CsvReader r;
        const auto f = readBytes(r, text);
        QCOMPARE(f.size(), size_t(2));
        QCOMPARE(r.diagnostics().size(), size_t(3));
        QCOMPARE(r.diagnostics()[0].where, int64_t(3));
        QCOMPARE(r.diagnostics()[1].where, int64_t(4));
        QCOMPARE(r.diagnostics()[2].where, int64_t(5));
        QCOMPARE(f[1].timestampNs, 1300000000LL);
    }

    // Content decides, not the name: PEAK vs IXXAT .trc, candump vs BUSMASTER .log, three CSVs.
    void detectionByContent() {
        QCOMPARE(LogFormats::detectContent("***BUSMASTER Ver 3.2.2***\r\n***PROTOCOL CAN***\r\n"),
                 QStringLiteral("busmaster"));
        QCOMPARE(LogFormats::detectContent("(1.0) can0 123#00\n"), QStringLiteral("candump"));
        QCOMPARE(LogFormats::detectContent("ASCII Trace IXXAT MiniMon V3\n"), QStringLiteral("ixxat"));
        QCOMPARE(LogFormats::detectContent(";$FILEVERSION=1.1\n"), QStringLiteral("trc"));
        QCOMPARE(LogFormats::detectContent("\xEF\xBB\xBFTime Stamp,ID,Extended,Dir,Bus,LEN,D1\n"),
                 QStringLiteral("gvret"));
        QCOMPARE(LogFormats::detectContent("number,time,bus,id,ext,rtr,fd,dir,len,data,summary\n"),
                 QStringLiteral("csv"));
        QCOMPARE(
            LogFormats::detectContent("Chn Identifier Flg   DLC  D0...1...2...3...4...5...6..D7       Time     Dir\n"),
            QStringLiteral("kvaser"));
        for (const char* name :
             {"busmaster_v3_hex_system.log", "ixxat_cananalyser.trc", "kvaser_canking.txt", "savvycan_gvret_v1.csv"}) {
            QFile f(fixture(name));
            QVERIFY(f.open(QIODevice::ReadOnly));
            QVERIFY2(!LogFormats::detect(&f, f.fileName()).isEmpty(), name);
        }
        // Every readable format is listed and has a reader.
        for (const auto& info : LogFormats::all())
            if (info.canRead) QVERIFY2(LogFormats::createReader(info.name), qPrintable(info.name));
    }

    // A CSV that is none of the known ones says why instead of reading as nothing.
    void unknownCsvRefusedWithReason() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("other.csv"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("a,b,c\n1,2,3\n");
        f.close();
        QString error;
        QVERIFY(!LogFormats::openReader(path, &error));
        QVERIFY2(error.contains(QStringLiteral("not a CoScope CSV")), qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TestLogioReaders)
#include "test_logio_readers.moc"
