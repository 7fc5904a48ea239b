// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli reads the other tools' logs: convert from each fixture, the CSV it writes reads
// back the same, and buses/--help list the formats.
#include "CliRun.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

namespace {
QString fixture(const char* name) {
    return QStringLiteral(COSCOPE_SOURCE_DIR "/tests/data/logs/") + QLatin1String(name);
}
QByteArray slurp(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}
}  // namespace

class TestCliLogReaders : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void convertsEveryNewFormat() {
        for (const char* name :
             {"busmaster_v3_hex_system.log", "busmaster_v2_dec_absolute.log", "ixxat_minimon_v3.csv",
              "ixxat_cananalyser.trc", "savvycan_gvret_v2.csv", "savvycan_gvret_v1.csv", "kvaser_canking.txt"}) {
            const QString out = dir_.filePath(QLatin1String(name) + QStringLiteral(".out.log"));
            const Run r = cli({QStringLiteral("convert"), fixture(name), out});
            QVERIFY2(r.code == 0, qPrintable(QLatin1String(name) + u' ' + r.err));
            QVERIFY2(r.err.contains(QStringLiteral(": warning:")),
                     qPrintable(r.err));  // every fixture has a bad line, reported by number
            QVERIFY(slurp(out).count('\n') >= 2);
        }
    }

    // candump -> CoScope CSV -> candump gives the same file back.
    void csvRoundTripThroughConvert() {
        const QString in = dir_.filePath(QStringLiteral("in.log"));
        QFile f(in);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(
            "(1700000000.000100) can0 181#0102\n(1700000000.010000) can1 1ABCDEF0#DEADBEEF\n(1700000000.020000) can0 "
            "701#R\n"
            "(1700000000.030000) can0 123##1000102030405060708090A0B\n(1700000000.040000) can0 080#\n");
        f.close();
        const QString csv = dir_.filePath(QStringLiteral("mid.csv")), back = dir_.filePath(QStringLiteral("back.log"));
        QCOMPARE(cli({QStringLiteral("convert"), in, csv}).code, 0);
        const Run r = cli({QStringLiteral("convert"), csv, back});
        QVERIFY2(r.code == 0 && r.err.isEmpty(), qPrintable(r.err));
        QCOMPARE(slurp(back), slurp(in).replace("123##1", "123##0"));  // CSV keeps FD but not BRS
    }

    void formatsListed() {
        const Run help = cli({QStringLiteral("--help")});
        const Run buses = cli({QStringLiteral("buses")});
        for (const char* name : {"busmaster", "ixxat", "gvret", "kvaser", "csv", "trc"}) {
            QVERIFY2(help.out.contains(QLatin1String(name)), name);
            QVERIFY2(buses.out.contains(QLatin1String(name)), name);
        }
    }
};

QTEST_GUILESS_MAIN(TestCliLogReaders)
#include "test_cli_log_readers.moc"
