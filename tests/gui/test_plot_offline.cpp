// SPDX-License-Identifier: GPL-3.0-or-later
// The Plot dock on a log file: open it, the signals of the PDO mappings written by SDO in the
// log are offered, the whole file is plotted, a click names the frame, and a Delta ASDA-A2
// (identified by 1018h in the log) gets its position in revolutions from 6093h
// (extract-delta-asda-a2 §4.7: PUU per rev = 1280000 x 6093h:02 / 6093h:01) and its velocity
// in rpm (0.1 rpm units).
#include "app/gui/plot/PlotDock.h"
#include "app/gui/plot/SignalPicker.h"
#include "app/gui/session/Workspace.h"

#include <QFile>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

#include "tests/gui/DriveLog.h"
#include "tests/gui/WaitFor.h"

#include <qcustomplot.h>

using namespace coscope;
using namespace coscope::gui;
using dissect::SignalKey;

namespace {
using coscope::testing::DriveLog;
using coscope::testing::waitFor;
QString le32(int32_t v) { return DriveLog::le(uint32_t(v), 4); }
constexpr int kFrames = 200;
int32_t position5(int i) { return -5000 + 100 * i; }
int32_t velocity5(int i) { return (i % 50) * 10 - 200; }

// A candump -L log: node 5 (no dictionary) and node 7 (a Delta ASDA-A2 by its 1018h) get
// TPDO1 = 6064h + 606Ch by SDO writes, then TPDO1s every 10 ms (8 ms + the 1 ms each line adds).
QString writeLog(const QString& path) {
    DriveLog log(1700000000.0);
    log.identifyDeltaAsda(7);
    for (int node : {5, 7}) log.mapTpdo(node, 1, {0x60640020, 0x606C0020});
    log.sdoWrite(7, 0x6093, 1, 1, 4);   // 6093h:01 = 1
    log.sdoWrite(7, 0x6093, 2, 10, 4);  // 6093h:02 = 10 -> 12 800 000 PUU/rev
    log.line(QStringLiteral("000#0100"));
    log.setTime(1700000001.0);
    for (int i = 0; i < kFrames; ++i) {
        log.line(QStringLiteral("185#") + le32(position5(i)) + le32(velocity5(i)));
        log.line(QStringLiteral("187#") + le32(1280000 + 6400 * i) + le32(1500), 0.009);
    }
    return log.write(path) ? path : QString();
}
}  // namespace

class TestPlotOffline : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void plotsTheWholeLog() {
        QVERIFY(dir_.isValid());
        const QString log = writeLog(dir_.filePath(QStringLiteral("drive.log")));
        QVERIFY(!log.isEmpty());
        Workspace ws;
        PlotDock dock(&ws);
        dock.resize(1200, 700);
        dock.show();
        connect(&ws, &Workspace::sourceChanged, &dock, &PlotDock::rebind);
        QString error;
        QVERIFY2(ws.openLog(log, &error), qPrintable(error));
        QVERIFY(waitFor([&] { return ws.loadJob()->isDone(); }));
        ws.poll();
        dock.refresh();
        QVERIFY(dock.wholeTrace());

        // The catalogue: both nodes' TPDO1 objects, typed by the dictionary (signed).
        const SignalKey pos5{0, 5, 0x6064, 0, -1}, vel5{0, 5, 0x606C, 0, -1};
        const SignalKey pos7{0, 7, 0x6064, 0, -1}, vel7{0, 7, 0x606C, 0, -1};
        for (const SignalKey& k : {pos5, vel5, pos7, vel7}) QVERIFY2(dock.picker()->info(k), qPrintable(k.text()));
        QCOMPARE(dock.picker()->info(pos5)->pdo, QStringLiteral("TPDO1"));
        QCOMPARE(dock.picker()->info(pos7)->dictionary, QStringLiteral("delta-asda-a2"));

        // Auto-picked: the first node carrying position and velocity (node 5), whole file.
        QCOMPARE(dock.pickedSignals(), (std::vector<SignalKey>{pos5, vel5}));
        const auto pts = dock.view()->drawnPoints(0);
        QCOMPARE(pts.size(), size_t(kFrames));  // fewer samples than pixels: every sample drawn
        for (int i = 0; i < kFrames; ++i) QCOMPARE(pts[static_cast<size_t>(i)].second, double(position5(i)));
        const auto vpts = dock.view()->drawnPoints(1);
        QCOMPARE(vpts[7].second, double(velocity5(7)));
        QVERIFY(vpts[0].second < 0);  // INTEGER32 from the generic CiA 402 names: signed
        const auto [from, to] = dock.view()->timeRange();
        QCOMPARE(from, 0.0);
        QVERIFY(to >= pts.back().first);
        QVERIFY(dock.hasContent());

        // Search narrows the list; a pick adds a trace.
        dock.picker()->setFilter(QStringLiteral("velocity"));
        dock.picker()->setFilter(QString());

        // Delta: revolutions from 6093h, rpm from 0.1 rpm.
        QCOMPARE(dock.picker()->scale(pos7).unit, QStringLiteral("rev"));
        QCOMPARE(dock.picker()->scale(vel7).unit, QStringLiteral("rpm"));
        dock.pick(pos5, false);
        dock.pick(vel5, false);
        dock.pick(pos7);
        dock.pick(vel7);
        dock.refresh();
        const double tFirst = dock.view()->drawnPoints(0).front().first;
        QCOMPARE(*dock.view()->valueAt(0, tFirst), 0.1);    // 1 280 000 PUU / 12 800 000
        QCOMPARE(*dock.view()->valueAt(1, tFirst), 150.0);  // 1500 x 0.1 rpm
        QCOMPARE(dock.view()->axisTitle(0), QStringLiteral("rev"));
        // The user's factor and unit.
        dock.picker()->setScale(vel7, {0.1 / 60.0, 0.0, QStringLiteral("rps")});  // raw 0.1 rpm -> rps
        dock.refresh();
        QCOMPARE(*dock.view()->valueAt(1, tFirst), 2.5);
        QCOMPARE(dock.view()->axisTitle(1), QStringLiteral("rps"));

        // Cursors: A and B read values and differences.
        dock.view()->setCursor(0, tFirst);
        dock.view()->setCursor(1, tFirst + 1.004);  // sample 100 (10 ms apart): +640 000 PUU = 0.05 rev
        QCOMPARE(*dock.view()->valueAt(0, tFirst + 1.004) - *dock.view()->valueAt(0, tFirst), 0.05);
        QVERIFY(dock.view()->readoutHtml().contains(QStringLiteral("&Delta;t = 1.004 s")));

        // A click jumps to the frame of the nearest sample.
        QSignalSpy jumps(&dock, &PlotDock::frameActivated);
        QCustomPlot* cp = dock.view()->customPlot();
        QCPAxisRect* rect = cp->axisRect(0);
        const double tClick = tFirst + 0.4;  // sample 40
        const QPoint at(int(rect->axis(QCPAxis::atBottom)->coordToPixel(tClick)), rect->rect().center().y());
        QTest::mouseClick(cp, Qt::LeftButton, Qt::NoModifier, at);
        QCOMPARE(jumps.count(), 1);
        const auto frame = jumps.at(0).at(0).value<uint32_t>();
        QCOMPARE(ws.store()->record(frame).id, 0x187u);
        const int64_t origin = dock.view()->origin();
        QVERIFY(std::abs(double(ws.store()->record(frame).timestampNs - origin) / 1e9 - tClick) < 0.006);

        // Zoom in (as a wheel or drag would): the view pauses, and CSV exports that window.
        dock.view()->setTimeRange(tFirst + 0.196, tFirst + 0.404);
        dock.setPaused(true);
        dock.refresh();
        const QString csv = dir_.filePath(QStringLiteral("window.csv"));
        QString err;
        QVERIFY2(dock.exportCsv(csv, &err), qPrintable(err));
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly | QIODevice::Text));
        const QStringList lines = QString::fromUtf8(f.readAll()).split(u'\n', Qt::SkipEmptyParts);
        QCOMPARE(lines[0],
                 QStringLiteral("time_s,frame,n7 Position actual value [rev],n7 Velocity actual value [rps]"));
        QCOMPARE(lines.size(), 1 + 21);  // samples 20..40 (10 ms apart)
        const QStringList first = lines[1].split(u',');
        QCOMPARE(first[2].toDouble(), (1280000 + 6400 * 20) / 12800000.0);
        QCOMPARE(first[3].toDouble(), 2.5);

        // Empty trace: nothing to plot, nothing picked.
        ws.clear();
        dock.refresh();
        QVERIFY(dock.pickedSignals().empty());
        QVERIFY(!dock.hasContent());
    }

    // Issue 37 item 7: node 5 sends every 10 ms for 2 s, nothing for 30 s, then again: the line
    // breaks in the gap (no ramp that never happened) and nowhere else, whole trace or zoomed in.
    void noLineAcrossAGap() {
        DriveLog log(1700000000.0);
        log.mapTpdo(5, 1, {0x60640020, 0x606C0020});
        log.setTime(1700000001.0);
        for (int i = 0; i < 400; ++i) {
            if (i == 200) log.setTime(1700000033.0);
            log.line(QStringLiteral("185#") + le32(i < 200 ? 0 : 100000) + le32(0), 0.009);
        }
        const QString path = dir_.filePath(QStringLiteral("gap.log"));
        QVERIFY(log.write(path));
        Workspace ws;
        PlotDock dock(&ws);
        dock.resize(1200, 700);
        dock.show();
        connect(&ws, &Workspace::sourceChanged, &dock, &PlotDock::rebind);
        QString error;
        QVERIFY2(ws.openLog(path, &error), qPrintable(error));
        QVERIFY(waitFor([&] { return ws.loadJob()->isDone(); }));
        ws.poll();
        dock.refresh();
        auto breaks = [&] {
            std::vector<double> at;
            for (const auto& [t, v] : dock.view()->drawnPoints(0))
                if (!std::isfinite(v)) at.push_back(t);
            return at;
        };
        const auto pts = dock.view()->drawnPoints(0);
        QVERIFY(!pts.empty());
        const double last = pts.front().first + 2.0;  // the last sample before the gap, about
        std::vector<double> at = breaks();
        QCOMPARE(at.size(), size_t(1));
        QVERIFY2(at[0] > last && at[0] < last + 30.0, qPrintable(QString::number(at[0])));
        // Zoomed in on the samples before the gap: one line, no break.
        dock.view()->setTimeRange(pts.front().first, pts.front().first + 1.5);
        dock.setPaused(true);
        dock.refresh();
        QVERIFY(breaks().empty());
    }
};

QTEST_MAIN(TestPlotOffline)
#include "test_plot_offline.moc"
