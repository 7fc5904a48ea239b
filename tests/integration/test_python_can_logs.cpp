// SPDX-License-Identifier: GPL-3.0-or-later
// Interoperability: python-can (Debian python3-can) writes ASC, BLF, TRC and candump logs with
// known messages; our readers read them back frame for frame. Skipped without python-can.
#include "core/logio/LogFormats.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace coscope;
using namespace coscope::logio;

namespace {
// Messages: (relative time s, id, extended, remote, fd, brs, data hex); base time 1700000000.5.
const char kScript[] = R"PY(
import sys, can
out = sys.argv[1]
base = 1700000000.5
msgs = [
    can.Message(timestamp=base + 0.000000, arbitration_id=0x123, data=bytes.fromhex("1122334455667788"), is_extended_id=False),
    can.Message(timestamp=base + 0.001250, arbitration_id=0x1ABCDEF0, data=bytes.fromhex("DEAD"), is_extended_id=True),
    can.Message(timestamp=base + 0.010000, arbitration_id=0x701, is_remote_frame=True, dlc=4, is_extended_id=False),
    can.Message(timestamp=base + 0.500001, arbitration_id=0x181, data=bytes(range(12)), is_fd=True, bitrate_switch=True, is_extended_id=False),
    can.Message(timestamp=base + 1.000000, arbitration_id=0x080, data=b"", is_extended_id=False),
]
for ext, writer in (("asc", can.ASCWriter), ("blf", can.BLFWriter), ("trc", can.TRCWriter), ("log", can.CanutilsLogWriter)):
    w = writer(out + "/py." + ext)
    for m in msgs:
        if ext == "trc" and (m.is_remote_frame or m.is_fd):
            continue  # python-can 4.1's TRC writer drops remote frames and writes FD as DT
        w.on_message_received(m)
    w.stop()
)PY";

struct Expect {
    int64_t relUs;
    uint32_t id;
    bool ext, rtr, fd;
    int len;
};
const Expect kExpect[] = {{0, 0x123, false, false, false, 8},
                          {1250, 0x1ABCDEF0, true, false, false, 2},
                          {10000, 0x701, false, true, false, 4},
                          {500001, 0x181, false, false, true, 12},
                          {1000000, 0x080, false, false, false, 0}};

QString python() {
    for (const QString& p : {QStringLiteral("/usr/bin/python3"), QStringLiteral("python3")}) {
        QProcess q;
        q.start(p, {QStringLiteral("-c"), QStringLiteral("import can")});
        if (q.waitForFinished(30000) && q.exitStatus() == QProcess::NormalExit && q.exitCode() == 0) return p;
    }
    return {};
}
}  // namespace

class TestPythonCanLogs : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        const QString py = python();
        if (py.isEmpty()) QSKIP("python-can is not installed");
        QProcess p;
        p.start(py, {QStringLiteral("-c"), QString::fromLatin1(kScript), dir_.path()});
        QVERIFY(p.waitForFinished(60000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
    }

    void readBack_data() {
        QTest::addColumn<QString>("ext");
        QTest::addColumn<int64_t>("timeTolUs");
        QTest::newRow("asc") << "asc" << int64_t(1);
        QTest::newRow("blf") << "blf" << int64_t(1);
        QTest::newRow("trc") << "trc" << int64_t(1);  // 2.1 offsets in ms with 3 decimals
        QTest::newRow("candump") << "log" << int64_t(1);
    }

    void readBack() {
        QFETCH(QString, ext);
        QFETCH(int64_t, timeTolUs);
        QString error;
        auto r = LogFormats::openReader(dir_.filePath(QStringLiteral("py.") + ext), &error);
        QVERIFY2(r, qPrintable(error));
        const auto got = r->readAll();
        QVERIFY2(r->diagnostics().empty(), r->diagnostics().empty() ? "" : qPrintable(r->diagnostics()[0].message));
        std::vector<Expect> want;
        for (const auto& e : kExpect)
            if (ext != u"trc" || (!e.rtr && !e.fd)) want.push_back(e);
        QCOMPARE(got.size(), want.size());
        for (size_t i = 0; i < want.size(); ++i) {
            const CanFrame& f = got[i];
            QCOMPARE(f.id, want[i].id);
            QCOMPARE(f.isExtended(), want[i].ext);
            QCOMPARE(f.isRemote(), want[i].rtr);
            QCOMPARE(f.isFd(), want[i].fd);
            if (!(ext == u"log" && want[i].rtr))
                QCOMPARE(int(f.len), want[i].len);  // python-can writes "701#R" without the length
            if (want[i].id == 0x123) QCOMPARE(f.data[7], uint8_t(0x88));
            if (want[i].id == 0x181) QCOMPARE(f.data[11], uint8_t(11));
            const int64_t relUs = (f.timestampNs - got[0].timestampNs) / 1000;
            QVERIFY2(std::llabs(relUs - want[i].relUs) <= timeTolUs,
                     qPrintable(QStringLiteral("frame %1: %2 us, want %3").arg(i).arg(relUs).arg(want[i].relUs)));
        }
        if (ext == u"log" || ext == u"blf") QCOMPARE(got[0].timestampNs / 1000, 1700000000500000LL);  // absolute
    }
};

QTEST_GUILESS_MAIN(TestPythonCanLogs)
#include "test_python_can_logs.moc"
