// SPDX-License-Identifier: GPL-3.0-or-later
// The real ASAM MDF4 logs in shared/testdata/mdf4 (CANedge loggers; see PROVENANCE.md) read
// completely through the log registry, with frame counts checked two ways besides this reader:
// - the counts PROVENANCE.md states, from the acquiring session's own throwaway pure-Python
//   reader (and, for the finalised file, its channel groups' cycle count, 5477);
// - tests/corpus/mdf4_count.py, an independent stdlib-only counter run here when python3 exists.
// First frames and start times are as PROVENANCE.md gives them from the raw bytes.
#include "core/logio/LogFormats.h"
#include "core/logio/LogProbe.h"
#include "core/logio/Mdf4Log.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QtTest>

#include <map>

using namespace coscope;
using namespace coscope::logio;

namespace {
QString mdfDir() { return QStringLiteral(COSCOPE_SHARED_DIR "/testdata/mdf4"); }

struct Counts {
    int frames = 0, extended = 0, tx = 0;
    std::map<QString, int> perBus;  // "1", "2": BusChannel as the file numbers it
};

QByteArray payload(const CanFrame& f) {
    return QByteArray(reinterpret_cast<const char*>(f.data.data()), f.payloadSize()).toHex().toUpper();
}
}  // namespace

class TestMdf4Corpus : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        if (!QDir(mdfDir()).exists()) QSKIP("shared MDF4 test data is not available");
    }

    void everyFile_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<int>("frames");
        QTest::addColumn<int>("bus1");
        QTest::addColumn<int>("bus2");
        QTest::addColumn<int>("extended");
        QTest::addColumn<int>("tx");
        QTest::addColumn<QString>("start");   // HD start time, UTC
        QTest::addColumn<qint64>("firstUs");  // first frame after the start time
        QTest::addColumn<int>("firstBus");    // BusChannel
        QTest::addColumn<uint>("firstId");
        QTest::addColumn<QByteArray>("firstData");
        // PROVENANCE: 1815 classic frames, all 29-bit, bus 1 1403 / bus 2 412, all Rx. First
        // t=1.084 s, bus 1, 0CF00300, FF FE 00 FF FF FF 00 FF. Unfinalised, DT length 24, VLSD CG.
        QTest::newRow("j1939 unfinalised")
            << "canedge_unfin_fw0103_j1939_29bit_00000001-60B621D9.mf4" << 1815 << 1403 << 412 << 1815 << 0
            << "2021-06-01T11:43:49Z" << qint64(1084000) << 1 << 0x0CF00300u << QByteArray("FFFE00FFFFFF00FF");
        // PROVENANCE: 5588 11-bit frames, bus 1 221 (52 Tx on 79B), bus 2 5367. First t=0.9497 s,
        // bus 1, 79B, Tx, 02 21 01 FF FF FF FF FF.
        QTest::newRow("uds unfinalised") << "canedge_unfin_fw0104_uds_gps_11bit_00000001.mf4" << 5588 << 221 << 5367
                                         << 0 << 52 << "2022-01-06T11:46:01Z" << qint64(949700) << 1 << 0x79Bu
                                         << QByteArray("022101FFFFFFFFFF");
        // PROVENANCE: finalised and sorted, 8 data groups; 5477 frames (the CG's cycle count too),
        // bus 1 631, bus 2 4846, 90 x 29-bit. First t=2345.72115 s, bus 2, 009, 9B E4 CF C0 00 FE AF 7F.
        QTest::newRow("obd2 finalised") << "canedge_finalized_fw0104_obd2_gps_mixed_11_29bit_00000005-60FEB5A8.mf4"
                                        << 5477 << 631 << 4846 << 90 << 0 << "2021-07-26T04:40:54Z"
                                        << qint64(2345721150) << 2 << 0x009u << QByteArray("9BE4CFC000FEAF7F");
        // PROVENANCE: 73 channel groups, virtual BusChannel/IDE/Dir, 48-bit us time; 4024 frames,
        // CAN1 247 Tx + 764 Rx, CAN2 3013, not in time order in the file (146 steps back, up to
        // 0.99 s). The first, in file order and in time, is t=14.10395 s, bus 2, 011, 01.
        QTest::newRow("73 groups unfinalised")
            << "canedge_unfin_fw0107_73cg_uds_gps_11bit_00000001-63BEF5CD.mf4" << 4024 << 1011 << 3013 << 0 << 247
            << "2023-01-11T17:41:55Z" << qint64(14103950) << 2 << 0x011u << QByteArray("01");
    }

    void everyFile() {
        QFETCH(QString, file);
        QFETCH(int, frames);
        QFETCH(int, bus1);
        QFETCH(int, bus2);
        QFETCH(int, extended);
        QFETCH(int, tx);
        QFETCH(QString, start);
        QFETCH(qint64, firstUs);
        QFETCH(int, firstBus);
        QFETCH(uint, firstId);
        QFETCH(QByteArray, firstData);
        const QString path = mdfDir() + u'/' + file;
        const LogProbe probe = probeLog(path);
        QVERIFY2(probe.usable, qPrintable(probe.error));
        QCOMPARE(probe.format, QStringLiteral("mf4"));
        QString error;
        auto reader = LogFormats::openReader(path, &error);
        QVERIFY2(reader, qPrintable(error));
        auto* mdf = dynamic_cast<Mdf4Reader*>(reader.get());
        QVERIFY(mdf);
        const auto all = reader->readAll();
        QVERIFY2(!reader->hasError(), qPrintable(reader->errorString()));
        QStringList problems;
        for (const auto& d : reader->diagnostics()) problems << d.message;
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(u'\n')));
        QCOMPARE(mdf->startTime().toString(Qt::ISODate), start);

        Counts c;
        for (const auto& f : all) {
            ++c.frames;
            if (f.isExtended()) ++c.extended;
            if (f.isTx()) ++c.tx;
            ++c.perBus[QString::number(f.bus + 1)];
            QVERIFY(!f.isFd() && !f.isError() && !f.isRemote());
        }
        QCOMPARE(c.frames, frames);
        QCOMPARE(c.perBus[QStringLiteral("1")], bus1);
        QCOMPARE(c.perBus[QStringLiteral("2")], bus2);
        QCOMPARE(c.extended, extended);
        QCOMPARE(c.tx, tx);
        const CanFrame& first = all.front();
        QCOMPARE((first.timestampNs - mdf->startNs()) / 1000, firstUs);
        QCOMPARE(int(first.bus) + 1, firstBus);
        QCOMPARE(first.id, firstId);
        QCOMPARE(payload(first), firstData);
        // In time order, the data groups merged and the channel groups of one data group too.
        for (size_t i = 1; i < all.size(); ++i) QVERIFY(all[i].timestampNs >= all[i - 1].timestampNs);

        // The independent counter agrees.
        QProcess py;
        py.start(QStringLiteral("python3"), {QStringLiteral(COSCOPE_SOURCE_DIR "/tests/corpus/mdf4_count.py"), path});
        if (!py.waitForFinished(30000) || py.exitCode() != 0) {
            if (py.error() == QProcess::FailedToStart) QSKIP("python3 is not available for the independent count");
            QFAIL(qPrintable(QString::fromUtf8(py.readAllStandardError())));
        }
        const QJsonObject counted = QJsonDocument::fromJson(py.readAllStandardOutput()).object();
        QCOMPARE(counted.value(QStringLiteral("frames")).toInt(), c.frames);
        QCOMPARE(counted.value(QStringLiteral("extended")).toInt(), c.extended);
        QCOMPARE(counted.value(QStringLiteral("tx")).toInt(), c.tx);
        const QJsonObject buses = counted.value(QStringLiteral("bus")).toObject();
        for (const auto& [bus, n] : c.perBus) QCOMPARE(buses.value(bus).toInt(), n);
        if (file.contains(QStringLiteral("finalized")))
            QCOMPARE(counted.value(QStringLiteral("cycles")).toInt(), c.frames);
        const QJsonArray earliest = counted.value(QStringLiteral("first")).toArray();
        QCOMPARE(earliest.size(), 3);
        QCOMPARE(qint64(earliest[0].toDouble()), firstUs);
        QCOMPARE(earliest[1].toInt(), firstBus);
        QCOMPARE(uint(earliest[2].toDouble()), firstId);
    }

    // A cut copy of a real unfinalised log keeps every whole record before the cut.
    void cutRealFileKeepsWhatWasRead() {
        QFile in(mdfDir() + QStringLiteral("/canedge_unfin_fw0104_uds_gps_11bit_00000001.mf4"));
        QVERIFY(in.open(QIODevice::ReadOnly));
        const QByteArray bytes = in.readAll();
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("cut.mf4"));
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(bytes.left(bytes.size() / 2 + 7));
        out.close();
        QString error;
        auto reader = LogFormats::openReader(path, &error);
        QVERIFY2(reader, qPrintable(error));
        const auto all = reader->readAll();
        QVERIFY(all.size() > 2000 && all.size() < 5588);
        QCOMPARE(all.front().id, 0x79Bu);
        QVERIFY(!reader->diagnostics().empty());
        QVERIFY2(reader->diagnostics().back().message.contains(QStringLiteral("cut short")),
                 qPrintable(reader->diagnostics().back().message));
    }

    // Cut before its first data group: the error names the block and where the file ends.
    void fileCutInItsMetadataSaysWhere() {
        QFile in(mdfDir() + QStringLiteral("/canedge_unfin_fw0104_uds_gps_11bit_00000001.mf4"));
        QVERIFY(in.open(QIODevice::ReadOnly));
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("head.mf4"));
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(in.read(5000));
        out.close();
        QString error;
        QVERIFY(!LogFormats::openReader(path, &error));
        QCOMPARE(error, path + QStringLiteral(": DG block at byte 5288: past the end of the file (5000 bytes); the "
                                              "data groups after it are lost"));
        const LogProbe probe = probeLog(path);
        QVERIFY(!probe.usable);
        QCOMPARE(probe.error, error);
    }
};

QTEST_GUILESS_MAIN(TestMdf4Corpus)
#include "test_mdf4_corpus.moc"
