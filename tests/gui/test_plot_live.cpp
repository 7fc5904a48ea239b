// SPDX-License-Identifier: GPL-3.0-or-later
// The Plot dock on the virtual network (`coscope --simulate`): the demo enables the AIMOTOR
// drive (node 2) in profile velocity; the dock picks its position and velocity from TPDO1/2,
// the values move, the units are the AIMOTOR's (pulse, pulse/s: extract-aimotor §6), pause
// keeps recording, a click jumps to a frame and the CSV export holds the decoded values.
#include "app/gui/MainWindow.h"
#include "app/gui/plot/PlotDock.h"
#include "app/gui/plot/SignalPicker.h"
#include "app/gui/session/SimulationDemo.h"
#include "app/gui/session/Workspace.h"
#include "eds/SimulatorDictionaries.h"

#include <QFile>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

#include "tests/gui/WaitFor.h"

#include <qcustomplot.h>

using namespace coscope;
using namespace coscope::gui;
using dissect::SignalKey;

namespace {
using coscope::testing::waitFor;
const SignalKey kPosition{0, 2, 0x6064, 0, -1};
const SignalKey kVelocity{0, 2, 0x606C, 0, -1};

// The value of object index:sub in frame n as the trace decoder's PDO dissection gives it.
std::optional<double> decoded(Workspace* ws, FrameNo n, uint16_t index) {
    dissect::Dissection d;
    d.reset(dissect::Dissection::Level::Flat);
    ws->traceDecoder().decodeAt(*ws->store(), n, d);
    for (int i = 0; i < d.signalCount; ++i) {
        const dissect::PdoSignal& s = d.pdoSignals[static_cast<size_t>(i)];
        if (s.index != index) continue;
        switch (s.value.kind) {
        case dissect::FlatField::Kind::Int: return double(s.value.i);
        case dissect::FlatField::Kind::UInt: return double(s.value.u);
        case dissect::FlatField::Kind::Real: return s.value.d;
        default: return std::nullopt;
        }
    }
    return std::nullopt;
}
}  // namespace

class TestPlotLive : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_plot_live"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
        QVERIFY(dir_.isValid());
    }

    void plotsAMovingDrive() {
        MainWindow w;
        w.setQuiet(true);
        w.resize(1400, 900);
        w.show();
        QVERIFY(w.connectBus(QStringLiteral("sim://")));
        startSimulationDemo(w.workspace());
        QVERIFY(w.showView(QStringLiteral("plot")));
        PlotDock* dock = w.plotDock();

        // Auto-picked: position and velocity actual of the AIMOTOR (TPDO1/TPDO2).
        QVERIFY(waitFor([&] { return dock->pickedSignals().size() == 2; }));
        QCOMPARE(dock->pickedSignals()[0], kPosition);
        QCOMPARE(dock->pickedSignals()[1], kVelocity);
        const dissect::SignalInfo* pos = dock->picker()->info(kPosition);
        QVERIFY(pos);
        QCOMPARE(pos->pdo, QStringLiteral("TPDO1"));
        QCOMPARE(dock->picker()->scale(kPosition).unit, QStringLiteral("pulse"));
        QCOMPARE(dock->picker()->scale(kVelocity).unit, QStringLiteral("pulse/s"));
        QCOMPARE(dock->view()->axisTitle(0), QStringLiteral("pulse"));
        QCOMPARE(dock->view()->axisTitle(1), QStringLiteral("pulse/s"));

        // It moves: velocity reaches the demo's first target (3000 pulse/s), position grows.
        auto vel = w.workspace()->signalRecorder()->buffer(kVelocity);
        auto posBuf = w.workspace()->signalRecorder()->buffer(kPosition);
        QVERIFY(vel && posBuf);
        QVERIFY(waitFor([&] { return vel->last() && vel->last()->value >= 2999; }));
        const double p0 = posBuf->last()->value;
        QVERIFY(waitFor([&] { return posBuf->last()->value > p0 + 300; }));  // 0.1 s at 3000 pulse/s
        QVERIFY(waitFor([&] { return dock->hasContent(); }));
        // The plot draws what the buffer holds, scaled 1:1 (pulse).
        QVERIFY(waitFor([&] { return !dock->view()->drawnPoints(1).empty() && dock->view()->drawnPoints(1).back().second >= 2999; }));

        // A statusword bit as a digital trace: "operation enabled" is 1.
        const SignalKey enabledBit{0, 2, 0x6041, 0, 2};
        QVERIFY(dock->picker()->info(enabledBit) && dock->picker()->info(enabledBit)->digital);
        dock->pick(enabledBit);
        QCOMPARE(dock->view()->plotted().size(), size_t(3));
        QTest::qWait(100);
        const auto [f0, t0] = dock->view()->timeRange();
        QCOMPARE(dock->view()->valueAt(2, t0), std::optional<double>(1.0));
        dock->pick(enabledBit, false);

        // Pause: the view stays, the data keeps coming; resume follows again.
        dock->setWindowSeconds(2.0);  // shorter than the data so far: the window rolls
        QTest::qWait(100);
        dock->setPaused(true);
        const auto frozen = dock->view()->timeRange();
        const uint64_t before = vel->appended();
        QTest::qWait(600);
        QCOMPARE(dock->view()->timeRange(), frozen);
        QVERIFY(vel->appended() > before + 20);  // 100 Hz SYNC: ~60 samples in 0.6 s
        dock->setPaused(false);
        QVERIFY(waitFor([&] { return dock->view()->timeRange().second > frozen.second + 0.3; }, 3000));
        QVERIFY(std::abs(dock->view()->timeRange().second - dock->view()->timeRange().first - dock->windowSeconds()) < 1e-6);

        // A click in the plot places cursor A and names a TPDO frame of node 2.
        dock->setPaused(true);
        QSignalSpy jumps(dock, &PlotDock::frameActivated);
        QCustomPlot* cp = dock->view()->customPlot();
        const QRect area = cp->axisRect(0)->rect();
        QTest::mouseClick(cp, Qt::LeftButton, Qt::NoModifier, area.center());
        QCOMPARE(jumps.count(), 1);
        const auto frame = jumps.at(0).at(0).value<uint32_t>();
        const TraceRecord& r = w.workspace()->store()->record(frame);
        QVERIFY2(r.id == 0x182 || r.id == 0x282, qPrintable(QString::number(r.id, 16)));
        QVERIFY(dock->view()->cursor(0).has_value());
        QVERIFY(!dock->view()->readoutHtml().isEmpty());

        // CSV of the visible window: the decoded values, one row per frame.
        const QString csvPath = dir_.filePath(QStringLiteral("plot.csv"));
        QString error;
        QVERIFY2(dock->exportCsv(csvPath, &error), qPrintable(error));
        QFile f(csvPath);
        QVERIFY(f.open(QIODevice::ReadOnly | QIODevice::Text));
        const QStringList lines = QString::fromUtf8(f.readAll()).split(u'\n', Qt::SkipEmptyParts);
        QVERIFY(lines.size() > 50);  // 10 s at 100 Hz, two PDOs
        QCOMPARE(lines[0], QStringLiteral("time_s,frame,n2 Position actual value [pulse],n2 Velocity actual value [pulse/s]"));
        int checked = 0;
        for (int i = 1; i < lines.size(); ++i) {
            const QStringList c = lines[i].split(u',');
            QCOMPARE(c.size(), 4);
            const auto n = static_cast<FrameNo>(c[1].toUInt());
            for (int col = 2; col < 4; ++col) {
                if (c[col].isEmpty()) continue;
                const std::optional<double> v = decoded(w.workspace(), n, col == 2 ? 0x6064 : 0x606C);
                QVERIFY2(v, qPrintable(lines[i]));
                QCOMPARE(c[col].toDouble(), *v);
                ++checked;
            }
            const double t = c[0].toDouble();
            QVERIFY(t >= frozen.first - 1 && t <= dock->view()->timeRange().second + 0.001);
        }
        QVERIFY(checked > 50);

        // PNG and PDF of the plot.
        QVERIFY(dock->exportPng(dir_.filePath(QStringLiteral("plot.png"))));
        QVERIFY(QFileInfo(dir_.filePath(QStringLiteral("plot.png"))).size() > 1000);
        QVERIFY(dock->exportPdf(dir_.filePath(QStringLiteral("plot.pdf"))));
        QVERIFY(QFileInfo(dir_.filePath(QStringLiteral("plot.pdf"))).size() > 500);

        // Legend toggles hide a trace; the shared-plot layout keeps both.
        dock->view()->setGraphVisible(0, false);
        QVERIFY(!dock->view()->graphVisible(0));
        dock->setLayoutMode(PlotView::Layout::Overlay);
        QCOMPARE(dock->view()->customPlot()->axisRectCount(), 1);
        QCOMPARE(dock->view()->customPlot()->graphCount(), 2);
        w.disconnectBus();
    }
};

QTEST_MAIN(TestPlotLive)
#include "test_plot_live.moc"
