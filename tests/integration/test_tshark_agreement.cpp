// SPDX-License-Identifier: GPL-3.0-or-later
// decode --format jsonl agrees with tshark's CANopen dissector on NMT, SYNC, EMCY, heartbeat,
// LSS and single-frame SDO fields of the same pcapng (skipped when tshark is not installed).
#include "core/logio/PcapLog.h"
#include "tests/CliRun.h"

#include <QIODevice>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace coscope;

class TsharkAgreement : public QObject {
    Q_OBJECT
private slots:
    void fieldsAgree() {
        const QString tshark = QStandardPaths::findExecutable(QStringLiteral("tshark"));
        if (tshark.isEmpty()) QSKIP("tshark is not installed");
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("agree.pcapng"));
        {
            logio::PcapngWriter w;
            QVERIFY(w.open(path));
            int64_t t = 1000000000;
            auto put = [&](uint32_t id, std::initializer_list<uint8_t> b) {
                CanFrame f = CanFrame::classic(id, b);
                f.timestampNs = (t += 1000000);
                w.write(f);
            };
            put(0x000, {0x01, 0x05});
            put(0x000, {0x81, 0x00});
            put(0x000, {0x80, 0x7F});
            put(0x080, {});
            put(0x080, {0x11});
            put(0x081, {0x05, 0x73, 0x81, 0x11, 0x00, 0x00, 0x00, 0x00});  // Delta AL011 (extract §8.2)
            put(0x085, {0x10, 0x23, 0x05, 1, 2, 3, 4, 5});
            put(0x701, {0x00});
            put(0x705, {0x7F});
            put(0x705, {0x05});
            put(0x7E5, {0x04, 0x01, 0, 0, 0, 0, 0, 0});
            put(0x7E5, {0x11, 0x07, 0, 0, 0, 0, 0, 0});
            put(0x7E4, {0x11, 0x00, 0, 0, 0, 0, 0, 0});
            put(0x605, {0x2B, 0x40, 0x60, 0x00, 0x06, 0, 0, 0});
            put(0x585, {0x60, 0x40, 0x60, 0x00, 0, 0, 0, 0});
            put(0x605, {0x40, 0x41, 0x60, 0x00, 0, 0, 0, 0});
            put(0x585, {0x80, 0x41, 0x60, 0x00, 0x02, 0x00, 0x01, 0x06});
            put(0x601, {0x23, 0x00, 0x18, 0x01, 0x81, 0x01, 0x00, 0x80});
            QVERIFY(w.close());
        }
        const QStringList tsFields = {
            "frame.number",         "canopen.nmt_ctrl.cd", "canopen.nmt_ctrl.node_id", "canopen.sync.counter",
            "canopen.em.err_code",  "canopen.em.err_reg",  "canopen.nmt_guard.state",  "canopen.lss.cs",
            "canopen.sdo.main_idx", "canopen.sdo.sub_idx", "canopen.sdo.abort_code"};
        const QStringList ours = {"",          "nmt.cs", "nmt.node",  "sync.counter", "emcy.code", "emcy.reg",
                                  "nmt.state", "lss.cs", "sdo.index", "sdo.sub",      "sdo.abort"};
        QStringList args = {QStringLiteral("-r"), path,
                            QStringLiteral("-d"), QStringLiteral("can.subdissector,canopen"),
                            QStringLiteral("-T"), QStringLiteral("fields"),
                            QStringLiteral("-E"), QStringLiteral("separator=;")};
        for (const QString& f : tsFields) args << QStringLiteral("-e") << f;
        QProcess ts;
        ts.start(tshark, args);
        QVERIFY(ts.waitForFinished(120000));
        const QList<QByteArray> tsLines = ts.readAllStandardOutput().trimmed().split('\n');
        const Run decoded =
            cli({QStringLiteral("decode"), path, QStringLiteral("--format"), QStringLiteral("jsonl")}, 60000);
        QList<QJsonObject> frames;
        for (const QByteArray& l : decoded.out.toUtf8().trimmed().split('\n')) {
            const QJsonObject o = QJsonDocument::fromJson(l).object();
            if (!o.contains(QStringLiteral("record"))) frames << o;
        }
        QCOMPARE(frames.size(), 18);
        QCOMPARE(tsLines.size(), frames.size());
        int compared = 0;
        for (int i = 0; i < frames.size(); ++i) {
            const QStringList cols = QString::fromUtf8(tsLines[i]).split(u';');
            const QJsonObject fields = frames[i].value(QStringLiteral("fields")).toObject();
            for (int k = 1; k < tsFields.size(); ++k) {
                const QString tv = cols.value(k);
                if (tv.isEmpty()) {
                    QVERIFY2(!fields.contains(ours[k]) || ours[k] == QLatin1String("nmt.node"),
                             qPrintable(QStringLiteral("frame %1: we have %2, tshark not").arg(i + 1).arg(ours[k])));
                    continue;
                }
                bool ok = false;
                const qint64 expected = tv.toLongLong(&ok, 0);
                QVERIFY(ok);
                QVERIFY2(fields.contains(ours[k]),
                         qPrintable(QStringLiteral("frame %1: tshark has %2, we not").arg(i + 1).arg(tsFields[k])));
                QCOMPARE(fields.value(ours[k]).toInteger(), expected);
                ++compared;
            }
        }
        QVERIFY(compared >= 25);
    }
};

QTEST_GUILESS_MAIN(TsharkAgreement)
#include "test_tshark_agreement.moc"
