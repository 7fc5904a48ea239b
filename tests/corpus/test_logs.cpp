// SPDX-License-Identifier: GPL-3.0-or-later
// Every real-world log in shared/testdata/logs (see PROVENANCE.md) reads completely, with the
// frame counts the provenance states and first/last frames checked by hand against the files.
#include "core/logio/LogFormats.h"

#include <QDir>
#include <QtTest>

using namespace coscope;
using namespace coscope::logio;

namespace {
QString logsDir() { return QStringLiteral(COSCOPE_SHARED_DIR "/testdata/logs"); }

QByteArray payload(const CanFrame& f) {
    return QByteArray(reinterpret_cast<const char*>(f.data.data()), f.payloadSize()).toHex().toUpper();
}
}  // namespace

class TestLogs : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        if (!QDir(logsDir()).exists()) QSKIP("shared test data is not available");
    }

    void everyLog_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("format");
        QTest::addColumn<int>("frames");
        QTest::addColumn<uint>("firstId");
        QTest::addColumn<QByteArray>("firstData");
        QTest::addColumn<uint>("lastId");
        QTest::addColumn<QByteArray>("lastData");
        QTest::addColumn<qint64>("spanUs");  // last - first timestamp, -1 = not checked
        // PROVENANCE: PCAN-View TRC 1.1, 11 283 frames. First "1) 144.5 Rx 0728 1 7F",
        // last "11283) 241052.4 Rx 010A 8 EC A8 88 0C 99 8C 00 00".
        QTest::newRow("trc") << "pcanview_v1.1_canopen_pcan1.trc"
                             << "trc" << 11283 << 0x728u << QByteArray("7F") << 0x10Au << QByteArray("ECA8880C998C0000")
                             << qint64(241052400 - 144500);
        // PROVENANCE: pcapng, SocketCAN, 149 frames; SDO scan starts with 601 upload of 0x1000.
        QTest::newRow("pcapng") << "socketcan_epos_sdo_scan.pcapng"
                                << "pcap" << 149 << 0x601u << QByteArray("4000100000000000") << 0x582u
                                << QByteArray("6040600000000000") << qint64(1521803006197147LL - 1521802991795187LL);
        // candump -L, one frame per line (12 974 lines).
        QTest::newRow("candump -L") << "savvycan_candump_L_automotive.log"
                                    << "candump" << 12974 << 0x21Au << QByteArray("FE3612FE690507AD") << 0x102u
                                    << QByteArray("0C96D0FFC1FF") << qint64(8000000);
        // candump default text, first line unindented, last line without a line end: 115 frames.
        QTest::newRow("candump text") << "candump_default_ds402_tmcm1636_ros_canopen.txt"
                                      << "candump" << 115 << 0x000u << QByteArray("8201") << 0x000u
                                      << QByteArray("0201") << qint64(-1);
        // candump default text with CAN FD lengths up to 64, one frame per line.
        QTest::newRow("candump fd") << "candump_default_canfd_moteus.txt"
                                    << "candump" << 1251 << 0x002u << QByteArray("400114") << 0x200u << QByteArray()
                                    << qint64(-1);
        // python-can ASC zoo: 3 error frames, 3 remote, 8 x 18EBFF00, 6F9, 6F8, 4 CANFD lines
        // (one remote, one error frame); statistics, chip status and J1939TP skipped.
        QTest::newRow("asc") << "vector_asc_python-can_logfile.asc"
                             << "asc" << 20 << 0u << QByteArray() << 0u << QByteArray() << qint64(30806898 - 2501000);
        // python-can BLF fixture: two CAN_MESSAGE objects with filler values.
        QTest::newRow("blf") << "vector_blf_python-can_test_CanMessage.blf"
                             << "blf" << 2 << 0x4444444u << QByteArray("5566778899AABBCC") << 0x4444444u
                             << QByteArray("5566778899AABBCC") << qint64(0);
    }

    void everyLog() {
        QFETCH(QString, file);
        QFETCH(QString, format);
        QFETCH(int, frames);
        QFETCH(uint, firstId);
        QFETCH(QByteArray, firstData);
        QFETCH(uint, lastId);
        QFETCH(QByteArray, lastData);
        QFETCH(qint64, spanUs);
        const QString path = logsDir() + u'/' + file;
        QFile probe(path);
        QVERIFY(probe.open(QIODevice::ReadOnly));
        QCOMPARE(LogFormats::detect(&probe, path), format);
        QString error;
        auto reader = LogFormats::openReader(path, &error);
        QVERIFY2(reader, qPrintable(error));
        const auto all = reader->readAll();
        QVERIFY2(!reader->hasError(), qPrintable(reader->errorString()));
        QVERIFY2(reader->diagnostics().empty(), reader->diagnostics().empty()
                                                    ? ""
                                                    : qPrintable(QStringLiteral("%1: %2")
                                                                     .arg(reader->diagnostics()[0].where)
                                                                     .arg(reader->diagnostics()[0].message)));
        QCOMPARE(int(all.size()), frames);
        QCOMPARE(reader->progress(), 1.0);
        QCOMPARE(all.front().id, firstId);
        if (!firstData.isEmpty()) QCOMPARE(payload(all.front()).left(firstData.size()), firstData);
        QCOMPARE(all.back().id, lastId);
        if (!lastData.isEmpty()) QCOMPARE(payload(all.back()), lastData);
        if (spanUs >= 0) QCOMPARE((all.back().timestampNs - all.front().timestampNs) / 1000, spanUs);
    }

    // Any file of the formats read from other tools (BUSMASTER, IXXAT, SavvyCAN, Kvaser, CoScope
    // CSV) that is dropped into the folder reads to its end without a fatal error.
    void otherToolsLogsRead() {
        const QStringList formats = {QStringLiteral("busmaster"), QStringLiteral("ixxat"), QStringLiteral("gvret"),
                                     QStringLiteral("kvaser"), QStringLiteral("csv")};
        int seen = 0;
        for (const QFileInfo& fi : QDir(logsDir()).entryInfoList(QDir::Files)) {
            QFile probe(fi.filePath());
            QVERIFY(probe.open(QIODevice::ReadOnly));
            const QString format = LogFormats::detect(&probe, fi.filePath());
            if (!formats.contains(format)) continue;
            ++seen;
            QString error;
            auto reader = LogFormats::openReader(fi.filePath(), &error);
            QVERIFY2(reader, qPrintable(error));
            const auto all = reader->readAll();
            QVERIFY2(!reader->hasError(), qPrintable(fi.fileName() + u' ' + reader->errorString()));
            QVERIFY2(!all.empty(), qPrintable(fi.fileName()));
            QCOMPARE(reader->progress(), 1.0);
        }
        if (!seen) QSKIP("no BUSMASTER, IXXAT, GVRET, Kvaser or CoScope CSV log in the shared folder");
    }

    void moteusFdFrames() {
        auto reader = LogFormats::openReader(logsDir() + QStringLiteral("/candump_default_canfd_moteus.txt"), nullptr);
        QVERIFY(reader);
        const auto all = reader->readAll();
        QVERIFY(all[0].isFd());
        QCOMPARE(int(all[0].len), 23);  // "[23]": kept although not a DLC length
        QVERIFY(all[1].isExtended() && all[1].id == 0x8002);
        QCOMPARE(int(all.back().len), 64);
    }
};

QTEST_GUILESS_MAIN(TestLogs)
#include "test_logs.moc"
