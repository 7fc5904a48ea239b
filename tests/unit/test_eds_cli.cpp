// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli eds check / eds dump, run as a user would.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include "tests/CliRun.h"

namespace {

const QString kQuirks = QStringLiteral(COSCOPE_SOURCE_DIR "/tests/data/eds/quirks.eds");

}  // namespace

class TestEdsCli : public QObject {
    Q_OBJECT
private slots:
    void checkUsableFile();
    void checkUnusableFile();
    void checkUsage();
    void dumpJson();
    void dumpText();
    void dumpBadArguments();
};

void TestEdsCli::checkUsableFile() {
    const Run r = cli({"eds", "check", kQuirks});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("quirks.eds:70: warning: duplicate key DefaultValue"), qPrintable(r.out));
    QVERIFY(r.out.contains("12 objects"));
}

void TestEdsCli::checkUnusableFile() {
    QTemporaryDir dir;
    QFile f(dir.filePath("empty.eds"));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("; nothing here\n");
    f.close();
    const Run r = cli({"eds", "check", kQuirks, f.fileName()});
    QCOMPARE(r.code, 1);
    QVERIFY(r.out.contains("empty.eds: error: no object could be read"));
    QVERIFY(r.err.startsWith("coscope-cli eds check: 1 of 2 files not usable"));
}

void TestEdsCli::checkUsage() {
    QCOMPARE(cli({"eds", "check"}).code, 2);
    QCOMPARE(cli({"eds", "check", "--help"}).code, 0);
}

void TestEdsCli::dumpJson() {
    const Run r = cli({"eds", "dump", kQuirks, "--node-id", "3", "--format", "json"});
    QCOMPARE(r.code, 0);
    const QJsonArray list = QJsonDocument::fromJson(r.out.toUtf8()).array();
    QVERIFY(list.size() > 20);
    bool found = false;
    for (const QJsonValue& v : list) {
        const QJsonObject e = v.toObject();
        for (const char* k : {"index", "sub", "name", "type", "access", "pdo", "default", "value", "low", "high"})
            QVERIFY2(e.contains(k), k);
        if (e["index"].toInt() == 0x2000 && e["sub"].toInt() == 0) {
            found = true;
            QCOMPARE(e["default"].toInt(), 0x183);  // $NODEID+0x180 with --node-id 3
            QCOMPARE(e["type"].toString(), QString("UNSIGNED32"));
            QCOMPARE(e["access"].toString(), QString("rw"));
            QCOMPARE(e["pdo"].toBool(), true);
            QCOMPARE(e["low"].toInt(), 0x100);
            QCOMPARE(e["high"].toInt(), 0x7FF);
        }
        if (e["index"].toInt() == 0x1017) QCOMPARE(e["value"].toInt(), 1000);  // ParameterValue
    }
    QVERIFY(found);
}

void TestEdsCli::dumpText() {
    const Run r = cli({"eds", "dump", kQuirks});
    QCOMPARE(r.code, 0);
    QVERIFY2(r.out.contains("2000:00"), qPrintable(r.out.left(400)));
    QVERIFY(r.out.contains("Heartbeat of node 1"));
    QVERIFY(r.out.contains("0x00000185"));  // node-ID 5 from the file's commissioning section
}

void TestEdsCli::dumpBadArguments() {
    QCOMPARE(cli({"eds", "dump", kQuirks, "--format", "xml"}).code, 2);
    QCOMPARE(cli({"eds", "dump", kQuirks, "--node-id", "200"}).code, 2);
    const Run r = cli({"eds", "dump", "no-such-dictionary"});
    QCOMPARE(r.code, 1);
    QVERIFY(r.err.startsWith("coscope-cli eds dump: "));
}

QTEST_GUILESS_MAIN(TestEdsCli)
#include "test_eds_cli.moc"
