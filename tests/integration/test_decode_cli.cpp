// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli decode / stats on a small candump log: formats, --dict, --filter, exit codes.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include "tests/CliRun.h"

class DecodeCli : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString log_;
private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        log_ = dir_.filePath(QStringLiteral("drive.log"));
        QFile f(log_);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(
            "(0.000000) can0 701#00\n"
            "(0.001000) can0 000#0101\n"
            "(0.002000) can0 080#\n"
            "(0.003000) can0 601#2B40600006000000\n"
            "(0.004000) can0 581#6040600000000000\n"
            "(0.005000) can0 081#0573011100000000\n"
            "(0.006000) can0 181#371600881300\n"
            "(0.007000) can0 581#8041600002000106\n"
            "(1.500000) can0 702#05\n");
    }

    void jsonlContract() {
        const Run r = cli({QStringLiteral("decode"), log_, QStringLiteral("--format"), QStringLiteral("jsonl"),
                           QStringLiteral("--dict"), QStringLiteral("1=delta-asda-a2")});
        QCOMPARE(r.code, 0);
        const QList<QByteArray> lines = r.out.toUtf8().trimmed().split('\n');
        QCOMPARE(lines.size(), 11);  // 9 frames + 2 SDO transfer records
        QJsonObject first = QJsonDocument::fromJson(lines[0]).object();
        for (const char* k :
             {"t", "bus", "id", "ext", "rtr", "fd", "len", "data", "service", "node", "summary", "fields"})
            QVERIFY2(first.contains(QLatin1String(k)), k);
        QCOMPARE(first.value("service").toString(), QStringLiteral("NMT_EC"));
        QCOMPARE(first.value("fields").toObject().value("nmt.state").toInt(), 0);
        const QJsonObject sdo = QJsonDocument::fromJson(lines[3]).object();
        QCOMPARE(sdo.value("fields").toObject().value("sdo.index").toInt(), 0x6040);
        QCOMPARE(sdo.value("fields").toObject().value("sdo.cs").toString(),
                 QStringLiteral("initiate download request"));
        const QJsonObject rec = QJsonDocument::fromJson(lines[5]).object();
        QCOMPARE(rec.value("record").toString(), QStringLiteral("sdo_transfer"));
        QCOMPARE(rec.value("object").toString(), QStringLiteral("6040:00"));
        QCOMPARE(rec.value("status").toString(), QStringLiteral("ok"));
        QCOMPARE(rec.value("data").toString(), QStringLiteral("0600"));
        const QJsonObject emcy = QJsonDocument::fromJson(lines[6]).object();
        QVERIFY(emcy.value("fields").toObject().value("emcy.vendor").toString().startsWith(QStringLiteral("AL011")));
        const QJsonObject abortRec = QJsonDocument::fromJson(lines[9]).object();
        QCOMPARE(abortRec.value("status").toString(), QStringLiteral("aborted"));
        QCOMPARE(abortRec.value("abort").toInteger(), 0x06010002);
    }

    void filters() {
        Run r = cli({QStringLiteral("decode"), log_, QStringLiteral("--format"), QStringLiteral("jsonl"),
                     QStringLiteral("--filter"), QStringLiteral("service=SDO")});
        QCOMPARE(r.code, 0);
        for (const QByteArray& l : r.out.toUtf8().trimmed().split('\n')) {
            const QJsonObject o = QJsonDocument::fromJson(l).object();
            QVERIFY(o.contains("record") || o.value("service").toString().startsWith(QStringLiteral("SDO")));
        }
        r = cli({QStringLiteral("decode"), log_, QStringLiteral("--format"), QStringLiteral("csv"),
                 QStringLiteral("--filter"), QStringLiteral("node=2")});
        QCOMPARE(r.out.trimmed().split('\n').size(), 2);  // header + 702h
        r = cli(
            {QStringLiteral("decode"), log_, QStringLiteral("--filter"), QStringLiteral("id=0x080-0x0FF && node!=1")});
        QCOMPARE(r.out.trimmed().split('\n').size(), 1);  // SYNC only (EMCY is node 1)
        r = cli({QStringLiteral("decode"), log_, QStringLiteral("--filter"), QStringLiteral("colour=red")});
        QCOMPARE(r.code, 2);
        QVERIFY(r.err.startsWith("coscope-cli decode: "));
    }

    void errors() {
        Run r = cli({QStringLiteral("decode"), dir_.filePath(QStringLiteral("missing.log"))});
        QCOMPARE(r.code, 1);
        QCOMPARE(r.err.count('\n'), 1);
        r = cli({QStringLiteral("decode"), log_, QStringLiteral("--dict"), QStringLiteral("1=no-such-drive")});
        QCOMPARE(r.code, 1);
        r = cli({QStringLiteral("decode"), log_, QStringLiteral("--format"), QStringLiteral("xml")});
        QCOMPARE(r.code, 2);
        r = cli({QStringLiteral("decode"), log_, QStringLiteral("--dict"), QStringLiteral("300=aimotor")});
        QCOMPARE(r.code, 2);
    }

    void stats() {
        const Run r = cli({QStringLiteral("stats"), log_});
        QCOMPARE(r.code, 0);
        const QString& s = r.out;
        QVERIFY2(s.contains(QStringLiteral("Frames: 9")), qPrintable(s));
        QVERIFY(s.contains(QStringLiteral("SDO transfers: 2 (ok 1, aborted 1")));
        QVERIFY(s.contains(QStringLiteral("EMCY: 1")));
        QVERIFY(s.contains(QStringLiteral("node   2  Operational")));
        // The per-second load table is behind --per-second (issue 15).
        QVERIFY(!s.contains(QStringLiteral("second      1")));
        const Run p = cli({QStringLiteral("stats"), log_, QStringLiteral("--per-second")});
        QCOMPARE(p.code, 0);
        QVERIFY2(p.out.contains(QStringLiteral("second      1")), qPrintable(p.out));
        QCOMPARE(cli({QStringLiteral("stats")}).code, 2);
    }
};

QTEST_GUILESS_MAIN(DecodeCli)
#include "test_decode_cli.moc"
