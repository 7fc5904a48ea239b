// SPDX-License-Identifier: GPL-3.0-or-later
// Log readers and writers: round trips, hand-written samples of each variant, bad lines.
#include "core/logio/CandumpLog.h"
#include "core/logio/CsvWriter.h"
#include "core/logio/LogFormats.h"
#include "core/logio/PcapLog.h"
#include "core/logio/PeakTrc.h"
#include "core/logio/ReadAhead.h"
#include "core/logio/VectorAsc.h"
#include "core/logio/VectorBlf.h"

#include <QBuffer>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtEndian>
#include "core/can/CanErrorFrame.h"

#include <QtTest>

#include <zlib.h>

#include <atomic>
#include <span>
#include <thread>
#include <vector>

using namespace coscope;
using namespace coscope::logio;

namespace {

std::vector<CanFrame> readBytes(LogReader& r, const QByteArray& bytes) {
    QBuffer buf;
    buf.setData(bytes);
    buf.open(QIODevice::ReadOnly);
    if (!r.open(&buf)) return {};
    return r.readAll();
}

CanFrame frame(int64_t ts, uint32_t id, std::initializer_list<uint8_t> bytes, uint8_t flags = 0, uint8_t bus = 0) {
    CanFrame f;
    f.timestampNs = ts;
    f.id = id;
    f.flags = flags;
    f.bus = bus;
    f.len = uint8_t(bytes.size());
    std::copy(bytes.begin(), bytes.end(), f.data.begin());
    return f;
}

// Frames of every kind, timestamps on whole microseconds after a whole millisecond start.
std::vector<CanFrame> sampleFrames() {
    const int64_t t0 = 1700000000123000000LL;
    std::vector<CanFrame> v;
    v.push_back(frame(t0, 0x123, {0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77, 0x88}));
    v.push_back(frame(t0 + 1000, 0x1ABCDEF0, {0xDE, 0xAD}, CanFrame::Extended));
    CanFrame rtr = frame(t0 + 2000, 0x701, {}, CanFrame::Remote);
    rtr.len = 4;
    v.push_back(rtr);
    CanFrame fd = frame(t0 + 3000000, 0x181, {}, CanFrame::Fd | CanFrame::BitRateSwitch);
    fd.len = 12;
    for (int i = 0; i < 12; ++i) fd.data[size_t(i)] = uint8_t(i * 17);
    v.push_back(fd);
    v.push_back(frame(t0 + 4000001000LL, 0x080, {}, CanFrame::Tx, 1));
    return v;
}

CanFrame errorFrame(int64_t ts) {
    CanFrame e = frame(ts, 0x004, {0, 0x04, 0, 0, 0, 0, 0, 0}, CanFrame::Error);
    return e;
}

QByteArray writeAll(LogWriter& w, const std::vector<CanFrame>& frames) {
    QBuffer buf;
    buf.open(QIODevice::WriteOnly);
    w.open(&buf);
    for (const auto& f : frames) w.write(f);
    w.close();
    return buf.data();
}

void compareFrames(const std::vector<CanFrame>& got, const std::vector<CanFrame>& want, bool checkTx, bool checkBus) {
    QCOMPARE(got.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i) {
        const CanFrame& a = got[i];
        const CanFrame& b = want[i];
        QVERIFY2(a.timestampNs == b.timestampNs,
                 qPrintable(QStringLiteral("frame %1: time %2 != %3").arg(i).arg(a.timestampNs).arg(b.timestampNs)));
        QCOMPARE(a.id, b.id);
        QCOMPARE(a.len, b.len);
        const uint8_t mask = uint8_t(~(checkTx ? 0 : CanFrame::Tx));
        QCOMPARE(int(a.flags & mask), int(b.flags & mask));
        if (checkBus) QCOMPARE(a.bus, b.bus);
        QVERIFY(std::equal(a.data.begin(), a.data.begin() + a.payloadSize(), b.data.begin()));
    }
}

}  // namespace

class TestLogioFormats : public QObject {
    Q_OBJECT
private slots:
    void candumpRoundTrip() {
        auto frames = sampleFrames();
        frames.push_back(errorFrame(frames.back().timestampNs + 5));
        frames.back().timestampNs = frames[4].timestampNs + 7000;
        CandumpWriter w;
        w.setBusNames({QStringLiteral("can0"), QStringLiteral("can1")});
        const QByteArray bytes = writeAll(w, frames);
        QVERIFY(bytes.contains("(1700000000.123000) can0 123#1122334455667788\n"));
        CandumpReader r;
        const auto back = readBytes(r, bytes);
        QVERIFY(r.diagnostics().empty());
        compareFrames(back, frames, false, true);
        QCOMPARE(r.busNames(), QStringList({QStringLiteral("can0"), QStringLiteral("can1")}));
    }

    void candumpVariants() {
        const QByteArray text =
            "can0  000   [2]  82 01\n"  // unindented first line
            "  can0  701   [1]  00\n"
            "  can0  123   [4]  remote request\n"
            "  can0  00008002  [03]  42 01 30\n"  // FD, 29-bit
            "  can0       200  [12]  00 01 02 03 04 05 06 07 08 09 0A 0B\n"
            "  can0  080   [0] \n"
            "(1700000000.500000) vcan1 7FF#R T\n"
            "(1700000000.600000) vcan1 18FF0001##3AABB R\n"
            "(1700000000.700000) vcan1 20000004#0004000000000000\n";
        CandumpReader r;
        const auto f = readBytes(r, text);
        QVERIFY2(r.diagnostics().empty(), r.diagnostics().empty() ? "" : qPrintable(r.diagnostics()[0].message));
        QCOMPARE(f.size(), size_t(9));
        QCOMPARE(f[0].id, 0u);
        QCOMPARE(f[0].len, uint8_t(2));
        QVERIFY(f[2].isRemote() && f[2].len == 4);
        QVERIFY(f[3].isFd() && f[3].isExtended() && f[3].id == 0x8002 && f[3].len == 3 && f[3].data[2] == 0x30);
        QVERIFY(f[4].isFd() && f[4].len == 12 && f[4].data[11] == 0x0B);
        QCOMPARE(f[5].len, uint8_t(0));
        QVERIFY(f[6].isRemote() && f[6].isTx() && f[6].id == 0x7FF && f[6].bus == 1);
        QCOMPARE(f[6].timestampNs, 1700000000500000000LL);
        QVERIFY(f[7].isFd() && (f[7].flags & CanFrame::BitRateSwitch) && (f[7].flags & CanFrame::ErrorState) &&
                f[7].len == 2);
        QVERIFY(f[8].isError() && f[8].id == 0x4 && f[8].data[1] == 0x04);
    }

    void candumpBadLinesReportedAndRestKept() {
        const QByteArray text =
            "(1.000000) can0 123#11\n"
            "(1.100000) can0 12G#11\n"   // line 2: bad id
            "(1.200000) can0 123#112\n"  // line 3: odd digits
            "garbage\n"                  // line 4
            "(1.300000) can0 124#2233\n";
        CandumpReader r;
        const auto f = readBytes(r, text);
        QCOMPARE(f.size(), size_t(2));
        QCOMPARE(f[1].id, 0x124u);
        QCOMPARE(r.diagnostics().size(), size_t(3));
        QCOMPARE(r.diagnostics()[0].where, 2);
        QCOMPARE(r.diagnostics()[1].where, 3);
        QCOMPARE(r.diagnostics()[2].where, 4);
        QVERIFY(!r.hasError());
    }

    void ascRoundTrip() {
        auto frames = sampleFrames();
        CanFrame err;
        err.timestampNs = frames.back().timestampNs + 1000;
        err.flags = CanFrame::Error;  // ASC keeps only "an error frame happened"
        frames.push_back(err);
        AscWriter w;
        const QByteArray bytes = writeAll(w, frames);
        QVERIFY(bytes.startsWith("date "));
        QVERIFY(bytes.contains("Begin Triggerblock"));
        QVERIFY(bytes.trimmed().endsWith("End TriggerBlock"));
        AscReader r;
        const auto back = readBytes(r, bytes);
        QVERIFY(r.diagnostics().empty());
        compareFrames(back, frames, true, true);
    }

    void ascSample() {
        const QByteArray text =
            "date Sam Sep 30 15:06:13.191 2017\n"
            "base hex  timestamps absolute\n"
            "internal events logged\n"
            "// version 9.0.0\n"
            "Begin Triggerblock Sam Sep 30 15:06:13.191 2017\n"
            "   0.000000 Start of measurement\n"
            "   0.015991 CAN 1 Status:chip status error active\n"
            "   1.015991 1  Statistic: D 0 R 0 XD 0 XR 0 E 0 O 0 B 0.00%\n"
            "   2.501000 1 ErrorFrame\n"
            "   2.510001 2 100 Tx r\n"
            "   2.584921 4 300 Tx r 8 Length = 1704000 BitCount = 145\n"
            "   3.098426 1  18EBFF00x       Rx d 8 01 A0 0F A6 60 3B D1 40    Length = 273910\n"
            "   3.297743 1  J1939TP FEE3p        6    0  0   -   Rx   d 23 A0 0F\n"
            "   4.000000 1  123 Rx d 8 01 02\n"  // line 14: too few bytes
            "  30.005071 CANFD   2 Rx        300  Generic_Name_12   1 0 8  8 01 02 03 04 05 06 07 08   102203  133   "
            "303000 e0006659\n"
            "  30.506898 CANFD   4 Rx        4EE        0 0 d 32 01 02 03 04 05 06 07 08 09 0A 0B 0C 0D 0E 0F 10 11 12 "
            "13 14 15 16 17 18 19 1A 1B 1C 1D 1E 1F 20 0 0 0\n"
            "End TriggerBlock\n";
        AscReader r;
        const auto f = readBytes(r, text);
        QCOMPARE(f.size(), size_t(6));
        QCOMPARE(r.diagnostics().size(), size_t(1));
        QCOMPARE(r.diagnostics()[0].where, 14);
        QVERIFY(f[0].isError());
        QVERIFY(f[1].isRemote() && f[1].id == 0x100 && f[1].isTx() && f[1].bus == 1);
        QVERIFY(f[2].isRemote() && f[2].len == 8 && f[2].bus == 3);
        QVERIFY(f[3].isExtended() && f[3].id == 0x18EBFF00 && f[3].len == 8 && f[3].data[7] == 0x40);
        QVERIFY(f[4].isFd() && (f[4].flags & CanFrame::BitRateSwitch) && f[4].len == 8 && f[4].id == 0x300);
        QVERIFY(f[5].isFd() && f[5].len == 32 && f[5].data[31] == 0x20);
        // Times are the trigger block's local time plus the offset.
        const int64_t start = QDateTime(QDate(2017, 9, 30), QTime(15, 6, 13, 191)).toMSecsSinceEpoch() * 1000000;
        QCOMPARE(f[3].timestampNs, start + 3098426000LL);
    }

    void ascDecimalAndRelative() {
        const QByteArray text =
            "base dec  timestamps relative\n"
            "0.100000 1  291  Rx d 2 17 255\n"
            "0.050000 1  291  Rx d 1 1\n";
        AscReader r;
        const auto f = readBytes(r, text);
        QCOMPARE(f.size(), size_t(2));
        QCOMPARE(f[0].id, 291u);
        QCOMPARE(f[0].data[1], uint8_t(255));
        QCOMPARE(f[1].timestampNs - f[0].timestampNs, 50000000LL);
    }

    void trcRoundTrip() {
        auto frames = sampleFrames();
        CanFrame err;
        err.timestampNs = frames.back().timestampNs + 1000;
        err.flags = CanFrame::Error;
        frames.push_back(err);
        TrcWriter w;
        const QByteArray bytes = writeAll(w, frames);
        QVERIFY(bytes.startsWith(";$FILEVERSION=2.1\r\n"));
        TrcReader r;
        const auto back = readBytes(r, bytes);
        QVERIFY2(r.diagnostics().empty(), r.diagnostics().empty() ? "" : qPrintable(r.diagnostics()[0].message));
        compareFrames(back, frames, true, true);
    }

    void trcVersions_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::newRow("1.0") << QByteArray(
            ";##########\n;   Start time: 1.1.2020\n"
            "     1)      1841  0001  8  00 01 02 03 04 05 06 07\n"
            "     2)      1842  00000100  2  AA BB\n");
        QTest::newRow("1.1") << QByteArray(
            ";$FILEVERSION=1.1\n;$STARTTIME=44964.5725134375\n"
            "     1)      1841.0  Rx         0001  8  00 01 02 03 04 05 06 07 \n"
            "     2)      1842.0  Tx     00000100  2  AA BB \n");
        QTest::newRow("1.3") << QByteArray(
            ";$FILEVERSION=1.3\n;$STARTTIME=44964.5725134375\n"
            "     1)      1841.0 1  Rx         0001 -  8    00 01 02 03 04 05 06 07\n"
            "     2)      1842.0 1  Tx     00000100 -  2    AA BB\n");
        QTest::newRow("2.0") << QByteArray(
            ";$FILEVERSION=2.0\n;$STARTTIME=44964.5725134375\n;$COLUMNS=N,O,T,I,d,l,D\n"
            "      1      1841.000 DT     0001 Rx 8  00 01 02 03 04 05 06 07\n"
            "      2      1842.000 DT 00000100 Tx 2  AA BB\n");
        QTest::newRow("2.1") << QByteArray(
            ";$FILEVERSION=2.1\n;$STARTTIME=44964.5725134375\n;$COLUMNS=N,O,T,B,I,d,R,L,D\n"
            "      1      1841.000 DT  1     0001 Rx -  8    00 01 02 03 04 05 06 07\n"
            "      2      1842.000 DT  1 00000100 Tx -  2    AA BB\n"
            "      3      1843.000 ST  1       Rx -  4    00 00 00 04\n");
    }
    void trcVersions() {
        QFETCH(QByteArray, text);
        TrcReader r;
        const auto f = readBytes(r, text);
        QVERIFY2(r.diagnostics().empty(), r.diagnostics().empty() ? "" : qPrintable(r.diagnostics()[0].message));
        QCOMPARE(f.size(), size_t(2));
        QCOMPARE(f[0].id, 1u);
        QVERIFY(!f[0].isExtended());
        QCOMPARE(f[0].data[7], uint8_t(7));
        QVERIFY(f[1].isExtended());
        QCOMPARE(f[1].id, 0x100u);
        QCOMPARE(f[1].len, uint8_t(2));
        QCOMPARE(f[1].timestampNs - f[0].timestampNs, 1000000LL);
    }

    void trcFdRemoteAndBadLine() {
        const QByteArray text =
            ";$FILEVERSION=2.1\n;$COLUMNS=N,O,T,B,I,d,R,L,D\n"
            "      1         1.000 FB  2     0181 Rx -  9    00 01 02 03 04 05 06 07 08 09 0A 0B\n"
            "      2         2.000 RR  1     0701 Rx -  1\n"
            "      3         3.000 DT  1     0ZZZ Rx -  1    00\n"  // line 5
            "      4         4.000 DT  1     0702 Rx -  1    05\n";
        TrcReader r;
        const auto f = readBytes(r, text);
        QCOMPARE(f.size(), size_t(3));
        QVERIFY(f[0].isFd() && (f[0].flags & CanFrame::BitRateSwitch) && f[0].len == 12 && f[0].bus == 1);
        QVERIFY(f[1].isRemote() && f[1].len == 1);
        QCOMPARE(f[2].id, 0x702u);
        QCOMPARE(r.diagnostics().size(), size_t(1));
        QCOMPARE(r.diagnostics()[0].where, 5);
    }

    // Error warnings (PEAK CAN TRC File Format 1.0 "Error Warnings", 1.1+ type Warng) are the bus
    // state the driver saw: kept as error frames the Events show, not dropped (issue 37).
    void trcErrorWarningsBecomeErrorFrames() {
        const QByteArray v10 =
            ";   Start time: 1.1.2020\n"
            "     1)      1841  0001  8  00 01 02 03 04 05 06 07\n"
            "     2)      1843  FFFFFFFF  4  00 00 00 04 ------BUSLIGHT\n"
            "     3)      1844  FFFFFFFF  4  00 00 00 08 ------BUSHEAVY\n"
            "     4)      1845  FFFFFFFF  4  00 00 00 10 ------BUSOFF\n";
        TrcReader r;
        const auto f = readBytes(r, v10);
        QVERIFY2(r.diagnostics().empty(), r.diagnostics().empty() ? "" : qPrintable(r.diagnostics()[0].message));
        QCOMPARE(f.size(), size_t(4));
        QVERIFY(f[1].isError() && f[2].isError() && f[3].isError());
        QCOMPARE(decodeCanError(f[1]).state, CanErrorReport::BusState::Warning);
        QCOMPARE(decodeCanError(f[2]).state, CanErrorReport::BusState::Passive);
        QCOMPARE(decodeCanError(f[3]).state, CanErrorReport::BusState::BusOff);
        QCOMPARE(f[3].timestampNs - f[0].timestampNs, 4000000LL);

        const QByteArray v11 =
            ";$FILEVERSION=1.1\n;$STARTTIME=44964.5725134375\n"
            "     1)      1841.0  Rx         0001  8  00 01 02 03 04 05 06 07 \n"
            "     2)      1842.0  Warng  FFFFFFFF  4  00 00 00 08 BUSHEAVY \n";
        TrcReader r11;
        const auto g = readBytes(r11, v11);
        QVERIFY(r11.diagnostics().empty());
        QCOMPARE(g.size(), size_t(2));
        QCOMPARE(decodeCanError(g[1]).state, CanErrorReport::BusState::Passive);
    }

    void oleDate() {
        const int64_t ns = 1700000000123000000LL;
        QCOMPARE(*oleDateToNs(nsToOleDate(ns).toStdString()), ns);
    }

    void pcapngRoundTrip() {
        auto frames = sampleFrames();
        frames.push_back(errorFrame(frames.back().timestampNs + 1000));
        CanFrame ourFd = frame(frames.back().timestampNs + 1000, 0x601, {}, CanFrame::Fd | CanFrame::Tx);
        ourFd.len = 16;
        frames.push_back(ourFd);
        PcapngWriter w;
        const QByteArray bytes = writeAll(w, frames);
        PcapReader r;
        const auto back = readBytes(r, bytes);
        QVERIFY(r.diagnostics().empty());
        QVERIFY(!r.hasError());
        // Which frames were ours survives the file (epb_flags outbound, pcapng section 4.3.1).
        compareFrames(back, frames, true, true);
        QVERIFY(back[4].isTx() && back[6].isTx() && !back[0].isTx());
    }

    void pcapngOpensInTshark() {
        const QString tshark = QStandardPaths::findExecutable(QStringLiteral("tshark"));
        if (tshark.isEmpty()) QSKIP("tshark is not installed");
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("t.pcapng"));
        PcapngWriter w;
        QVERIFY(w.open(path));
        for (const auto& f : sampleFrames()) w.write(f);
        QVERIFY(w.close());
        QProcess p;
        p.start(tshark,
                {QStringLiteral("-r"), path, QStringLiteral("-T"), QStringLiteral("fields"), QStringLiteral("-e"),
                 QStringLiteral("can.id"), QStringLiteral("-e"), QStringLiteral("frame.packet_flags_direction")});
        QVERIFY(p.waitForFinished(60000));
        QCOMPARE(p.exitCode(), 0);
        const QStringList ids = QString::fromLatin1(p.readAllStandardOutput()).split(u'\n', Qt::SkipEmptyParts);
        QCOMPARE(ids.size(), 5);
        QVERIFY2(ids[0].contains(QStringLiteral("0x123")) || ids[0].section(u'\t', 0, 0) == u"291", qPrintable(ids[0]));
        // Our frame (the last, CanFrame::Tx) is outbound (2) for Wireshark too; the others unknown.
        QVERIFY2(ids[4].endsWith(QStringLiteral("\t2")) || ids[4].endsWith(QStringLiteral("\t0x2")) ||
                     ids[4].endsWith(QStringLiteral("\t0x00000002")),
                 qPrintable(ids[4]));
        QVERIFY2(!ids[0].endsWith(QStringLiteral("2")), qPrintable(ids[0]));
    }

    void pcapClassicBothEndians() {
        for (bool bigEndian : {false, true}) {
            QByteArray b;
            auto put32 = [&](uint32_t v) {
                for (int i = 0; i < 4; ++i) b.append(char(bigEndian ? v >> (24 - 8 * i) : v >> (8 * i)));
            };
            auto put16 = [&](uint16_t v) {
                for (int i = 0; i < 2; ++i) b.append(char(bigEndian ? v >> (8 - 8 * i) : v >> (8 * i)));
            };
            put32(0xA1B23C4D);  // nanosecond pcap
            put16(2);
            put16(4);
            put32(0);
            put32(0);
            put32(65535);
            put32(227);
            put32(100);
            put32(5);  // 100 s + 5 ns
            put32(16);
            put32(16);
            const unsigned char pkt[16] = {0x80, 0x12, 0x34, 0x56, 2, 0, 0, 0, 0xCA, 0xFE, 0, 0, 0, 0, 0, 0};
            b.append(reinterpret_cast<const char*>(pkt), 16);
            PcapReader r;
            const auto f = readBytes(r, b);
            QCOMPARE(f.size(), size_t(1));
            QCOMPARE(f[0].timestampNs, 100000000005LL);
            QVERIFY(f[0].isExtended());
            QCOMPARE(f[0].id, 0x00123456u);
            QCOMPARE(f[0].len, uint8_t(2));
            QCOMPARE(f[0].data[1], uint8_t(0xFE));
        }
    }

    void blfRoundTrip() {
        const auto frames = sampleFrames();
        BlfWriter w;
        const QByteArray bytes = writeAll(w, frames);
        QVERIFY(bytes.startsWith("LOGG"));
        QCOMPARE(qFromLittleEndian<quint64>(bytes.constData() + 16),
                 quint64(bytes.size()));  // file size patched in at close
        QCOMPARE(qFromLittleEndian<quint32>(bytes.constData() + 32), quint32(frames.size()));  // object count
        BlfReader r;
        const auto back = readBytes(r, bytes);
        QVERIFY2(r.diagnostics().empty(), r.diagnostics().empty() ? "" : qPrintable(r.diagnostics()[0].message));
        QVERIFY(!r.hasError());
        compareFrames(back, frames, true, true);
    }

    void blfManyContainersAndErrorFrames() {
        std::vector<CanFrame> frames;
        for (int i = 0; i < 20000; ++i)
            frames.push_back(frame(1700000000000000000LL + i * 100000LL, uint32_t(0x180 + (i % 127)),
                                   {uint8_t(i), uint8_t(i >> 8)}));
        frames.push_back(errorFrame(frames.back().timestampNs + 1000));
        BlfWriter w;
        const QByteArray bytes = writeAll(w, frames);
        QVERIFY(bytes.size() < int(frames.size()) * 48 / 2);  // compressed
        BlfReader r;
        const auto back = readBytes(r, bytes);
        QVERIFY(r.diagnostics().empty());
        QCOMPARE(back.size(), frames.size());
        QCOMPARE(back[12345].id, frames[12345].id);
        QCOMPARE(back[12345].data[0], frames[12345].data[0]);
        QCOMPARE(back[12345].timestampNs, frames[12345].timestampNs);
        QVERIFY(back.back().isError());
    }

    void blfHandMade() {
        // One zlib container with a CAN_MESSAGE (v1 header, 10 us units) and a CAN_FD_MESSAGE_64.
        auto le16 = [](QByteArray& o, uint16_t v) { o.append(char(v)).append(char(v >> 8)); };
        auto le32 = [&](QByteArray& o, uint32_t v) {
            le16(o, uint16_t(v));
            le16(o, uint16_t(v >> 16));
        };
        auto le64 = [&](QByteArray& o, uint64_t v) {
            le32(o, uint32_t(v));
            le32(o, uint32_t(v >> 32));
        };
        auto object = [&](uint32_t type, uint32_t tsFlags, uint64_t ts, const QByteArray& body) {
            QByteArray o("LOBJ");
            le16(o, 32);
            le16(o, 1);
            le32(o, uint32_t(32 + body.size()));
            le32(o, type);
            le32(o, tsFlags);
            le16(o, 0);
            le16(o, 0);
            le64(o, ts);
            o += body;
            while (o.size() % 4) o.append('\0');
            return o;
        };
        QByteArray msg;
        le16(msg, 2);            // channel 2
        msg.append(char(0x01));  // Tx
        msg.append(char(3));
        le32(msg, 0x80000123);  // extended
        msg.append("\x01\x02\x03\x00\x00\x00\x00\x00", 8);
        QByteArray fd64;
        fd64.append(char(1)).append(char(9)).append(char(12)).append(char(0));
        le32(fd64, 0x181);
        le32(fd64, 0);
        le32(fd64, 0x3000);  // EDL + BRS
        for (int i = 0; i < 4; ++i) le32(fd64, 0);
        le16(fd64, 0);
        fd64.append(char(0)).append(char(0));
        le32(fd64, 0);
        for (int i = 0; i < 12; ++i) fd64.append(char(0xA0 + i));
        const QByteArray inner = object(1, 1, 150, msg) + object(101, 2, 2000000, fd64);
        QByteArray packed(int(compressBound(uLong(inner.size()))), '\0');
        uLongf packedLen = uLongf(packed.size());
        QCOMPARE(compress(reinterpret_cast<Bytef*>(packed.data()), &packedLen,
                          reinterpret_cast<const Bytef*>(inner.constData()), uLong(inner.size())),
                 Z_OK);
        packed.resize(int(packedLen));
        QByteArray cont("LOBJ");
        le16(cont, 16);
        le16(cont, 1);
        le32(cont, uint32_t(32 + packed.size()));
        le32(cont, 10);
        le16(cont, 2);
        cont.append(QByteArray(6, '\0'));
        le32(cont, uint32_t(inner.size()));
        le32(cont, 0);
        cont += packed;
        while (cont.size() % 4) cont.append('\0');
        QByteArray file("LOGG");
        le32(file, 144);
        file.append(QByteArray(136, '\0'));
        file += cont;
        BlfReader r;
        const auto f = readBytes(r, file);
        QVERIFY2(r.diagnostics().empty(), r.diagnostics().empty() ? "" : qPrintable(r.diagnostics()[0].message));
        QCOMPARE(f.size(), size_t(2));
        QVERIFY(f[0].isExtended() && f[0].isTx() && f[0].id == 0x123 && f[0].len == 3 && f[0].bus == 1);
        QCOMPARE(f[0].timestampNs, 1500000LL);
        QVERIFY(f[1].isFd() && (f[1].flags & CanFrame::BitRateSwitch) && f[1].len == 12 && f[1].data[11] == 0xAB);
        QCOMPARE(f[1].timestampNs, 2000000LL);
    }

    void csvWithSummary() {
        CsvWriter w;
        w.setSummaryProvider([](const CanFrame& f) { return QStringLiteral("id %1, \"x\"").arg(f.id); });
        const QByteArray bytes = writeAll(w, {frame(1500000, 0x181, {1, 2})});
        QCOMPARE(bytes, QByteArray("number,time,bus,id,ext,rtr,fd,dir,len,data,summary\n"
                                   "1,0.001500,can0,0x181,0,0,0,rx,2,01 02,\"id 385, \"\"x\"\"\"\n"));
    }

    void sniffByContent() {
        QTemporaryDir dir;
        auto check = [&](const QByteArray& bytes, const QString& want) {
            const QString path = dir.filePath(QStringLiteral("wrong.csv"));  // misleading extension
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
            f.write(bytes);
            f.close();
            QVERIFY(f.open(QIODevice::ReadOnly));
            QCOMPARE(LogFormats::detect(&f, path), want);
            f.close();
            QString error;
            auto r = LogFormats::openReader(path, &error);
            QVERIFY2(r, qPrintable(error));
            QVERIFY(!r->readAll().empty());
        };
        CandumpWriter cw;
        check(writeAll(cw, sampleFrames()), QStringLiteral("candump"));
        AscWriter aw;
        check(writeAll(aw, sampleFrames()), QStringLiteral("asc"));
        TrcWriter tw;
        check(writeAll(tw, sampleFrames()), QStringLiteral("trc"));
        PcapngWriter pw;
        check(writeAll(pw, sampleFrames()), QStringLiteral("pcap"));
        check("  can0  123   [2]  11 22\n", QStringLiteral("candump"));
        QCOMPARE(LogFormats::formatForExtension(QStringLiteral("x.blf")), QStringLiteral("blf"));
        QString error;
        QCOMPARE(LogFormats::writerFormatFor(QStringLiteral("out.pcapng"), {}, &error), QStringLiteral("pcapng"));
        QVERIFY(LogFormats::writerFormatFor(QStringLiteral("out.xyz"), {}, &error).isEmpty());
        QVERIFY(error.contains(QStringLiteral("--to")));
    }

    void unreadableFileIsAnError() {
        QString error;
        QVERIFY(!LogFormats::openReader(QStringLiteral("/nonexistent/x.log"), &error));
        QVERIFY(error.contains(QStringLiteral("/nonexistent/x.log")));
        PcapReader r;
        readBytes(r, QByteArray("\xD4\xC3\xB2\xA1 short", 10));
        QVERIFY(r.hasError());
    }

    // "Never crash on a file": a pcapng that another program truncates while it is being read
    // (a capture being rotated) ends with what was read and a clear diagnostic, no SIGBUS.
    void pcapngTruncatedWhileReading() {
        std::vector<CanFrame> frames;
        for (int i = 0; i < 200000; ++i)
            frames.push_back(frame(1000000LL * i, 0x181 + (i % 4), {uint8_t(i), uint8_t(i >> 8), 3, 4, 5, 6, 7, 8}));
        PcapngWriter w;
        const QByteArray bytes = writeAll(w, frames);
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("growing.pcapng"));
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            QCOMPARE(f.write(bytes), bytes.size());
        }
        QString error;
        auto r = LogFormats::openReader(path, &error);
        QVERIFY2(r, qPrintable(error));
        std::vector<CanFrame> batch(1000);
        QCOMPARE(r->read(batch.data(), batch.size()), batch.size());
        QVERIFY(QFile::resize(path, bytes.size() / 2 + 13));  // cut mid-block
        size_t total = batch.size();
        while (const size_t n = r->read(batch.data(), batch.size())) total += n;
        QVERIFY2(total >= 1000 && total < frames.size(), qPrintable(QString::number(total)));
        QVERIFY(r->hasError() || r->diagnosticCount() > 0);
    }

    // ReadAhead hands out every frame in order, and can be dropped half-way without hanging.
    void readAheadKeepsOrderAndStops() {
        QByteArray text;
        for (int i = 0; i < 50000; ++i)
            text += QByteArray("(1.000000) can0 ") + QByteArray::number(0x100 + i % 0x600, 16) + "#" +
                    QByteArray::number(i % 256 + 256, 16).right(2) + "\n";
        std::vector<CanFrame> want;
        {
            CandumpReader r;
            want = readBytes(r, text);
        }
        QCOMPARE(want.size(), size_t(50000));
        QBuffer buf(&text);
        buf.open(QIODevice::ReadOnly);
        CandumpReader r;
        QVERIFY(r.open(&buf));
        std::vector<CanFrame> got, observed;  // `observed` is read only after the reading thread ended
        std::atomic<size_t> observedCount{0};
        std::thread::id observerThread;
        {
            // The observer sees each batch on the reading thread before the consumer does.
            ReadAhead ahead(r, 1000, 3, [&](std::span<const CanFrame> b) {
                observerThread = std::this_thread::get_id();
                observed.insert(observed.end(), b.begin(), b.end());
                observedCount += b.size();
            });
            for (auto b = ahead.next(); !b.empty(); b = ahead.next()) {
                QVERIFY(observedCount.load() >= got.size() + b.size());
                got.insert(got.end(), b.begin(), b.end());
            }
        }
        compareFrames(got, want, false, false);
        compareFrames(observed, want, false, false);
        QVERIFY(observerThread != std::thread::id() && observerThread != std::this_thread::get_id());
        QBuffer buf2(&text);
        buf2.open(QIODevice::ReadOnly);
        CandumpReader r2;
        QVERIFY(r2.open(&buf2));
        {
            ReadAhead ahead(r2, 100, 2);
            QCOMPARE(ahead.next().size(), size_t(100));
        }  // destroyed with the producer still going: cancels and joins
        QVERIFY(r2.framesRead() < 50000);
    }

    void cancelStopsReading() {
        QByteArray text;
        for (int i = 0; i < 100000; ++i) text += "(1.000000) can0 123#11\n";
        CandumpReader r;
        QBuffer buf(&text);
        buf.open(QIODevice::ReadOnly);
        QVERIFY(r.open(&buf));
        CanFrame batch[100];
        QCOMPARE(r.read(batch, 100), size_t(100));
        r.cancel();
        QCOMPARE(r.read(batch, 100), size_t(0));
        QVERIFY(r.progress() < 1.0);
    }
};

QTEST_GUILESS_MAIN(TestLogioFormats)
#include "test_logio_formats.moc"
