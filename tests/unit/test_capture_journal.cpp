// SPDX-License-Identifier: GPL-3.0-or-later
// The capture journal (core/trace/CaptureJournal) and its folder (JournalFolder): what is written
// is readable pcapng up to the last flush, a torn last block is skipped with a diagnostic, a full
// disk is reported, and old journals are cleaned up by age and size without touching open ones.
#include "core/logio/PcapLog.h"
#include "core/trace/CaptureJournal.h"
#include "core/trace/JournalFolder.h"

#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <vector>

using namespace coscope;

namespace {
CanFrame makeFrame(uint32_t i) {
    CanFrame f;
    f.timestampNs = 1'700'000'000'000'000'000LL + int64_t(i) * 125'000;
    f.id = 0x180 + (i % 4);
    f.len = 8;
    for (int b = 0; b < 8; ++b) f.data[size_t(b)] = uint8_t(i >> (b % 4 * 8));
    return f;
}
std::vector<CanFrame> frames(uint32_t n) {
    std::vector<CanFrame> v;
    for (uint32_t i = 0; i < n; ++i) v.push_back(makeFrame(i));
    return v;
}
struct ReadBack {
    std::vector<CanFrame> frames;
    QString error;
    uint64_t diagnostics = 0;
};
ReadBack readJournal(const QString& path) {
    logio::PcapReader r;
    ReadBack out;
    if (!r.open(path)) {
        out.error = r.errorString();
        return out;
    }
    out.frames = r.readAll();
    out.error = r.errorString();
    out.diagnostics = r.diagnosticCount();
    return out;
}
bool sameFrames(const std::vector<CanFrame>& a, const std::vector<CanFrame>& b, size_t n) {
    if (a.size() < n || b.size() < n) return false;
    for (size_t i = 0; i < n; ++i)
        if (a[i].id != b[i].id || a[i].timestampNs != b[i].timestampNs || a[i].len != b[i].len ||
            a[i].data != b[i].data)
            return false;
    return true;
}
void touch(const QString& path, qint64 bytes, const QDateTime& when) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(QByteArray(bytes, 'x'));
    f.flush();  // else closing writes the buffer and the time becomes now
    QVERIFY(f.setFileTime(when, QFileDevice::FileModificationTime));
}
}  // namespace

class TestCaptureJournal : public QObject {
    Q_OBJECT
private slots:
    void closedJournalHoldsEveryFrame() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("a.pcapng"));
        CaptureJournal j;
        QVERIFY2(j.open(path, {QStringLiteral("can0")}), qPrintable(j.errorString()));
        QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("a.open"))));
        const auto in = frames(10000);
        for (size_t i = 0; i < in.size(); i += 100) j.append(std::span(in).subspan(i, 100));
        QVERIFY(j.close());
        QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("a.open"))));
        const ReadBack r = readJournal(path);
        QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
        QCOMPARE(r.frames.size(), in.size());
        QVERIFY(sameFrames(r.frames, in, in.size()));
        QCOMPARE(r.diagnostics, uint64_t(0));
    }

    // Without any flush() call the writer thread hands frames to the kernel within a second:
    // what a SIGKILL would leave behind is readable while the journal is still open.
    void framesReachTheFileWithinASecond() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("b.pcapng"));
        CaptureJournal j;
        QVERIFY(j.open(path, {QStringLiteral("can0")}));
        const auto in = frames(500);
        j.append(in);
        QTest::qWait(CaptureJournal::kSyncIntervalMs + 100);
        const ReadBack r = readJournal(path);
        QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
        QCOMPARE(r.frames.size(), in.size());
        QVERIFY(sameFrames(r.frames, in, in.size()));
        QVERIFY(QFileInfo::exists(CaptureJournal::sidecarOf(path)));  // still open
        QVERIFY(j.close());
    }

    void tornLastBlockIsSkippedWithADiagnostic() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("c.pcapng"));
        CaptureJournal j;
        QVERIFY(j.open(path, {QStringLiteral("can0")}));
        const auto in = frames(50);
        j.append(in);
        QVERIFY(j.flush());
        QCOMPARE(j.framesWritten(), uint64_t(50));
        QVERIFY(j.close());
        QFile f(path);
        QVERIFY(f.resize(f.size() - 10));  // the power went out mid-block
        const ReadBack r = readJournal(path);
        QVERIFY2(r.error.isEmpty(), qPrintable(r.error));
        QCOMPARE(r.frames.size(), size_t(49));
        QVERIFY(sameFrames(r.frames, in, 49));
        QCOMPARE(r.diagnostics, uint64_t(1));
    }

    // Issue 16 "Lost adapter": the gap goes into the journal as the comment of the first packet
    // after it; our reader gives it back at that frame, tshark reads the file without error
    // and shows the comment on that packet.
    void gapIsInTheJournalAndReadBack() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("gap.pcapng"));
        CaptureJournal j;
        QVERIFY(j.open(path, {QStringLiteral("can0")}));
        const auto in = frames(150);
        const int64_t lost = in[99].timestampNs + 1'000'000, back = in[100].timestampNs - 2'000'000;
        j.append(std::span(in).first(100));
        QVERIFY(j.flush());
        j.addGap({100, lost, back});
        j.append(std::span(in).subspan(100));
        QVERIFY(j.close());

        logio::PcapReader r;
        QVERIFY(r.open(path));
        const auto read = r.readAll();
        QVERIFY2(r.errorString().isEmpty(), qPrintable(r.errorString()));
        QCOMPARE(r.diagnosticCount(), uint64_t(0));
        QVERIFY(sameFrames(read, in, in.size()));
        QCOMPARE(r.gaps().size(), size_t(1));
        QCOMPARE(r.gaps()[0].frame, uint64_t(100));
        QCOMPARE(r.gaps()[0].lostNs, lost);
        QCOMPARE(r.gaps()[0].backNs, back);

        const QString tshark = QStandardPaths::findExecutable(QStringLiteral("tshark"));
        if (tshark.isEmpty()) return;
        QProcess p;
        p.start(tshark, {QStringLiteral("-r"), path, QStringLiteral("-T"), QStringLiteral("fields"),
                         QStringLiteral("-e"), QStringLiteral("frame.comment")});
        QVERIFY(p.waitForFinished(60000));
        const QString err = QString::fromLocal8Bit(p.readAllStandardError());
        QVERIFY2(p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0, qPrintable(err));
        QVERIFY2(!err.contains(QStringLiteral("appears to be damaged")) && !err.contains(QStringLiteral("cut short")),
                 qPrintable(err));
        const QList<QByteArray> lines = p.readAllStandardOutput().split('\n');
        QVERIFY(lines.size() >= 150);
        QVERIFY2(lines[100].contains("gap in the capture"), lines[100].constData());
        QVERIFY(lines[99].trimmed().isEmpty() && lines[101].trimmed().isEmpty());
    }

    // The adapter lost twice with no frame between (issue 16 "Lost adapter"): both gaps, with
    // their own times, are comments of the same packet, read back in order; tshark shows both.
    void twoGapsBeforeOneFrameAreBothKept() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("gaps.pcapng"));
        CaptureJournal j;
        QVERIFY(j.open(path, {QStringLiteral("can0")}));
        const auto in = frames(150);
        const int64_t lost1 = in[99].timestampNs + 1'000'000, back1 = lost1 + 3'000'000;
        const int64_t lost2 = back1 + 1'000'000, back2 = in[100].timestampNs - 1'000'000;
        j.append(std::span(in).first(100));
        j.addGap({100, lost1, back1});
        j.addGap({100, lost2, back2});
        j.append(std::span(in).subspan(100));
        QVERIFY(j.close());

        logio::PcapReader r;
        QVERIFY(r.open(path));
        const auto read = r.readAll();
        QCOMPARE(r.diagnosticCount(), uint64_t(0));
        QVERIFY(sameFrames(read, in, in.size()));
        QCOMPARE(r.gaps().size(), size_t(2));
        QCOMPARE(r.gaps()[0].frame, uint64_t(100));
        QCOMPARE(r.gaps()[1].frame, uint64_t(100));
        QCOMPARE(r.gaps()[0].lostNs, lost1);
        QCOMPARE(r.gaps()[0].backNs, back1);
        QCOMPARE(r.gaps()[1].lostNs, lost2);
        QCOMPARE(r.gaps()[1].backNs, back2);

        const QString tshark = QStandardPaths::findExecutable(QStringLiteral("tshark"));
        if (tshark.isEmpty()) return;
        QProcess p;
        p.start(tshark, {QStringLiteral("-r"), path, QStringLiteral("-T"), QStringLiteral("fields"),
                         QStringLiteral("-e"), QStringLiteral("frame.comment")});
        QVERIFY(p.waitForFinished(60000));
        QVERIFY2(p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0, p.readAllStandardError().constData());
        const QList<QByteArray> lines = p.readAllStandardOutput().split('\n');
        QVERIFY(lines.size() >= 150);
        QVERIFY2(lines[100].count("gap in the capture") == 2, lines[100].constData());
    }

    void fullDiskIsReported() {
        if (!QFileInfo::exists(QStringLiteral("/dev/full"))) QSKIP("no /dev/full");
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("full.pcapng"));
        QVERIFY(QFile::link(QStringLiteral("/dev/full"), path));
        CaptureJournal j;
        QVERIFY(j.open(path, {QStringLiteral("can0")}));
        j.append(frames(100));
        QVERIFY(!j.flush());
        QVERIFY(j.hasError());
        QVERIFY2(j.errorString().contains(QStringLiteral("space"), Qt::CaseInsensitive), qPrintable(j.errorString()));
        j.append(frames(100));  // dropped at once, nothing piles up
        QVERIFY(!j.close());
    }

    void unclosedJournalsAreThoseOfGoneProcesses() {
        QTemporaryDir dir;
        const QString dead = dir.filePath(QStringLiteral("capture-dead.pcapng"));
        {
            CaptureJournal j;
            QVERIFY(j.open(dead, {}));
            j.append(frames(3));
            QVERIFY(j.flush());
            // As if killed: the sidecar names a process that no longer runs.
            QFile s(CaptureJournal::sidecarOf(dead));
            QVERIFY(j.close());
            QVERIFY(s.open(QIODevice::WriteOnly));
            s.write("2147483646\n");
        }
        const QString mine = dir.filePath(QStringLiteral("capture-mine.pcapng"));
        CaptureJournal live;
        QVERIFY(live.open(mine, {}));
        live.append(frames(3));
        QVERIFY(live.flush());
        const QString empty = dir.filePath(QStringLiteral("capture-empty.pcapng"));
        touch(empty, 0, QDateTime::currentDateTime());
        QFile es(CaptureJournal::sidecarOf(empty));
        QVERIFY(es.open(QIODevice::WriteOnly));
        es.write("2147483646\n");
        es.close();

        QCOMPARE(journals::unclosed(dir.path()), QStringList{dead});
        QVERIFY(!QFileInfo::exists(empty));  // nothing in it: removed with its sidecar
        journals::markOffered(dead);
        QVERIFY(journals::unclosed(dir.path()).isEmpty());
        QVERIFY(live.close());
    }

    void newJournalNamesAreUnique() {
        QTemporaryDir dir;
        const QString folder = dir.filePath(QStringLiteral("x/captures"));
        const QDateTime t(QDate(2026, 11, 25), QTime(20, 15, 10));
        const QString a = journals::newJournalPath(folder, QStringLiteral("socketcan://can0"), t);
        QCOMPARE(QFileInfo(a).fileName(), QStringLiteral("capture-20261125-201510-socketcan_can0.pcapng"));
        touch(a, 4, t);
        const QString b = journals::newJournalPath(folder, QStringLiteral("socketcan://can0"), t);
        QVERIFY(b != a);
        QVERIFY(b.endsWith(QStringLiteral("-2.pcapng")));
    }

    void cleanupByAgeAndSize() {
        QTemporaryDir dir;
        const QDateTime now = QDateTime::currentDateTime();
        const auto p = [&](const char* n) { return dir.filePath(QString::fromLatin1(n)); };
        touch(p("old.pcapng"), 100, now.addDays(-20));
        touch(p("oldOpen.pcapng"), 100, now.addDays(-30));  // unclosed, not offered yet
        touch(p("oldOpen.open"), 6, now);
        touch(p("oldCurrent.pcapng"), 100, now.addDays(-15));
        touch(p("mid1.pcapng"), 1000, now.addDays(-5));
        touch(p("mid2.pcapng"), 1000, now.addDays(-4));
        touch(p("new.pcapng"), 1000, now.addDays(-1));
        touch(p("notes.txt"), 5000, now.addDays(-40));

        journals::CleanupPolicy policy;
        policy.maxAgeDays = 14;
        policy.maxTotalBytes = 2300;
        const QStringList removed = journals::cleanup(dir.path(), policy, {p("oldCurrent.pcapng")}, now);
        // Age: old goes (oldOpen has a sidecar, oldCurrent is kept). Size: 3200 left > 2300, so
        // the oldest that may go (mid1) goes: 2200.
        QCOMPARE(QSet<QString>(removed.begin(), removed.end()), (QSet<QString>{p("old.pcapng"), p("mid1.pcapng")}));
        for (const char* n : {"oldOpen.pcapng", "oldCurrent.pcapng", "mid2.pcapng", "new.pcapng", "notes.txt"})
            QVERIFY2(QFileInfo::exists(p(n)), n);
        policy.maxTotalBytes = 0;
        journals::cleanup(dir.path(), policy, {}, now);
        QVERIFY(QFileInfo::exists(p("oldOpen.pcapng")));
        QVERIFY(!QFileInfo::exists(p("new.pcapng")));
    }
};

QTEST_GUILESS_MAIN(TestCaptureJournal)
#include "test_capture_journal.moc"
