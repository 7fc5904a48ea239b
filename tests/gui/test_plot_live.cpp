// SPDX-License-Identifier: GPL-3.0-or-later
// The Plot dock on the virtual network (`coscope --simulate`): the demo enables the AIMOTOR
// drive (node 2) in profile velocity; the dock picks its position and velocity from TPDO1/2,
// the values move, the units are the AIMOTOR's (pulse, pulse/s: extract-aimotor §6), pause
// keeps recording, a click jumps to a frame and the CSV export holds the decoded values. The
// test acts as a user does (clicks and keys on the dock's widgets) and waits on the data itself,
// never for a time: it holds on a loaded machine or a sanitizer build.
#include "app/gui/MainWindow.h"
#include "app/gui/plot/PlotDock.h"
#include "app/gui/plot/SignalPicker.h"
#include "app/gui/session/SimulationDemo.h"
#include "app/gui/session/Workspace.h"
#include "eds/SimulatorDictionaries.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QHeaderView>
#include <QLineEdit>
#include <QMenu>
#include <QSettings>
#include <QStyleOptionViewItem>
#include <QTemporaryDir>
#include <QToolButton>
#include <QTreeWidget>
#include <QtTest>

#include <set>

#include "tests/gui/ItemClick.h"
#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/TypeText.h"
#include "tests/gui/WaitFor.h"

#include <qcustomplot.h>

using namespace coscope;
using namespace coscope::gui;
using dissect::SignalKey;

namespace {
using coscope::testing::answerFileDialog;
using coscope::testing::clickCheckBox;
using coscope::testing::menuItem;
using coscope::testing::signalItem;
using coscope::testing::typeAndEnter;
using coscope::testing::waitFor;
// However slow the machine (ASan, a loaded CI runner): waits end on what they wait for.
constexpr int kPatienceMs = 60000;
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

// Export ▸ `item`… as a user does: a click on the Export button, one on the menu item, the file
// name typed into the save dialog. True when the file is there.
bool exportThroughMenu(PlotDock* dock, const QString& item, const QString& path) {
    auto* button = dock->findChild<QToolButton*>(QStringLiteral("plotExport"));
    if (!button || !button->isVisible()) return false;
    const auto name = answerFileDialog(path);
    bool clicked = false;
    QTimer poll;  // the menu runs its own event loop inside the click on the button
    QObject::connect(&poll, &QTimer::timeout, [&] {
        auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
        if (!menu || !menu->isVisible()) return;
        poll.stop();
        if (QAction* a = menuItem(menu, item)) {
            clicked = true;
            QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(a).center());
        } else {
            QTest::keyClick(menu, Qt::Key_Escape);
        }
    });
    poll.start(20);
    QTest::mouseClick(button, Qt::LeftButton);
    return waitFor(
        [&] { return clicked && name->answered() && !QApplication::activeModalWidget() && QFileInfo::exists(path); },
        kPatienceMs);
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
        auto* pause = dock->findChild<QToolButton*>(QStringLiteral("plotPause"));
        auto* windowSeconds = dock->findChild<QDoubleSpinBox*>(QStringLiteral("plotWindowSeconds"));
        auto* layout = dock->findChild<QComboBox*>(QStringLiteral("plotLayout"));
        auto* search = dock->findChild<QLineEdit*>(QStringLiteral("signalSearch"));
        auto* tree = dock->findChild<QTreeWidget*>(QStringLiteral("signalTree"));
        QVERIFY(pause && windowSeconds && layout && search && tree);

        // Auto-picked: position and velocity actual of the AIMOTOR (TPDO1/TPDO2).
        QVERIFY(waitFor([&] { return dock->pickedSignals().size() == 2; }, kPatienceMs));
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
        QVERIFY(waitFor([&] { return vel->last() && vel->last()->value >= 2999; }, kPatienceMs));
        const double p0 = posBuf->last()->value;
        QVERIFY(waitFor([&] { return posBuf->last()->value > p0 + 300; }, kPatienceMs));  // 0.1 s at 3000 pulse/s
        QVERIFY(waitFor([&] { return dock->hasContent(); }, kPatienceMs));
        // The plot draws what the buffer holds, scaled 1:1 (pulse).
        QVERIFY(waitFor(
            [&] { return !dock->view()->drawnPoints(1).empty() && dock->view()->drawnPoints(1).back().second >= 2999; },
            kPatienceMs));

        // A statusword bit as a digital trace: "operation enabled" is 1. The user finds it by
        // its name in the search box and ticks its check box.
        const SignalKey enabledBit{0, 2, 0x6041, 0, 2};
        QVERIFY(dock->picker()->info(enabledBit) && dock->picker()->info(enabledBit)->digital);
        const QString bitName = dock->picker()->info(enabledBit)->name.section(QStringLiteral(": "), 1);
        typeAndEnter(search, bitName);
        QTreeWidgetItem* bitItem = nullptr;
        QVERIFY(waitFor(
            [&] { return (bitItem = signalItem(tree, 2, bitName)) && tree->visualItemRect(bitItem).isValid(); }));
        QVERIFY(clickCheckBox(tree, bitItem));
        QCOMPARE(dock->pickedSignals().size(), size_t(3));
        QCOMPARE(dock->pickedSignals()[2], enabledBit);
        QCOMPARE(dock->view()->plotted().size(), size_t(3));
        // The drive moves, so it is enabled now: the newest sample of the bit, at the window's end.
        QCOMPARE(dock->view()->valueAt(2, dock->view()->timeRange().second), std::optional<double>(1.0));
        QVERIFY((bitItem = signalItem(tree, 2, bitName)));
        QVERIFY(clickCheckBox(tree, bitItem));
        QCOMPARE(dock->pickedSignals(), (std::vector<SignalKey>{kPosition, kVelocity}));
        QCOMPARE(dock->view()->plotted().size(), size_t(2));
        QTest::mouseClick(search, Qt::LeftButton);
        QTest::keyClick(search, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClick(search, Qt::Key_Backspace);

        // A window of 2 s, shorter than the data so far (hasContent: 5 s): the window rolls.
        QVERIFY(windowSeconds->isVisible());
        QTest::mouseClick(windowSeconds, Qt::LeftButton);
        QTest::keyClick(windowSeconds, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(windowSeconds, QStringLiteral("2"));
        QTest::keyClick(windowSeconds, Qt::Key_Return);
        QCOMPARE(dock->windowSeconds(), 2.0);
        QVERIFY(waitFor(
            [&] {
                const auto [from, to] = dock->view()->timeRange();
                return from > 0 && std::abs(to - from - 2.0) < 1e-6;
            },
            kPatienceMs));

        // Pause: the view stays while the data keeps coming (half a second of it past the frozen
        // window, in the samples' own time); resume follows again.
        QVERIFY(pause->isVisible());
        QTest::mouseClick(pause, Qt::LeftButton);
        QVERIFY(dock->isPaused());
        const auto frozen = dock->view()->timeRange();
        const uint64_t before = vel->appended();
        QVERIFY(waitFor(
            [&] {
                return vel->appended() > before + 20 && vel->last()->timeNs > dock->view()->toNs(frozen.second + 0.5);
            },
            kPatienceMs));
        QCOMPARE(dock->view()->timeRange(), frozen);
        QTest::mouseClick(pause, Qt::LeftButton);
        QVERIFY(!dock->isPaused());
        QVERIFY(waitFor([&] { return dock->view()->timeRange().second > frozen.second + 0.3; }, kPatienceMs));
        QVERIFY(std::abs(dock->view()->timeRange().second - dock->view()->timeRange().first - dock->windowSeconds()) <
                1e-6);

        // A click in the plot places cursor A and names a TPDO frame of node 2.
        QTest::mouseClick(pause, Qt::LeftButton);
        QVERIFY(dock->isPaused());
        QSignalSpy jumps(dock, &PlotDock::frameActivated);
        QCustomPlot* cp = dock->view()->customPlot();
        const QRect area = cp->axisRect(0)->rect();
        // Beside the legend (a click on it hides a trace), as a user aims at the curve.
        QPoint at = area.center();
        for (int x = area.left() + 10;
             cp->legend && cp->legend->visible() && cp->legend->outerRect().contains(at) && x < area.right(); x += 10)
            at.setX(x);
        QVERIFY(!cp->legend || !cp->legend->visible() || !cp->legend->outerRect().contains(at));
        QTest::mouseClick(cp, Qt::LeftButton, Qt::NoModifier, at);
        QCOMPARE(jumps.count(), 1);
        const auto frame = jumps.at(0).at(0).value<uint32_t>();
        const TraceRecord& r = w.workspace()->store()->record(frame);
        QVERIFY2(r.id == 0x182 || r.id == 0x282, qPrintable(QString::number(r.id, 16)));
        QVERIFY(dock->view()->cursor(0).has_value());
        QVERIFY(!dock->view()->readoutHtml().isEmpty());

        // CSV of the visible window (Export ▸ CSV…): the decoded values, one row per frame that
        // carries a plotted signal in the window.
        const QString csvPath = dir_.filePath(QStringLiteral("plot.csv"));
        QVERIFY(exportThroughMenu(dock, QStringLiteral("CSV"), csvPath));
        const auto [from, to] = dock->view()->timeRange();
        std::set<FrameNo> framesInWindow;
        size_t samplesInWindow = 0;
        for (const auto& buffer : {posBuf, vel})
            for (const SignalSample& x : buffer->samples(dock->view()->toNs(from), dock->view()->toNs(to))) {
                framesInWindow.insert(x.frame);
                ++samplesInWindow;
            }
        QFile f(csvPath);
        QVERIFY(f.open(QIODevice::ReadOnly | QIODevice::Text));
        const QStringList lines = QString::fromUtf8(f.readAll()).split(u'\n', Qt::SkipEmptyParts);
        QVERIFY(!framesInWindow.empty());
        QCOMPARE(size_t(lines.size()), framesInWindow.size() + 1);
        QCOMPARE(lines[0],
                 QStringLiteral("time_s,frame,n2 Position actual value [pulse],n2 Velocity actual value [pulse/s]"));
        size_t checked = 0;
        int columnsSeen[4] = {};
        for (int i = 1; i < lines.size(); ++i) {
            const QStringList c = lines[i].split(u',');
            QCOMPARE(c.size(), 4);
            const auto n = static_cast<FrameNo>(c[1].toUInt());
            QVERIFY2(framesInWindow.count(n), qPrintable(lines[i]));
            for (int col = 2; col < 4; ++col) {
                if (c[col].isEmpty()) continue;
                const std::optional<double> v = decoded(w.workspace(), n, col == 2 ? 0x6064 : 0x606C);
                QVERIFY2(v, qPrintable(lines[i]));
                QCOMPARE(c[col].toDouble(), *v);
                ++checked;
                ++columnsSeen[col];
            }
            const double t = c[0].toDouble();
            QVERIFY(t >= frozen.first - 1 && t <= dock->view()->timeRange().second + 0.001);
        }
        QCOMPARE(checked, samplesInWindow);
        QVERIFY(columnsSeen[2] > 0 && columnsSeen[3] > 0);  // both PDOs

        // PNG and PDF of the plot (Export ▸ PNG…, PDF…).
        QVERIFY(exportThroughMenu(dock, QStringLiteral("PNG"), dir_.filePath(QStringLiteral("plot.png"))));
        QVERIFY(QFileInfo(dir_.filePath(QStringLiteral("plot.png"))).size() > 1000);
        QVERIFY(exportThroughMenu(dock, QStringLiteral("PDF"), dir_.filePath(QStringLiteral("plot.pdf"))));
        QVERIFY(QFileInfo(dir_.filePath(QStringLiteral("plot.pdf"))).size() > 500);

        // A click on a legend entry hides its trace; the shared-plot layout keeps both.
        QVERIFY(cp->legend && cp->legend->visible() && cp->legend->itemCount() == 2);
        QTest::mouseClick(cp, Qt::LeftButton, Qt::NoModifier, cp->legend->item(0)->rect().center());
        QVERIFY(!dock->view()->graphVisible(0));
        QVERIFY(dock->view()->graphVisible(1));
        QVERIFY(layout->isVisible());
        QTest::keyClick(layout, Qt::Key_Down);  // Stacked -> Shared plot
        QCOMPARE(dock->view()->layoutMode(), PlotView::Layout::Overlay);
        QCOMPARE(dock->view()->customPlot()->axisRectCount(), 1);
        QCOMPARE(dock->view()->customPlot()->graphCount(), 2);
        w.disconnectBus();
    }
};

QTEST_MAIN(TestPlotLive)
#include "test_plot_live.moc"
