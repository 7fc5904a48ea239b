// SPDX-License-Identifier: GPL-3.0-or-later
// The Plot dock on words and factors as a manual writes them (issue 35, item 7), in the main
// window on a log, through clicks and keys: a Delta ASDA-A2 (node 7, by its 1018h) in homing
// mode sends its statusword, mode and position in TPDO1. The statusword plotted as a value has a
// hex axis and a hex cursor readout ("1637h"); its bits 12/13 are named by the mode the drive
// reports (HM: "homing attained", "homing error"; CiA 402-2 §13.1), the names the trace gives;
// the position's factor reads "1/1280000" (PUU per revolution, extract-delta-asda-a2 §4.7), a
// fraction typed into the factor cell is kept as typed; the legend shows "Pos_Cmd" with its
// underscore and stays clear of the value axis.
#include "app/gui/MainWindow.h"
#include "app/gui/plot/PlotDock.h"
#include "app/gui/plot/PlotView.h"
#include "app/gui/plot/SignalPicker.h"
#include "app/gui/session/Workspace.h"
#include "eds/SimulatorDictionaries.h"

#include <QFile>
#include <QHeaderView>
#include <QLineEdit>
#include <QRegularExpression>
#include <QSettings>
#include <QStyleOptionViewItem>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest>

#include "tests/gui/DriveLog.h"
#include "tests/gui/WaitFor.h"

#include <qcustomplot.h>

using namespace coscope;
using namespace coscope::gui;
using dissect::SignalKey;

namespace {
using coscope::testing::DriveLog;
using coscope::testing::waitFor;
constexpr int kFrames = 100;
uint16_t statusword(int i) { return i < 50 ? 0x0637 : 0x1637; }  // bit 12 on from frame 50: homing attained

// candump -L: node 7 says it is a Delta ASDA-A2 (1018h), gets TPDO1 = 6041h/16, 6061h/8,
// 6064h/32 by SDO, then sends TPDO1 every 10 ms in homing mode (6061h = 6).
QString writeLog(const QString& path) {
    DriveLog log(100.0);
    log.identifyDeltaAsda(7);
    log.mapTpdo(7, 1, {0x60410010, 0x60610008, 0x60640020});
    log.mapTpdo(7, 2, {0x60C10120});  // 60C1h:01 "Position command (Pos_Cmd)"
    log.setTime(101.0);
    for (int i = 0; i < kFrames; ++i) {
        log.line(QStringLiteral("187#") + DriveLog::le(statusword(i), 2) + DriveLog::le(6, 1) +
                 DriveLog::le(uint32_t(1280 * i), 4));
        log.line(QStringLiteral("287#") + DriveLog::le(uint32_t(640 * i), 4), 0.01);
    }
    return log.write(path) ? path : QString();
}

// The picker's row of `object` ("6041:00") or of bit `bit` of it under node 7.
QTreeWidgetItem* row(QTreeWidget* tree, const QString& object, int bit = -1) {
    for (int i = 0; i < tree->topLevelItemCount(); ++i) {
        QTreeWidgetItem* g = tree->topLevelItem(i);
        if (!g->text(0).startsWith(QStringLiteral("Node 7"))) continue;
        for (int k = 0; k < g->childCount(); ++k) {
            QTreeWidgetItem* w = g->child(k);
            if (w->text(1) != object) continue;
            if (bit < 0) return w;
            for (int b = 0; b < w->childCount(); ++b)
                if (w->child(b)->text(1) == QStringLiteral("bit %1").arg(bit)) return w->child(b);
        }
    }
    return nullptr;
}

// Clicks the check box of `item` where the tree's style draws it.
bool clickCheckBox(QTreeWidget* tree, QTreeWidgetItem* item) {
    tree->scrollToItem(item);
    const QRect r = tree->visualItemRect(item);
    QStyleOptionViewItem option;
    option.initFrom(tree->viewport());
    option.rect = QRect(r.left(), r.top(), tree->columnWidth(0) - (r.left() + tree->header()->offset()), r.height());
    option.features = QStyleOptionViewItem::HasCheckIndicator | QStyleOptionViewItem::HasDisplay;
    option.text = item->text(0);
    option.checkState = item->checkState(0);
    const QRect box = tree->style()->subElementRect(QStyle::SE_ItemViewItemCheckIndicator, &option, tree);
    const Qt::CheckState was = item->checkState(0);
    QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, box.center());
    return item->checkState(0) != was;
}
}  // namespace

class TestPlotWords : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_plot_words"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
        QVERIFY(dir_.isValid());
    }

    void statuswordAndFactorAsWritten() {
        const QString log = writeLog(dir_.filePath(QStringLiteral("homing.log")));
        QVERIFY(!log.isEmpty());
        MainWindow w;
        w.setQuiet(true);
        w.resize(1400, 900);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openLog(log));
        QVERIFY(waitFor([&] { return w.workspace()->loadJob()->isDone(); }));
        w.refresh();
        QVERIFY(w.showView(QStringLiteral("plot")));
        PlotDock* dock = w.plotDock();
        auto* tree = dock->findChild<QTreeWidget*>(QStringLiteral("signalTree"));
        QVERIFY(tree);
        QVERIFY(waitFor([&] {
            w.refresh();
            return row(tree, QStringLiteral("6041:00"), 12) != nullptr;
        }));

        // Bits 12/13 by the drive's mode (HM), as the trace names them.
        QCOMPARE(row(tree, QStringLiteral("6041:00"), 12)->text(0), QStringLiteral("homing attained"));
        QCOMPARE(row(tree, QStringLiteral("6041:00"), 13)->text(0), QStringLiteral("homing error"));
        QCOMPARE(row(tree, QStringLiteral("6041:00"), 10)->text(0), QStringLiteral("target reached"));

        // The position's factor as the vendor's rule writes it, not 7.8125e-07.
        QTreeWidgetItem* position = row(tree, QStringLiteral("6064:00"));
        QVERIFY(position);
        QCOMPARE(position->text(2), QStringLiteral("rev"));
        QCOMPARE(position->text(3), QStringLiteral("1/1280000"));
        // A fraction typed into the cell is taken and kept as typed.
        tree->scrollToItem(position);
        const QPoint cell(tree->header()->sectionViewportPosition(3) + tree->header()->sectionSize(3) / 2,
                          tree->visualItemRect(position).center().y());
        // What the mouse sends for a double click: press, release, double-click, release.
        QTest::mouseClick(tree->viewport(), Qt::LeftButton, {}, cell);
        QTest::mouseDClick(tree->viewport(), Qt::LeftButton, {}, cell);
        QTest::mouseRelease(tree->viewport(), Qt::LeftButton, {}, cell);
        auto* editor = tree->viewport()->findChild<QLineEdit*>();
        QVERIFY(waitFor([&] { return (editor = tree->viewport()->findChild<QLineEdit*>()) && editor->isVisible(); }));
        QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(editor, QStringLiteral("1/128000"));
        QTest::keyClick(editor, Qt::Key_Return);
        QVERIFY(waitFor([&] { return row(tree, QStringLiteral("6064:00"))->text(3) == u"1/128000"; }));
        QCOMPARE(dock->picker()->scale(SignalKey{0, 7, 0x6064, 0, -1}).factor, 1.0 / 128000);

        // The statusword as a value: only it on the plot, hex axis.
        for (const SignalKey& k : dock->pickedSignals())
            clickCheckBox(tree, row(tree, k.index == 0x6064 ? QStringLiteral("6064:00") : QStringLiteral("6041:00")));
        QVERIFY(dock->pickedSignals().empty());
        QVERIFY(clickCheckBox(tree, row(tree, QStringLiteral("6041:00"))));
        QCOMPARE(dock->pickedSignals(), (std::vector<SignalKey>{SignalKey{0, 7, 0x6041, 0, -1}}));
        dock->refresh();
        QCustomPlot* cp = dock->view()->customPlot();
        cp->replot();
        QCPAxis* y = cp->axisRect(0)->axis(QCPAxis::atLeft);
        const QVector<QString> labels = y->tickVectorLabels();
        QVERIFY(!labels.isEmpty());
        for (const QString& l : labels)
            QVERIFY2(QRegularExpression(QStringLiteral("^[0-9A-F]{4,}h$")).match(l).hasMatch(), qPrintable(l));

        // A click places cursor A: the readout says the statusword in hex.
        QCPAxisRect* rect = cp->axisRect(0);
        const double tLate = dock->view()->drawnPoints(0).back().first - 0.05;
        QTest::mouseClick(cp, Qt::LeftButton, Qt::NoModifier,
                          QPoint(int(rect->axis(QCPAxis::atBottom)->coordToPixel(tLate)), rect->rect().center().y()));
        QVERIFY2(dock->view()->readoutHtml().contains(QStringLiteral(">1637h<")),
                 qPrintable(dock->view()->readoutHtml()));

        // A name with underscores, as the dictionary writes it, in the legend.
        QVERIFY(clickCheckBox(tree, row(tree, QStringLiteral("60C1:01"))));
        dock->refresh();
        cp->replot();
        QCOMPARE(cp->legend->itemCount(), 2);
        const QString second = static_cast<QCPPlottableLegendItem*>(cp->legend->item(1))->plottable()->name();
        QVERIFY2(second.contains(QStringLiteral("(Pos_Cmd)")), qPrintable(second));
        // All of its text is drawn: a layer draws clipped one pixel up of the entry's box
        // (QCPLayer::draw), the underscore sits in the font's lowest row.
        for (int i = 0; i < cp->legend->itemCount(); ++i) {
            QCPAbstractLegendItem* entry = cp->legend->item(i);
            const QRect drawn = entry->outerRect().translated(0, -1);
            QVERIFY2(drawn.bottom() >= entry->rect().top() + QFontMetrics(entry->font()).height() - 1,
                     qPrintable(second));
        }
        if (const QString grab = qEnvironmentVariable("COSCOPE_GRAB_DIR"); !grab.isEmpty())
            cp->savePng(grab + QStringLiteral("/plot_words.png"));

        // The legend is inside the plot, clear of the value axis and its tick marks (the axis
        // rect and axis of now: adding a signal rebuilt them).
        rect = cp->axisRect(0);
        y = rect->axis(QCPAxis::atLeft);
        QVERIFY(cp->legend && cp->legend->visible());
        QVERIFY2(cp->legend->outerRect().left() >= rect->left() + y->tickLengthIn() + 2,
                 qPrintable(
                     QStringLiteral("legend at %1, axis at %2").arg(cp->legend->outerRect().left()).arg(rect->left())));
        QVERIFY(cp->legend->outerRect().top() >= rect->top() + 2);
    }
};

QTEST_MAIN(TestPlotWords)
#include "test_plot_words.moc"
