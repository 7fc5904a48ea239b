// SPDX-License-Identifier: GPL-3.0-or-later
// Devices without a dictionary: coscope-cli decode --signal (raw signals in the jsonl
// pdo.signals and the text) and pdo dbc (the PDO layout learnt from the log's SDO writes plus
// the raw signals as a DBC file, checked against the DBC grammar and decoded again).
#include "CliRun.h"
#include "DbcReader.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

namespace {
// Nodes 16 and 32, no dictionary: node 16's TPDO1 mapping is written by SDO in the log
// (1A00h:01 = 6041h:00/16, :02 = 6064h:00/32); node 32 sends TPDO2 nobody described.
const char* kLog =
    "(1.000000) can0 710#00\n"
    "(1.001000) can0 720#00\n"
    "(1.010000) can0 610#2F001A0000000000\n"
    "(1.011000) can0 590#60001A0000000000\n"
    "(1.012000) can0 610#23001A0110004160\n"
    "(1.013000) can0 590#60001A0100000000\n"
    "(1.014000) can0 610#23001A0220006460\n"
    "(1.015000) can0 590#60001A0200000000\n"
    "(1.016000) can0 610#2F001A0002000000\n"
    "(1.017000) can0 590#60001A0000000000\n"
    "(1.100000) can0 190#3716A0860100\n"
    "(1.200000) can0 190#37026079FEFF\n"
    "(1.300000) can0 2A0#FF38C80000000000\n"
    "(1.400000) can0 2A0#00640A0000000000\n"
    "(1.500000) can0 18FF0010#0000C03F\n";

const QStringList kSignals = {QStringLiteral("--signal"), QStringLiteral("speed=0x2A0:7:16:s@0:0.5:0:rpm"),
                              QStringLiteral("--signal"), QStringLiteral("level=0x2A0:16:8:u"),
                              QStringLiteral("--signal"), QStringLiteral("temp=0x18FF0010:0:32:f")};

std::vector<QJsonObject> lines(const QString& out) {
    std::vector<QJsonObject> v;
    for (const QString& l : out.split(u'\n', Qt::SkipEmptyParts))
        v.push_back(QJsonDocument::fromJson(l.toUtf8()).object());
    return v;
}
}  // namespace

class RawSignalCli : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        log_ = dir_.filePath(QStringLiteral("nodict.log"));
        QFile f(log_);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(kLog);
    }

    void decodeJsonl() {
        const Run r = cli(QStringList{QStringLiteral("decode"), log_, QStringLiteral("--format"),
                                      QStringLiteral("jsonl"), QStringLiteral("--no-identity")} +
                          kSignals);
        QCOMPARE(r.code, 0);
        std::map<QString, std::vector<QJsonObject>> byName;  // raw signals only
        for (const QJsonObject& o : lines(r.out))
            for (const QJsonValue& s :
                 o.value(QStringLiteral("fields")).toObject().value(QStringLiteral("pdo.signals")).toArray())
                if (s.toObject().value(QStringLiteral("obj")).isNull())
                    byName[s.toObject().value(QStringLiteral("name")).toString()].push_back(s.toObject());
        QCOMPARE(byName[QStringLiteral("speed")].size(), size_t(2));
        QCOMPARE(byName[QStringLiteral("speed")][0].value(QStringLiteral("value")).toDouble(),
                 -100.0);  // FF38h = -200 x 0.5
        QCOMPARE(byName[QStringLiteral("speed")][0].value(QStringLiteral("unit")).toString(), QStringLiteral("rpm"));
        QCOMPARE(byName[QStringLiteral("speed")][1].value(QStringLiteral("value")).toDouble(), 50.0);  // 0064h x 0.5
        QCOMPARE(byName[QStringLiteral("level")][0].value(QStringLiteral("value")).toInt(), 200);
        QVERIFY(byName[QStringLiteral("level")][0].value(QStringLiteral("unit")).isNull());
        QCOMPARE(byName[QStringLiteral("temp")][0].value(QStringLiteral("value")).toDouble(), 1.5);
    }

    void decodeText() {
        Run r = cli(QStringList{QStringLiteral("decode"), log_, QStringLiteral("--no-identity")} + kSignals);
        QCOMPARE(r.code, 0);
        QVERIFY2(r.out.contains(QStringLiteral("speed = -100 rpm, level = 200")), qPrintable(r.out));
        r = cli({QStringLiteral("decode"), log_, QStringLiteral("--signal"), QStringLiteral("x=0x2A0:0:33:f")});
        QCOMPARE(r.code, 2);
        QVERIFY(r.err.startsWith(QStringLiteral("coscope-cli decode: ")));
        r = cli({QStringLiteral("decode"), QStringLiteral("--help")});
        QVERIFY(r.out.contains(QStringLiteral("@0")));
    }

    void dbcExport() {
        const QString out = dir_.filePath(QStringLiteral("layout.dbc"));
        const Run r =
            cli(QStringList{QStringLiteral("pdo"), QStringLiteral("dbc"), log_, out, QStringLiteral("--no-identity")} +
                kSignals);
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QFile f(out);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const dbc::File file = dbc::parse(f.readAll());
        QVERIFY2(file.errors.isEmpty(), qPrintable(file.errors.join(u'\n')));
        QVERIFY(file.nodes.contains(QStringLiteral("Node16")));
        QVERIFY(file.messages.count(0x190));
        const dbc::Message& t1 = file.messages.at(0x190);
        QCOMPARE(t1.name, QStringLiteral("TPDO1_node16"));
        QCOMPARE(t1.dlc, 6);
        QCOMPARE(t1.transmitter, QStringLiteral("Node16"));
        QCOMPARE(int(t1.sigs.size()), 2);
        QCOMPARE(t1.sigs[0].start, 0);
        QCOMPARE(t1.sigs[0].length, 16);
        QVERIFY(!t1.sigs[0].isSigned && t1.sigs[0].intel);
        QVERIFY(t1.sigs[0].comment.startsWith(QStringLiteral("6041:00")));
        QCOMPARE(t1.sigs[1].start, 16);
        QCOMPARE(t1.sigs[1].length, 32);
        QVERIFY(t1.sigs[1].isSigned);
        QVERIFY(t1.sigs[1].comment.startsWith(QStringLiteral("6064:00")));
        QVERIFY(file.messages.count(0x2A0));
        const dbc::Signal* speed = file.messages.at(0x2A0).find(QStringLiteral("speed"));
        QVERIFY(speed && !speed->intel && speed->isSigned && speed->factor == 0.5 &&
                speed->unit == QStringLiteral("rpm"));
        QVERIFY(file.messages.count(0x18FF0010u | 0x80000000u));
        QCOMPARE(file.messages.at(0x18FF0010u | 0x80000000u).sigs.at(0).valType, 1);

        // Every signal CoScope decodes reads the same through the DBC.
        const Run dec = cli(QStringList{QStringLiteral("decode"), log_, QStringLiteral("--format"),
                                        QStringLiteral("jsonl"), QStringLiteral("--no-identity")} +
                            kSignals);
        int compared = 0;
        for (const QJsonObject& o : lines(dec.out)) {
            const QJsonArray sigs =
                o.value(QStringLiteral("fields")).toObject().value(QStringLiteral("pdo.signals")).toArray();
            if (sigs.isEmpty()) continue;
            const uint32_t id = o.value(QStringLiteral("id")).toInteger() |
                                (o.value(QStringLiteral("ext")).toBool() ? 0x80000000u : 0u);
            QVERIFY2(file.messages.count(id), qPrintable(QString::number(id, 16)));
            const dbc::Message& m = file.messages.at(id);
            const QByteArray data = QByteArray::fromHex(o.value(QStringLiteral("data")).toString().toLatin1());
            for (const QJsonValue& sv : sigs) {
                const QJsonObject s = sv.toObject();
                const QString name = s.value(QStringLiteral("name")).toString().replace(u' ', u'_');
                const dbc::Signal* ds = m.find(name);
                QVERIFY2(ds, qPrintable(name));
                QCOMPARE(dbc::decode(*ds, data).value(), s.value(QStringLiteral("value")).toDouble());
                ++compared;
            }
        }
        QCOMPARE(compared, 2 * 2 + 2 * 2 + 1);
    }

    // A bus: the nodes' PDOs read over SDO as `pdo show` reads them (the virtual drive's TPDO1
    // at 180h + node-ID carries the statusword first).
    void dbcFromBus() {
        const QString out = dir_.filePath(QStringLiteral("bus.dbc"));
        const Run r =
            cli({QStringLiteral("pdo"), QStringLiteral("dbc"), QStringLiteral("sim://?nodes=3:generic-cia402"), out,
                 QStringLiteral("--node"), QStringLiteral("3")});
        QVERIFY2(r.code == 0, qPrintable(r.err + r.out));
        const Run show = cli({QStringLiteral("pdo"), QStringLiteral("show"),
                              QStringLiteral("sim://?nodes=3:generic-cia402"), QStringLiteral("3")});
        QFile f(out);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const dbc::File file = dbc::parse(f.readAll());
        QVERIFY2(file.errors.isEmpty(), qPrintable(file.errors.join(u'\n')));
        QVERIFY(file.nodes.contains(QStringLiteral("Node3")));
        // Every mapped object `pdo show` lists is a signal of its PDO's message.
        int objects = 0;
        bool valid = false;
        for (const QString& line : show.out.split(u'\n')) {
            const QString t = line.trimmed();
            if (!line.startsWith(u' ')) valid = !line.contains(QStringLiteral("not valid"));
            if (!valid || !line.startsWith(QStringLiteral("    ")) || t.size() < 7 || t[4] != u':' ||
                t.startsWith(QStringLiteral("000")))
                continue;
            bool found = false;
            for (const auto& [id, m] : file.messages)
                for (const dbc::Signal& s : m.sigs) found |= s.comment.startsWith(t.left(7));
            QVERIFY2(found, qPrintable(t));
            ++objects;
        }
        QVERIFY2(objects > 0, qPrintable(show.out));
    }

    void dbcErrors() {
        Run r = cli({QStringLiteral("pdo"), QStringLiteral("dbc"), dir_.filePath(QStringLiteral("missing.log")),
                     dir_.filePath(QStringLiteral("x.dbc"))});
        QCOMPARE(r.code, 1);
        r = cli({QStringLiteral("pdo"), QStringLiteral("dbc"), log_});
        QCOMPARE(r.code, 2);
    }

private:
    QTemporaryDir dir_;
    QString log_;
};

QTEST_GUILESS_MAIN(RawSignalCli)
#include "test_raw_signal_cli.moc"
