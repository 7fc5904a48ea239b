// SPDX-License-Identifier: GPL-3.0-or-later
// Gaps of a live capture (issue 16 "Lost adapter") in every log format that can hold them:
// pcapng (packet comment), Vector ASC ("//" line), PEAK TRC (";" line), CSV ("gap" row). Written
// with a gap, read back: the same frames and the same gaps; python-can still reads every frame
// of an ASC or TRC with a gap comment. candump and BLF cannot hold a gap and say so.
#include "core/logio/CaptureGapText.h"
#include "core/logio/LogFormats.h"

#include "tests/PythonCan.h"

#include <QBuffer>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

using namespace coscope;
using namespace coscope::logio;

namespace {

constexpr int64_t kT0 = 1700000000123000000LL;
// The adapter was lost after frame 1 and back before frame 2; again before frame 4, twice.
struct GapAt {
    size_t frame;
    int64_t lostNs, backNs;
};
const GapAt kGaps[] = {{2, kT0 + 2500000, kT0 + 1750000000LL},
                       {4, kT0 + 1800000000LL, kT0 + 1900000000LL},
                       {4, kT0 + 1950000000LL, kT0 + 2000000000LL}};

std::vector<CanFrame> frames() {
    std::vector<CanFrame> v;
    for (int i = 0; i < 6; ++i) {
        CanFrame f;
        f.timestampNs = kT0 + (i < 2 ? i * 1000000LL : 2000001000LL + i * 1000LL);
        f.id = i == 3 ? 0x1ABCDEF0 : 0x181 + uint32_t(i);
        if (i == 3) f.flags |= CanFrame::Extended;
        f.len = uint8_t(2 + i);
        for (int b = 0; b < f.len; ++b) f.data[size_t(b)] = uint8_t(0x10 * i + b);
        v.push_back(f);
    }
    return v;
}

// Writes frames() with kGaps: both gaps before frame 4 too (in pcapng two comments of one packet).
QByteArray writeWithGaps(const QString& format, std::vector<GapAt>* written) {
    auto w = LogFormats::createWriter(format);
    QBuffer buf;
    buf.open(QIODevice::WriteOnly);
    w->open(&buf);
    const auto v = frames();
    for (size_t i = 0; i < v.size(); ++i) {
        for (const GapAt& g : kGaps) {
            if (g.frame != i) continue;
            w->markGap(g.lostNs, g.backNs);
            if (written) written->push_back(g);
        }
        w->write(v[i]);
    }
    w->close();
    return buf.data();
}

std::unique_ptr<LogReader> readBack(const QString& format, const QByteArray& bytes, QBuffer& buf,
                                    std::vector<CanFrame>* got) {
    buf.setData(bytes);
    buf.open(QIODevice::ReadOnly);
    auto r = LogFormats::createReader(format);
    if (!r->open(&buf)) return nullptr;
    *got = r->readAll();
    return r;
}

}  // namespace

class TestLogioGaps : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void wordingRoundTrips() {
        const QByteArray text = captureGapText(kT0, kT0 + 2500000000LL);
        QVERIFY(text.startsWith("CoScope: gap in the capture before this frame"));
        QVERIFY(text.contains("2.5 s"));
        int64_t lost = 0, back = 0;
        QVERIFY(parseCaptureGapText(std::string_view(text.constData(), size_t(text.size())), &lost, &back));
        QCOMPARE(lost, kT0);
        QCOMPARE(back, kT0 + 2500000000LL);
        QVERIFY(!parseCaptureGapText("version 9.0.0", &lost, &back));
        QVERIFY(!parseCaptureGapText("CoScope: gap in the capture, no times", &lost, &back));
    }

    void sameFramesAndGaps_data() {
        QTest::addColumn<QString>("format");
        QTest::addColumn<QByteArray>("commentMark");  // how the gap shows in the file's text
        QTest::newRow("asc") << "asc" << QByteArray("\n// CoScope: gap in the capture");
        QTest::newRow("trc") << "trc" << QByteArray("\n; CoScope: gap in the capture");
        QTest::newRow("csv") << "csv" << QByteArray(",gap,,,\"CoScope: gap in the capture");
        QTest::newRow("pcapng") << "pcapng" << QByteArray("CoScope: gap in the capture");
    }

    void sameFramesAndGaps() {
        QFETCH(QString, format);
        QFETCH(QByteArray, commentMark);
        std::vector<GapAt> written;
        const QByteArray bytes = writeWithGaps(format, &written);
        QVERIFY(bytes.contains(commentMark));
        QBuffer buf;
        std::vector<CanFrame> got;
        auto r = readBack(format, bytes, buf, &got);
        QVERIFY(r);
        QVERIFY2(r->diagnostics().empty(), r->diagnostics().empty() ? "" : qPrintable(r->diagnostics()[0].message));
        const auto want = frames();
        QCOMPARE(got.size(), want.size());
        for (size_t i = 0; i < want.size(); ++i) {
            QCOMPARE(got[i].id, want[i].id);
            QCOMPARE(got[i].len, want[i].len);
            QCOMPARE(got[i].isExtended(), want[i].isExtended());
            QCOMPARE(got[i].timestampNs / 1000, want[i].timestampNs / 1000);
            QVERIFY(std::equal(want[i].data.begin(), want[i].data.begin() + want[i].len, got[i].data.begin()));
        }
        QCOMPARE(written.size(), std::size(kGaps));
        QCOMPARE(r->gaps().size(), written.size());
        for (size_t i = 0; i < written.size(); ++i) {
            QCOMPARE(r->gaps()[i].frame, uint64_t(written[i].frame));
            QCOMPARE(r->gaps()[i].lostNs, written[i].lostNs);
            QCOMPARE(r->gaps()[i].backNs, written[i].backNs);
        }
        QVERIFY(LogFormats::createWriter(format)->keepsGaps());
    }

    // A gap comment CoScope did not write (or a damaged one) is an ordinary comment.
    void otherCommentsAreNoGaps() {
        const QByteArray asc =
            "date Tue Nov 14 10:13:20.123 PM 2023\nbase hex  timestamps absolute\nBegin Triggerblock Tue Nov 14 "
            "10:13:20.123 PM 2023\n// CoScope: gap in the capture (lost_ns=x back_ns=1)\n// a remark\n"
            "   0.001000 1  181             Rx   d 1 01\nEnd TriggerBlock\n";
        QBuffer buf;
        std::vector<CanFrame> got;
        auto r = readBack(QStringLiteral("asc"), asc, buf, &got);
        QVERIFY(r);
        QCOMPARE(got.size(), size_t(1));
        QVERIFY(r->gaps().empty());
    }

    void candumpAndBlfCannotHoldGaps_data() {
        QTest::addColumn<QString>("format");
        QTest::newRow("candump") << "candump";
        QTest::newRow("blf") << "blf";
    }

    void candumpAndBlfCannotHoldGaps() {
        QFETCH(QString, format);
        auto w = LogFormats::createWriter(format);
        QVERIFY(!w->keepsGaps());
        QBuffer buf;
        buf.open(QIODevice::WriteOnly);
        w->open(&buf);
        w->markGap(kT0, kT0 + 1);
        w->write(frames()[0]);
        w->close();
        QCOMPARE(w->gapsDropped(), uint64_t(1));
    }

    // python-can (a third-party reader of ASC and TRC) reads every frame of a file with gap
    // comments: the same ids in the same order.
    void pythonCanReadsEveryFrame_data() {
        QTest::addColumn<QString>("format");
        QTest::addColumn<QString>("readerClass");
        QTest::newRow("asc") << "asc"
                             << "ASCReader";
        QTest::newRow("trc") << "trc"
                             << "TRCReader";
    }

    void pythonCanReadsEveryFrame() {
        QFETCH(QString, format);
        QFETCH(QString, readerClass);
        const QString py = pythonWithCan(QStringLiteral("can"));
        if (py.isEmpty()) QSKIP("python3-can is not installed");
        const QString path = dir_.filePath(QStringLiteral("gaps.") + format);
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(writeWithGaps(format, nullptr));
        }
        QProcess p;
        p.start(
            py,
            {QStringLiteral("-c"),
             QStringLiteral("import sys, can\nfor m in can.%1(sys.argv[1]): print('%x %d' % (m.arbitration_id, m.dlc))")
                 .arg(readerClass),
             path});
        QVERIFY(p.waitForFinished(60000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        QStringList want;
        for (const CanFrame& f : frames()) want << QStringLiteral("%1 %2").arg(f.id, 0, 16).arg(f.len);
        QCOMPARE(QString::fromLatin1(p.readAllStandardOutput()).split(QLatin1Char('\n'), Qt::SkipEmptyParts), want);
    }
};

QTEST_GUILESS_MAIN(TestLogioGaps)
#include "test_logio_gaps.moc"
