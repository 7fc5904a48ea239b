// SPDX-License-Identifier: GPL-3.0-or-later
// The capture journal in the app (issue 16): a live capture is written to the data folder and
// closed cleanly on disconnect; a journal left unclosed (the app was killed) is offered at the
// next start in a banner, and "Reopen capture" loads its frames into the trace; "Dismiss" keeps
// the file; old journals are removed at start by the age and size settings.
#include "app/gui/JournalOffer.h"
#include "app/gui/MainWindow.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/session/SimulationDemo.h"
#include "app/gui/session/Workspace.h"
#include "app/gui/trace/LogLoadJob.h"
#include "app/gui/trace/LogSaveJob.h"
#include "app/gui/trace/TraceDock.h"
#include "app/gui/trace/TraceModel.h"
#include "app/gui/trace/TraceView.h"
#include "core/logio/PcapLog.h"
#include "core/trace/CaptureJournal.h"
#include "eds/SimulatorDictionaries.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLineEdit>
#include <QPushButton>
#include <QSettings>
#include <QTableView>
#include <QTemporaryDir>
#include <QtTest>

#include "tests/gui/TypeText.h"
#include "tests/gui/WaitFor.h"

#include <csignal>

#include <sys/resource.h>

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::waitFor;

namespace {
bool setModified(const QString& path, const QDateTime& when) {
    QFile f(path);
    return f.open(QIODevice::ReadWrite) && f.setFileTime(when, QFileDevice::FileModificationTime);
}
QString capturesFolder() { return qEnvironmentVariable("XDG_DATA_HOME") + QStringLiteral("/CoScope/captures"); }

// A journal as a killed app leaves it: frames up to the last flush, its sidecar naming a
// process that is gone.
QString makeUnclosedJournal(const QString& name, int frames) {
    QDir().mkpath(capturesFolder());
    const QString path = capturesFolder() + u'/' + name;
    CaptureJournal j;
    if (!j.open(path, {QStringLiteral("can0")})) return {};
    std::vector<CanFrame> v;
    for (int i = 0; i < frames; ++i) {
        CanFrame f;
        f.timestampNs = 1'700'000'000'000'000'000LL + i * 1'000'000LL;
        f.id = 0x181;
        f.len = 2;
        f.data[0] = uint8_t(i >> 8);
        f.data[1] = uint8_t(i);
        v.push_back(f);
    }
    j.append(v);
    j.close();
    QFile s(CaptureJournal::sidecarOf(path));
    if (!s.open(QIODevice::WriteOnly)) return {};
    s.write("2147483646\n");
    return path;
}
// As makeUnclosedJournal, with node 5's heartbeat (operational) before a gap at frame `gapAt`
// and only PDOs of another node after it; the gap is recorded as the app records one live.
// secondGap: the adapter was lost a second time, 2 s after it came back, before any frame came.
QString makeUnclosedJournalWithGap(const QString& name, int frames, int gapAt, int64_t* lostNs, int64_t* backNs,
                                   bool secondGap = false) {
    QDir().mkpath(capturesFolder());
    const QString path = capturesFolder() + u'/' + name;
    CaptureJournal j;
    if (!j.open(path, {QStringLiteral("can0")})) return {};
    std::vector<CanFrame> v;
    for (int i = 0; i < frames; ++i) {
        CanFrame f;
        f.timestampNs = 1'700'000'000'000'000'000LL + i * 1'000'000LL + (i >= gapAt ? 5'000'000'000LL : 0);
        f.id = i < gapAt ? 0x705 : 0x186;
        f.len = 1;
        f.data[0] = i < gapAt ? 0x05 : uint8_t(i);
        v.push_back(f);
    }
    *lostNs = v[size_t(gapAt - 1)].timestampNs + 500'000'000LL;
    *backNs = v[size_t(gapAt)].timestampNs - 1'000'000LL;
    j.append(std::span(v).first(size_t(gapAt)));
    if (secondGap) {
        j.addGap({FrameNo(gapAt), *lostNs, *lostNs + 1'000'000'000LL});
        j.addGap({FrameNo(gapAt), *lostNs + 3'000'000'000LL, *backNs});
    } else {
        j.addGap({FrameNo(gapAt), *lostNs, *backNs});
    }
    j.append(std::span(v).subspan(size_t(gapAt)));
    j.close();
    QFile s(CaptureJournal::sidecarOf(path));
    if (!s.open(QIODevice::WriteOnly)) return {};
    s.write("2147483646\n");
    return path;
}
// Shows the window, which must offer the journal `path`, and reopens it by the offer's button.
void reopenOffered(MainWindow& w, const QString& path) {
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.journalOffer()->isVisible());
    QCOMPARE(w.journalOffer()->offeredPath(), path);
    QTest::mouseClick(w.journalOffer()->reopenButton(), Qt::LeftButton);
    QVERIFY(waitFor([&] { return w.workspace()->loadJob() && w.workspace()->loadJob()->isDone(); }));
}
}  // namespace

class TestCaptureJournalGui : public QObject {
    Q_OBJECT
    QTemporaryDir data_;

private slots:
    void initTestCase() {
        QVERIFY(data_.isValid());
        qputenv("XDG_DATA_HOME", data_.path().toUtf8());  // this test's own data folder
        eds::installSimulatorDictionaries();
    }
    void init() {
        QDir(capturesFolder()).removeRecursively();
        QSettings().remove(QStringLiteral("captures"));
    }

    void liveCaptureIsJournaledAndClosed() {
        MainWindow w;
        w.setQuiet(true);
        QVERIFY(w.journalOffer()->isHidden());
        QVERIFY(w.connectBus(QStringLiteral("sim://"), true));  // the scan makes traffic
        const QString path = w.workspace()->journalPath();
        QVERIFY(path.startsWith(capturesFolder() + QStringLiteral("/capture-")));
        QVERIFY(QFileInfo::exists(CaptureJournal::sidecarOf(path)));
        QVERIFY(waitFor([&] { return w.workspace()->store()->size() >= 30; }));
        w.disconnectBus();
        const size_t frames = w.workspace()->store()->size();
        QVERIFY(!QFileInfo::exists(CaptureJournal::sidecarOf(path)));  // closed cleanly: nothing to offer
        logio::PcapReader r;
        QVERIFY(r.open(path));
        const auto read = r.readAll();
        QVERIFY2(r.errorString().isEmpty(), qPrintable(r.errorString()));
        QCOMPARE(read.size(), frames);
        QCOMPARE(read.back().id, w.workspace()->store()->frame(FrameNo(frames - 1)).id);
    }

    // The disk fills mid-capture (here: a file size limit for this process): the capture stops
    // with a message saying so, the trace keeps every frame received, the journal stays
    // readable up to where the disk was full.
    void fullDiskStopsTheCapture() {
        MainWindow w;
        w.setQuiet(true);
        QVERIFY(w.connectBus(QStringLiteral("sim://")));
        startSimulationDemo(w.workspace());  // steady traffic: heartbeats, PDOs
        const QString path = w.workspace()->journalPath();
        QVERIFY(waitFor([&] { return w.workspace()->journal()->framesWritten() >= 10; }));
        std::signal(SIGXFSZ, SIG_IGN);  // a write past the limit fails with EFBIG instead
        rlimit old{};
        QVERIFY(getrlimit(RLIMIT_FSIZE, &old) == 0);
        rlimit small = old;
        small.rlim_cur = rlim_t(QFileInfo(path).size() + 1000);
        QVERIFY(setrlimit(RLIMIT_FSIZE, &small) == 0);
        const bool stopped = waitFor([&] { return !w.workspace()->isLive(); }, 20000);
        setrlimit(RLIMIT_FSIZE, &old);
        QVERIFY(stopped);
        QVERIFY2(w.lastError().startsWith(QStringLiteral("Capture stopped: cannot write the capture journal")),
                 qPrintable(w.lastError()));
        const size_t kept = w.workspace()->store()->size();
        QVERIFY(kept > 20);
        logio::PcapReader r;
        QVERIFY(r.open(path));
        const auto read = r.readAll();
        QVERIFY2(r.errorString().isEmpty(), qPrintable(r.errorString()));
        QVERIFY(read.size() >= 10 && read.size() < kept);
        for (size_t i = 0; i < read.size(); ++i)
            QCOMPARE(read[i].timestampNs, w.workspace()->store()->frame(FrameNo(i)).timestampNs);
        QTest::qWait(300);
        QCOMPARE(w.workspace()->store()->size(), kept);  // stopped: nothing more arrives
    }

    void unclosedJournalIsOfferedAndReopened() {
        const QString path = makeUnclosedJournal(QStringLiteral("capture-20261125-101010-sim.pcapng"), 300);
        QVERIFY(!path.isEmpty());
        MainWindow w;
        w.setQuiet(true);
        reopenOffered(w, path);
        if (QTest::currentTestFailed()) return;
        QCOMPARE(w.workspace()->store()->size(), size_t(300));
        QCOMPARE(w.workspace()->store()->frame(299).data[1], uint8_t(299 & 0xFF));
        QVERIFY(!w.journalOffer()->isVisible());
        QVERIFY(!QFileInfo::exists(CaptureJournal::sidecarOf(path)));  // offered once
    }

    // Issue 16 "Lost adapter": the gap of a capture is in its journal; reopened after a kill the
    // trace marks it again (at the same frame, with the same times), the Nodes table shows the
    // nodes seen before it as unknown, and Save As to pcapng keeps it.
    void reopenedJournalShowsTheGap() {
        int64_t lost = 0, back = 0;
        const QString path =
            makeUnclosedJournalWithGap(QStringLiteral("capture-20261125-111111-gap.pcapng"), 300, 200, &lost, &back);
        QVERIFY(!path.isEmpty());
        MainWindow w;
        w.setQuiet(true);
        reopenOffered(w, path);
        if (QTest::currentTestFailed()) return;
        QCOMPARE(w.workspace()->store()->size(), size_t(300));
        const auto gaps = w.workspace()->store()->gaps();
        QCOMPARE(gaps.size(), size_t(1));
        QCOMPARE(gaps[0].firstFrame, FrameNo(200));
        QCOMPARE(gaps[0].lostNs, lost);
        QCOMPARE(gaps[0].backNs, back);
        QAbstractItemModel* nodes = w.nodesDock()->view()->model();
        QVERIFY(waitFor([&] { return nodes->rowCount() == 1; }));
        // The table refreshes on its timer: the node may show up before the gap has reached it.
        waitFor(
            [&] { return nodes->index(0, NodesModel::State).data().toString() == QStringLiteral("unknown (gap)"); });
        QCOMPARE(nodes->index(0, NodesModel::State).data().toString(), QStringLiteral("unknown (gap)"));

        const QString saved = data_.filePath(QStringLiteral("saved.pcapng"));
        LogSaveJob save(saved, QStringLiteral("pcapng"), w.workspace()->store(), std::nullopt,
                        w.workspace()->busNames());
        save.start();
        save.wait();
        QVERIFY2(!save.hasError(), qPrintable(save.errorString()));
        logio::PcapReader r;
        QVERIFY(r.open(saved));
        QCOMPARE(r.readAll().size(), size_t(300));
        QCOMPARE(r.gaps().size(), size_t(1));
        QCOMPARE(r.gaps()[0].frame, uint64_t(200));
        QCOMPARE(r.gaps()[0].lostNs, lost);
        QCOMPARE(r.gaps()[0].backNs, back);
    }

    // Two gaps before one frame (lost, back, lost again before a frame came): the row of that
    // frame shows both, in order, and Find finds it by the second one's text.
    void twoGapsBeforeOneFrameBothShow() {
        int64_t lost = 0, back = 0;
        const QString path = makeUnclosedJournalWithGap(QStringLiteral("capture-20261126-111111-gaps.pcapng"), 300, 200,
                                                        &lost, &back, true);
        QVERIFY(!path.isEmpty());
        MainWindow w;
        w.setQuiet(true);
        reopenOffered(w, path);
        if (QTest::currentTestFailed()) return;
        QCOMPARE(w.workspace()->store()->gaps().size(), size_t(2));
        const QAbstractItemModel* m = w.traceDock()->view()->model();
        QVERIFY(waitFor([&] { return m->rowCount() == 300; }));
        auto clock = [](int64_t ns) {
            return QDateTime::fromMSecsSinceEpoch(ns / 1'000'000).toString(QStringLiteral("HH:mm:ss.zzz"));
        };
        const QString firstLost = clock(lost), secondLost = clock(lost + 3'000'000'000LL);
        for (const int role : {int(Qt::DisplayRole), int(Qt::ToolTipRole)}) {
            const QString text = m->index(200, TraceModel::Summary).data(role).toString();
            QCOMPARE(text.count(QStringLiteral("Bus lost at")), 2);
            QVERIFY2(text.indexOf(firstLost) >= 0 && text.indexOf(firstLost) < text.indexOf(secondLost),
                     qPrintable(text));
        }
        QVERIFY(m->index(199, TraceModel::Summary).data().toString().indexOf(QStringLiteral("Bus lost")) < 0);
        QVERIFY(m->index(201, TraceModel::Summary).data().toString().indexOf(QStringLiteral("Bus lost")) < 0);
        // Find (the find field, Enter) reaches the row by the text of the second gap.
        auto* find = w.traceDock()->findChild<QLineEdit*>(QStringLiteral("findEdit"));
        QVERIFY(find);
        coscope::testing::typeAndEnter(find, secondLost);
        QVERIFY(waitFor([&] { return w.traceDock()->view()->currentRow() == 200; }));
    }

    // Issue 16 "Bounded memory" for File ▸ Open: a log larger than the trace memory budget is
    // read through a spill journal; the trace keeps about the budget in RAM, pages the rest back
    // identical, and the spill goes away with the trace.
    void openedLogStaysWithinTheBudget() {
        QSettings().setValue(QStringLiteral("trace/memoryBudgetMB"), 4);
        const QString log = data_.filePath(QStringLiteral("big.log"));
        constexpr uint32_t kFrames = 8 * TraceStore::kChunkSize + 123;  // 12 MB of records in RAM
        {
            QFile f(log);
            QVERIFY(f.open(QIODevice::WriteOnly));
            QByteArray text;
            for (uint32_t i = 0; i < kFrames; ++i) {
                text += QStringLiteral("(1700000000.%1) can%2 %3#%4\n")
                            .arg(i, 6, 10, QLatin1Char('0'))
                            .arg(i % 7 == 3 ? 1 : 0)
                            .arg(0x181 + i % 3, 3, 16, QLatin1Char('0'))
                            .arg(i, 8, 16, QLatin1Char('0'))
                            .toLatin1();
                if (text.size() > (1 << 20)) {
                    f.write(text);
                    text.clear();
                }
            }
            f.write(text);
        }
        MainWindow w;
        w.setQuiet(true);
        QVERIFY(w.openLog(log));
        QVERIFY(waitFor([&] { return w.workspace()->loadJob() && w.workspace()->loadJob()->isDone(); }, 120000));
        auto store = w.workspace()->store();
        QCOMPARE(store->size(), size_t(kFrames));
        const QString spill = w.workspace()->loadJob()->spillPath();
        QVERIFY(spill.startsWith(capturesFolder() + QStringLiteral("/opened/")));
        QVERIFY(QFileInfo::exists(spill));
        const bool within = waitFor([&] { return store->memoryBytes() <= (size_t(6) << 20); });
        QVERIFY2(
            within,
            qPrintable(
                QStringLiteral("%1 bytes in RAM, %2 chunks").arg(store->memoryBytes()).arg(store->residentChunks())));
        QVERIFY2(store->residentChunks() <= 3, qPrintable(QString::number(store->residentChunks())));
        const uint64_t pageInsBefore = store->pageIns();
        for (uint32_t i : {0u, 1u, 3u, 70000u, 3 * TraceStore::kChunkSize + 10, kFrames - 1}) {
            const CanFrame f = store->frame(i);
            QCOMPARE(f.id, 0x181u + i % 3);
            QCOMPARE(int(f.bus), i % 7 == 3 ? 1 : 0);
            QCOMPARE(f.timestampNs, 1'700'000'000'000'000'000LL + int64_t(i) * 1000);
            QCOMPARE(f.data[3], uint8_t(i));
        }
        QVERIFY(store->pageIns() > pageInsBefore);
        QCOMPARE(store->pageErrors(), uint64_t(0));
        QVERIFY(!QFileInfo::exists(CaptureJournal::sidecarOf(spill)));  // never offered as an unclosed capture
        w.workspace()->clear();
        QVERIFY(!QFileInfo::exists(spill));
        QSettings().remove(QStringLiteral("trace/memoryBudgetMB"));
    }

    void dismissKeepsTheJournalAndOffersTheNext() {
        const QString older = makeUnclosedJournal(QStringLiteral("capture-a.pcapng"), 5);
        QVERIFY(setModified(older, QDateTime::currentDateTime().addSecs(-60)));
        QVERIFY(setModified(CaptureJournal::sidecarOf(older), QDateTime::currentDateTime().addSecs(-60)));
        const QString newer = makeUnclosedJournal(QStringLiteral("capture-b.pcapng"), 5);
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QCOMPARE(w.journalOffer()->offeredPath(), newer);
        QTest::mouseClick(w.journalOffer()->dismissButton(), Qt::LeftButton);
        QCOMPARE(w.journalOffer()->offeredPath(), older);
        QVERIFY(w.journalOffer()->isVisible());
        QTest::mouseClick(w.journalOffer()->dismissButton(), Qt::LeftButton);
        QVERIFY(!w.journalOffer()->isVisible());
        QVERIFY(QFileInfo::exists(newer) && QFileInfo::exists(older));
        QCOMPARE(w.workspace()->store()->size(), size_t(0));
    }

    void oldJournalsAreRemovedAtStart() {
        QSettings().setValue(QStringLiteral("captures/keepDays"), 3);
        const QString unclosedOld = makeUnclosedJournal(QStringLiteral("capture-unclosed.pcapng"), 5);
        const QString old = makeUnclosedJournal(QStringLiteral("capture-old.pcapng"), 5);
        QFile::remove(CaptureJournal::sidecarOf(old));  // closed, 5 days old
        const QString recent = makeUnclosedJournal(QStringLiteral("capture-recent.pcapng"), 5);
        QFile::remove(CaptureJournal::sidecarOf(recent));
        for (const QString& p : {unclosedOld, old}) QVERIFY(setModified(p, QDateTime::currentDateTime().addDays(-5)));
        MainWindow w;
        w.setQuiet(true);
        QVERIFY(waitFor([&] { return !QFileInfo::exists(old); }));  // on a worker thread
        QVERIFY(QFileInfo::exists(recent));
        QVERIFY(QFileInfo::exists(unclosedOld));  // not offered yet: kept
        QCOMPARE(w.journalOffer()->offeredPath(), unclosedOld);
    }
};

QTEST_MAIN(TestCaptureJournalGui)
#include "test_capture_journal.moc"
