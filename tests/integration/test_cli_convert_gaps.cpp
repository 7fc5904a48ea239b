// SPDX-License-Identifier: GPL-3.0-or-later
// coscope-cli convert keeps the gaps of a capture (issue 16 "Lost adapter") in the formats that
// hold them (asc -> trc, csv, pcapng: same gap before the same frame) and warns on stderr when
// the output format cannot hold them (candump, BLF), converting the frames all the same.
#include "core/logio/LogFormats.h"
#include "tests/CliRun.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

using namespace coscope;
using namespace coscope::logio;

namespace {
constexpr int64_t kT0 = 1700000000000000000LL;
constexpr int64_t kLost = kT0 + 5000000, kBack = kT0 + 3005000000LL;
constexpr int kFrames = 10, kGapBefore = 4;

constexpr int64_t kLost2 = kBack + 1000000, kBack2 = kBack + 2000000;  // lost again at once

// An ASC capture of 10 frames with the adapter lost between frame 3 and frame 4 (`twice`: lost
// again right after it came back, before frame 4 arrived).
bool writeAscWithGap(const QString& path, bool twice = false) {
    auto w = LogFormats::createWriter(QStringLiteral("asc"));
    if (!w->open(path)) return false;
    for (int i = 0; i < kFrames; ++i) {
        CanFrame f;
        f.timestampNs = kT0 + i * 1000000LL + (i >= kGapBefore ? 3000000000LL : 0);
        f.id = 0x181;
        f.len = 1;
        f.data[0] = uint8_t(i);
        if (i == kGapBefore) w->markGap(kLost, kBack);
        if (i == kGapBefore && twice) w->markGap(kLost2, kBack2);
        w->write(f);
    }
    return w->close();
}
}  // namespace

class TestCliConvertGaps : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString in_;

private slots:
    void initTestCase() {
        in_ = dir_.filePath(QStringLiteral("gap.asc"));
        QVERIFY(writeAscWithGap(in_));
    }

    void keptWhereTheFormatHoldsIt_data() {
        QTest::addColumn<QString>("ext");
        QTest::newRow("trc") << "trc";
        QTest::newRow("csv") << "csv";
        QTest::newRow("pcapng") << "pcapng";
    }

    void keptWhereTheFormatHoldsIt() {
        QFETCH(QString, ext);
        const QString out = dir_.filePath(QStringLiteral("out.") + ext);
        const Run r = cli({QStringLiteral("convert"), in_, out});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(!r.err.contains(QStringLiteral("gap")), qPrintable(r.err));
        QString error;
        auto reader = LogFormats::openReader(out, &error);
        QVERIFY2(reader, qPrintable(error));
        QCOMPARE(reader->readAll().size(), size_t(kFrames));
        QCOMPARE(reader->gaps().size(), size_t(1));
        QCOMPARE(reader->gaps()[0].frame, uint64_t(kGapBefore));
        QCOMPARE(reader->gaps()[0].lostNs, kLost);
        QCOMPARE(reader->gaps()[0].backNs, kBack);
    }

    // Two gaps before the same frame: both kept, in order, through pcapng (two comments of one
    // packet) and back to ASC, and in TRC and CSV.
    void twoGapsBeforeOneFrame_data() {
        QTest::addColumn<QString>("ext");
        QTest::newRow("trc") << "trc";
        QTest::newRow("csv") << "csv";
        QTest::newRow("pcapng") << "pcapng";
    }

    void twoGapsBeforeOneFrame() {
        QFETCH(QString, ext);
        const QString in = dir_.filePath(QStringLiteral("gaps2.asc"));
        QVERIFY(writeAscWithGap(in, true));
        const QString out = dir_.filePath(QStringLiteral("out2.") + ext);
        Run r = cli({QStringLiteral("convert"), in, out});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QString back = dir_.filePath(QStringLiteral("back2.asc"));  // and from it again
        r = cli({QStringLiteral("convert"), out, back});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        for (const QString& path : {out, back}) {
            QString error;
            auto reader = LogFormats::openReader(path, &error);
            QVERIFY2(reader, qPrintable(error));
            QCOMPARE(reader->readAll().size(), size_t(kFrames));
            QCOMPARE(reader->gaps().size(), size_t(2));
            QCOMPARE(reader->gaps()[0].frame, uint64_t(kGapBefore));
            QCOMPARE(reader->gaps()[1].frame, uint64_t(kGapBefore));
            QCOMPARE(reader->gaps()[0].lostNs, kLost);
            QCOMPARE(reader->gaps()[0].backNs, kBack);
            QCOMPARE(reader->gaps()[1].lostNs, kLost2);
            QCOMPARE(reader->gaps()[1].backNs, kBack2);
        }
    }

    void warnedWhereItCannot_data() {
        QTest::addColumn<QString>("ext");
        QTest::newRow("candump") << "log";
        QTest::newRow("blf") << "blf";
    }

    void warnedWhereItCannot() {
        QFETCH(QString, ext);
        const QString out = dir_.filePath(QStringLiteral("out.") + ext);
        const Run r = cli({QStringLiteral("convert"), in_, out});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("warning: the input has 1 gap(s) in the capture (adapter lost)")),
                 qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral(" format cannot hold; they are not in the output")), qPrintable(r.err));
        QString error;
        auto reader = LogFormats::openReader(out, &error);
        QVERIFY2(reader, qPrintable(error));
        QCOMPARE(reader->readAll().size(), size_t(kFrames));
    }
};

QTEST_GUILESS_MAIN(TestCliConvertGaps)
#include "test_cli_convert_gaps.moc"
