// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli record writes the format OUT's extension names: a known log replayed over
// replay:// is recorded to .log, .asc, .blf, .trc, .pcapng and .csv and read back frame for frame
// (the pcapng also by tshark, the BLF also by python-can's BLFReader); an extension without a writer is a usage error (exit 2).
#include "core/logio/LogFormats.h"
#include "tests/CliRun.h"
#include "tests/PythonCan.h"

#include <QFile>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace coscope;

namespace {

// Standard, extended (29-bit), remote and empty frames (candump -L, can-utils lib.c).
const char* kSource =
    "(1700000000.000100) can0 701#00\n"
    "(1700000000.000200) can0 181#1122334455667788\n"
    "(1700000000.000300) can0 12345678#DEADBEEF\n"
    "(1700000000.000400) can0 080#\n"
    "(1700000000.000500) can0 601#R\n"
    "(1700000000.000600) can0 1FFFFFFF#0102\n"
    "(1700000000.000700) can0 000#8103\n";
constexpr int kFrames = 7;

std::vector<CanFrame> readLog(const QString& path, QString* error) {
    auto reader = logio::LogFormats::openReader(path, error);
    if (!reader) return {};
    return reader->readAll();
}

QString describe(const CanFrame& f) {
    return QStringLiteral("%1%2%3#%4")
        .arg(f.id, f.isExtended() ? 8 : 3, 16, QChar(u'0'))
        .arg(f.isExtended() ? QStringLiteral("x") : QString())
        .arg(f.isRemote() ? QStringLiteral("R") : QString())
        .arg(QString::fromLatin1(QByteArray(reinterpret_cast<const char*>(f.data.data()), f.payloadSize()).toHex()));
}

}  // namespace

class TestCliRecordFormats : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString source_;
    QStringList expected_;

    Run record(const QString& out) {
        return cli({QStringLiteral("record"), QStringLiteral("replay://%1?speed=0").arg(source_), out,
                    QStringLiteral("--count"), QString::number(kFrames), QStringLiteral("--duration"),
                    QStringLiteral("30")});
    }

private slots:
    void initTestCase() {
        source_ = dir_.filePath(QStringLiteral("source.log"));
        QFile f(source_);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(kSource);
        f.close();
        QString error;
        for (const CanFrame& fr : readLog(source_, &error)) expected_ << describe(fr);
        QCOMPARE(expected_.size(), kFrames);
    }

    void recordsTheNamedFormat_data() {
        QTest::addColumn<QString>("extension");
        QTest::addColumn<QString>("format");  // what the content says (LogFormats::detectContent)
        QTest::newRow("log") << QStringLiteral("log") << QStringLiteral("candump");
        QTest::newRow("asc") << QStringLiteral("asc") << QStringLiteral("asc");
        QTest::newRow("blf") << QStringLiteral("blf") << QStringLiteral("blf");
        QTest::newRow("trc") << QStringLiteral("trc") << QStringLiteral("trc");
        QTest::newRow("pcapng") << QStringLiteral("pcapng") << QStringLiteral("pcap");
    }
    void recordsTheNamedFormat() {
        QFETCH(QString, extension);
        QFETCH(QString, format);
        const QString out = dir_.filePath(QStringLiteral("rec.%1").arg(extension));
        const Run r = record(out);
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QFile f(out);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(logio::LogFormats::detectContent(f.read(4096)), format);
        f.close();
        QString error;
        const std::vector<CanFrame> back = readLog(out, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QStringList got;
        for (const CanFrame& fr : back) got << describe(fr);
        QCOMPARE(got, expected_);
    }

    // RFC 4180 CSV: number,time,bus,id,ext,rtr,fd,dir,len,data,summary.
    void recordsCsv() {
        const QString out = dir_.filePath(QStringLiteral("rec.csv"));
        const Run r = record(out);
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QFile f(out);
        QVERIFY(f.open(QIODevice::ReadOnly | QIODevice::Text));
        QStringList lines = QString::fromUtf8(f.readAll()).split(u'\n', Qt::SkipEmptyParts);
        QVERIFY(!lines.isEmpty());
        QVERIFY2(lines.takeFirst().startsWith(QStringLiteral("number,time,bus,id,ext,rtr,fd,dir,len,data")),
                 qPrintable(lines.join(u'\n')));
        QCOMPARE(lines.size(), kFrames);
        QVERIFY2(lines[2].contains(QStringLiteral(",0x12345678,1,0,0,")) &&
                     lines[2].contains(QStringLiteral(",4,DE AD BE EF")),
                 qPrintable(lines[2]));
        QVERIFY2(lines[4].contains(QStringLiteral(",0x601,0,1,0,")), qPrintable(lines[4]));
    }

    void pcapngOpensInTshark() {
        const QString tshark = QStandardPaths::findExecutable(QStringLiteral("tshark"));
        if (tshark.isEmpty()) QSKIP("tshark is not installed");
        const QString out = dir_.filePath(QStringLiteral("shark.pcapng"));
        const Run r = record(out);
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QProcess ts;
        ts.start(tshark, {QStringLiteral("-r"), out, QStringLiteral("-T"), QStringLiteral("fields"),
                          QStringLiteral("-e"), QStringLiteral("can.id")});
        QVERIFY(ts.waitForFinished(60000));
        QCOMPARE(ts.exitCode(), 0);
        const QStringList ids = QString::fromUtf8(ts.readAllStandardOutput()).split(u'\n', Qt::SkipEmptyParts);
        QCOMPARE(ids.size(), kFrames);
        QCOMPARE(ids[2].toUInt(nullptr, 0), 0x12345678u);
    }

    // A third-party reader (python-can's can.BLFReader) sees the same frames.
    void blfReadByPythonCan() {
        const QString py = pythonWithCan(QStringLiteral("can"));
        if (py.isEmpty()) QSKIP("python3-can is not installed");
        const QString out = dir_.filePath(QStringLiteral("py.blf"));
        const Run r = record(out);
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QProcess p;
        p.start(py, {QStringLiteral("-c"),
                     QStringLiteral("import sys, can\n"
                                    "for m in can.BLFReader(sys.argv[1]):\n"
                                    "    print('%X%s%s#%s' % (m.arbitration_id, 'x' if m.is_extended_id else '', 'R' "
                                    "if m.is_remote_frame else '', bytes(m.data).hex()))"),
                     out});
        QVERIFY(p.waitForFinished(60000));
        QVERIFY2(p.exitCode() == 0, qPrintable(QString::fromUtf8(p.readAllStandardError())));
        const QStringList got = QString::fromUtf8(p.readAllStandardOutput()).split(u'\n', Qt::SkipEmptyParts);
        QStringList want;
        for (QString e : expected_) {
            const QString id = e.section(u'#', 0, 0).remove(u'x').remove(u'R');
            want << QStringLiteral("%1%2%3#%4")
                        .arg(QString::number(id.toUInt(nullptr, 16), 16).toUpper(),
                             e.section(u'#', 0, 0).contains(u'x') ? QStringLiteral("x") : QString(),
                             e.section(u'#', 0, 0).contains(u'R') ? QStringLiteral("R") : QString(),
                             e.section(u'#', 1));
        }
        QCOMPARE(got, want);
    }

    void unknownExtensionIsUsageError() {
        const QString out = dir_.filePath(QStringLiteral("rec.xyz"));
        const Run r = record(out);
        QCOMPARE(r.code, 2);
        QCOMPARE(r.err.count(u'\n'), 1);
        QVERIFY2(r.err.contains(QStringLiteral("rec.xyz")) && r.err.contains(QStringLiteral(".pcapng")),
                 qPrintable(r.err));
        QVERIFY(!QFile::exists(out));
    }
};

QTEST_GUILESS_MAIN(TestCliRecordFormats)
#include "test_cli_record_formats.moc"
