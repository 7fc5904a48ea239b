// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli stats as the network health report (issue 15) on a crafted candump log: node 15
// reboots twice, node 1 raises EMCY 2310h, node 42 answers SDO slowly and leaves one request
// unanswered, node 2's heartbeat stops; --format text, json and html.
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include "tests/CliRun.h"

class StatsHealthCli : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString log_;

    static QString line(double t, const char* id, const char* data) {
        return QStringLiteral("(%1) can0 %2#%3\n").arg(t, 0, 'f', 6).arg(QLatin1String(id), QLatin1String(data));
    }

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        log_ = dir_.filePath(QStringLiteral("machine.log"));
        QString s;
        s += line(0.0, "70F", "00") + line(0.0, "701", "00") + line(0.0, "702", "00") + line(0.0, "72A", "00");
        s += line(0.01, "000", "0100");
        // Heartbeats every 100 ms for 10 s; node 2 stops after 3 s; node 15 reboots at 4 s and 7 s.
        for (int i = 1; i <= 100; ++i) {
            const double t = i * 0.1;
            s += line(t, "701", "05");
            if (t <= 3.0) s += line(t, "702", "05");
            s += line(t, "72A", "05");
            s += line(t, "70F", (i == 40 || i == 70) ? "00" : "05");
            s += line(t + 0.001, "080", "");
            s += line(t + 0.002, "181", "0102030405060708");
        }
        // EMCY 2310h (continuous over-current) from node 1 at 5 s, reset at 6 s.
        s += line(5.0, "081", "1023020000000000") + line(6.0, "081", "0000000000000000");
        // SDO to node 42: answered in 2 ms, 5 ms and 180 ms, then one request left unanswered.
        s += line(1.0, "62A", "4000100000000000") + line(1.002, "5AA", "4300100092010200");
        s += line(2.0, "62A", "4000100000000000") + line(2.005, "5AA", "4300100092010200");
        s += line(3.0, "62A", "4000100000000000") + line(3.180, "5AA", "4300100092010200");
        s += line(8.0, "62A", "4018100100000000");
        QStringList lines = s.split(u'\n', Qt::SkipEmptyParts);
        std::stable_sort(lines.begin(), lines.end(), [](const QString& a, const QString& b) {
            return a.mid(1, 12).toDouble() < b.mid(1, 12).toDouble();
        });
        QFile f(log_);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(lines.join(u'\n').toUtf8() + '\n');
    }

    void text() {
        const Run r = cli({QStringLiteral("stats"), log_});
        QCOMPARE(r.code, 0);
        const QString& o = r.out;
        // The verdict first (issue 37), then the findings, the worst first.
        QVERIFY2(
            o.startsWith(QStringLiteral("Problems found: 2 critical, 2 errors, 1 warning\n\nFindings:\n  [critical]")),
            qPrintable(o));
        QVERIFY2(
            o.contains(QStringLiteral(
                "[critical] nmt.reset, node 15: Node 15 booted up 2 time(s) without an NMT reset command before it.")),
            qPrintable(o));
        // Where: count, first and last time, the frames as the trace numbers them (No., in the
        // log's line order): 5 lines at 0 s, then per 100 ms step i 701, 702 (i < 30), 72A, 70F,
        // 080, 181; 70F 00h of step 40 is line 5 + 39 * 5 + 29 + 4 = 233, of step 70 line 383.
        QVERIFY2(o.contains(QStringLiteral("2 times, 4.000 s .. 7.000 s; frames 233, 383\n")), qPrintable(o));
        QVERIFY2(o.contains(QStringLiteral("heartbeat.stopped, node 2: Node 2's heartbeat stopped")), qPrintable(o));
        QVERIFY2(o.contains(QStringLiteral(
                     "emcy.fault, node 1: Node 1 reported EMCY 2310h (Continuous over-current) 1 time(s).")),
                 qPrintable(o));
        QVERIFY2(o.contains(QStringLiteral("once, at 5.000 s; frame ")), qPrintable(o));
        QVERIFY2(o.contains(QStringLiteral(
                     "sdo.slow, node 42: Node 42 answered SDO requests slowly: 180 ms at the 99th percentile")),
                 qPrintable(o));
        QVERIFY2(o.contains(QStringLiteral("sdo.timeout, node 42: Node 42 left 1 SDO request(s) unanswered")),
                 qPrintable(o));
        QVERIFY2(o.contains(QStringLiteral("      Why: ")) && o.contains(QStringLiteral(" Check: ")), qPrintable(o));
        QVERIFY(o.indexOf(QStringLiteral("nmt.reset")) < o.indexOf(QStringLiteral("sdo.slow")));
        QVERIFY(o.indexOf(QStringLiteral("sdo.slow")) < o.indexOf(QStringLiteral("Nodes (only those seen)")));
        // Each node's story after the findings: node 1 faulted (EMCY) and was reset.
        QVERIFY2(o.contains(QStringLiteral("  node 1: heartbeat 100 ms, Operational; recovered\n")), qPrintable(o));
        QVERIFY2(
            o.contains(QStringLiteral("  node 2: heartbeat 100 ms, Operational; not recovered (heartbeat stopped)\n")),
            qPrintable(o));
        QVERIFY2(o.contains(QStringLiteral("EMCY 2310h Continuous over-current")), qPrintable(o));
        QVERIFY(o.indexOf(QStringLiteral("Nodes (only those seen)")) <
                o.indexOf(QStringLiteral("Heartbeat / guarding")));
        QVERIFY(o.contains(QStringLiteral("load over time")));
        QVERIFY(!o.contains(QStringLiteral("second      1")));
    }

    void json() {
        const Run r = cli({QStringLiteral("stats"), log_, QStringLiteral("--format"), QStringLiteral("json")});
        QCOMPARE(r.code, 0);
        QJsonParseError e;
        const QJsonObject o = QJsonDocument::fromJson(r.out.toUtf8(), &e).object();
        QCOMPARE(e.error, QJsonParseError::NoError);
        for (const char* k : {"findings", "nodes", "pdos", "bus"}) QVERIFY2(o.contains(QLatin1String(k)), k);
        QMap<int, QJsonObject> nodes;
        for (const auto& v : o[QStringLiteral("nodes")].toArray())
            nodes[v.toObject()[QStringLiteral("node")].toInt()] = v.toObject();
        const QJsonObject n1 = nodes[1], n2 = nodes[2], n15 = nodes[15], n42 = nodes[42];
        QCOMPARE(n15[QStringLiteral("nmt")].toObject()[QStringLiteral("resets")].toInt(), 2);
        QCOMPARE(n15[QStringLiteral("nmt")].toObject()[QStringLiteral("boot_ups")].toInt(), 3);
        QCOMPARE(n1[QStringLiteral("heartbeat")].toObject()[QStringLiteral("count")].toInt(), 101);
        QCOMPARE(n1[QStringLiteral("heartbeat")].toObject()[QStringLiteral("period_ms")].toDouble(), 100.0);
        QCOMPARE(n1[QStringLiteral("emcy")].toObject()[QStringLiteral("count")].toInt(), 2);
        QCOMPARE(n1[QStringLiteral("emcy")].toObject()[QStringLiteral("resets")].toInt(), 1);
        QCOMPARE(n2[QStringLiteral("heartbeat")].toObject()[QStringLiteral("silent_now")].toBool(), true);
        const QJsonObject sdo = n42[QStringLiteral("sdo")].toObject();
        QCOMPARE(sdo[QStringLiteral("response_max_ms")].toDouble(), 180.0);
        QCOMPARE(sdo[QStringLiteral("response_min_ms")].toDouble(), 2.0);
        QCOMPARE(sdo[QStringLiteral("timeouts")].toInt(), 1);
        const QJsonArray pdos = o[QStringLiteral("pdos")].toArray();
        QCOMPARE(pdos.size(), 1);
        QCOMPARE(pdos[0].toObject()[QStringLiteral("cob_id")].toInt(), 0x181);
        QVERIFY(qAbs(pdos[0].toObject()[QStringLiteral("rate_hz")].toDouble() - 10.0) < 0.01);
        const QJsonObject bus = o[QStringLiteral("bus")].toObject();
        QCOMPARE(bus[QStringLiteral("sync")].toObject()[QStringLiteral("count")].toInt(), 100);
        QVERIFY(bus[QStringLiteral("load_over_time")].toArray().size() <= 60);
        QVERIFY(bus[QStringLiteral("load_peak_pct")].toDouble() > 0);
        QCOMPARE(o[QStringLiteral("findings")].toArray().at(0).toObject()[QStringLiteral("severity")].toString(),
                 QStringLiteral("critical"));
        // Issue 37: the verdict, and per finding its rule, count, times, frames and sentences.
        QCOMPARE(o[QStringLiteral("verdict")].toString(),
                 QStringLiteral("Problems found: 2 critical, 2 errors, 1 warning"));
        QJsonObject reset;
        for (const auto& v : o[QStringLiteral("findings")].toArray())
            if (v.toObject()[QStringLiteral("rule")].toString() == QLatin1String("nmt.reset")) reset = v.toObject();
        QCOMPARE(reset[QStringLiteral("node")].toInt(), 15);
        QCOMPARE(reset[QStringLiteral("count")].toInt(), 2);
        QCOMPARE(reset[QStringLiteral("first")].toDouble(), 4.0);
        QCOMPARE(reset[QStringLiteral("last")].toDouble(), 7.0);
        QCOMPARE(reset[QStringLiteral("frames")].toArray().size(), 2);
        for (const char* k : {"what", "why", "check"}) QVERIFY2(!reset[QLatin1String(k)].toString().isEmpty(), k);
        QVERIFY(!n1[QStringLiteral("story")].toArray().isEmpty());
        QCOMPARE(n1[QStringLiteral("outcome")].toString(), QStringLiteral("recovered"));
    }

    void html() {
        const Run r = cli({QStringLiteral("stats"), log_, QStringLiteral("--format"), QStringLiteral("html")});
        QCOMPARE(r.code, 0);
        const QString& h = r.out;
        QVERIFY(h.startsWith(QStringLiteral("<!DOCTYPE html>")));
        QVERIFY(h.contains(QStringLiteral("<svg")));
        QVERIFY2(h.contains(QStringLiteral("<b>Problems found: 2 critical, 2 errors, 1 warning</b>")), qPrintable(h));
        QVERIFY(h.contains(QStringLiteral("Node 15 booted up 2 time(s) without an NMT reset command before it.")));
        QVERIFY(h.contains(QStringLiteral("Why: ")) && h.contains(QStringLiteral("Check: ")));
        // Node 15's boot-ups as visible frame references, each with its own id.
        QVERIFY2(h.contains(QRegularExpression(QStringLiteral(
                     "frames <a class='fr' id='f(\\d+)-0'>#233</a>, <a class='fr' id='f\\1-1'>#383</a>"))),
                 qPrintable(h));
        QVERIFY(h.trimmed().endsWith(QStringLiteral("</html>")));
        // Self-contained: nothing to fetch.
        QVERIFY(!h.contains(QStringLiteral("src=")));
        QVERIFY(!h.contains(QStringLiteral("href=")));
        QVERIFY(!h.contains(QStringLiteral("<script")));
    }

    // Issue 37: a 17-minute log of 5 drives (heartbeat 1 s, TPDO1 every 100 ms, SDO reads now
    // and then, two with an abort, node 3 faults and is reset twice, node 4 reboots once) reads
    // as a short report: under 150 lines of text, the verdict first, and each node's story.
    void longLogStaysShort() {
        const QString path = dir_.filePath(QStringLiteral("17min.log"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        QByteArray out;
        auto put = [&](double t, const char* id, const char* data) { out += line(t, id, data).toUtf8(); };
        for (int n = 1; n <= 5; ++n) put(0.001 * n, QStringLiteral("70%1").arg(n).toLatin1().constData(), "00");
        put(0.5, "000", "0100");
        for (int step = 1; step <= 10200; ++step) {  // 1020 s in 100 ms steps
            const double t = step * 0.1;
            for (int n = 1; n <= 5; ++n) {
                const QByteArray cob = QByteArray::number(0x180 + n, 16).toUpper();
                put(t + 0.001 * n, cob.constData(), "3706000000000000");
                if (step % 10 == 0)
                    put(t + 0.0005 * n, QByteArray::number(0x700 + n, 16).toUpper().constData(),
                        (n == 4 && step == 6000) ? "00" : "05");
            }
            if (step % 600 == 0) {  // an SDO read of node 2 every minute; two of them aborted
                put(t + 0.02, "602", "4018100100000000");
                put(t + 0.022, "582", step == 1200 || step == 4800 ? "8018100100000206" : "4318100192010000");
            }
            if (step == 3000 || step == 7000) put(t + 0.03, "083", "1023020000000000");  // over-current
            if (step == 3100 || step == 7100) put(t + 0.03, "083", "0000000000000000");  // reset
        }
        f.write(out);
        f.close();
        const Run r = cli({QStringLiteral("stats"), path});
        QCOMPARE(r.code, 0);
        const QStringList lines = r.out.split(u'\n');
        QVERIFY2(lines.size() < 150, qPrintable(QStringLiteral("%1 lines:\n%2").arg(lines.size()).arg(r.out)));
        QVERIFY2(lines.front().startsWith(QStringLiteral("Problems found: 1 critical, 1 error, 1 warning")),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("  node 3: heartbeat 1000 ms, Operational; recovered\n")),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("  node 4: heartbeat 1000 ms, Operational; recovered\n")),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral(
                     "emcy.fault, node 3: Node 3 reported EMCY 2310h (Continuous over-current) 2 time(s).")),
                 qPrintable(r.out));
        QVERIFY2(r.out.contains(QStringLiteral("sdo.abort, node 2: Node 2 aborted 2 SDO transfer(s) with 06020000h")),
                 qPrintable(r.out));
    }

    void usage() {
        QCOMPARE(cli({QStringLiteral("stats"), log_, QStringLiteral("--format"), QStringLiteral("xml")}).code, 2);
    }
};

QTEST_GUILESS_MAIN(StatsHealthCli)
#include "test_stats_health_cli.moc"
