// SPDX-License-Identifier: GPL-3.0-or-later
// Devices without a dictionary in the window: a log whose nodes have none, Plot ▸ Add raw
// signal… typed in by hand (Motorola, signed, factor, offset, unit) plots the frames' values;
// the signal is kept with the workspace and offered again for its COB-ID after a restart; and
// File ▸ Export PDO layout as DBC writes the layout learnt from the log plus the raw signal.
#include "app/gui/MainWindow.h"
#include "app/gui/plot/PlotDock.h"
#include "app/gui/plot/SignalPicker.h"
#include "app/gui/session/Workspace.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFile>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QToolButton>
#include <QTreeWidget>
#include <QtTest>

#include "DbcReader.h"
#include "tests/gui/MenuClick.h"
#include "tests/gui/ModalAnswer.h"
#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::answerFileDialog;
using coscope::testing::clickMenuItem;
using coscope::testing::ModalAnswerer;
using coscope::testing::waitFor;

namespace {
constexpr int kFrames = 40;
int16_t speedRaw(int i) { return static_cast<int16_t>(i * 25 - 300); }  // crosses zero: signed matters

// candump -L: node 16 gets its TPDO1 mapping (6041h/16, 6064h/32) by SDO, node 32 sends TPDO2
// (2A0h) that no dictionary describes: a big-endian speed in bytes 0..1 and a level in byte 2.
QString writeLog(const QString& path) {
    QStringList l = {
        QStringLiteral("(100.000000) can0 710#00"),
        QStringLiteral("(100.001000) can0 720#00"),
        QStringLiteral("(100.010000) can0 610#2F001A0000000000"),
        QStringLiteral("(100.011000) can0 590#60001A0000000000"),
        QStringLiteral("(100.012000) can0 610#23001A0110004160"),
        QStringLiteral("(100.013000) can0 590#60001A0100000000"),
        QStringLiteral("(100.014000) can0 610#23001A0220006460"),
        QStringLiteral("(100.015000) can0 590#60001A0200000000"),
        QStringLiteral("(100.016000) can0 610#2F001A0002000000"),
        QStringLiteral("(100.017000) can0 590#60001A0000000000"),
    };
    for (int i = 0; i < kFrames; ++i) {
        const auto u = static_cast<uint16_t>(speedRaw(i));
        l << QStringLiteral("(%1) can0 2A0#%2%3%4")
                 .arg(101.0 + 0.01 * i, 0, 'f', 6)
                 .arg(u >> 8, 2, 16, QLatin1Char('0'))
                 .arg(u & 0xFF, 2, 16, QLatin1Char('0'))
                 .arg(i, 2, 16, QLatin1Char('0'));
        l << QStringLiteral("(%1) can0 190#3716%2").arg(101.005 + 0.01 * i, 0, 'f', 6).arg(i, 2, 16, QLatin1Char('0')) +
                 QStringLiteral("000000");
    }
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Text)) return {};
    f.write(l.join(u'\n').toUtf8() + "\n");
    return path;
}

bool openLoaded(MainWindow& w, const QString& path) {
    if (!w.openLog(path) || !waitFor([&] { return w.workspace()->loadJob()->isDone(); })) return false;
    w.refresh();
    return true;
}

// Types into a field as a user does: select what is there, type.
void typeInto(QWidget* field, const QString& text) {
    QTest::keyClick(field, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(field, text);
}

// The picker's group titles.
QStringList groups(PlotDock* dock) {
    QStringList t;
    auto* tree = dock->picker()->findChild<QTreeWidget*>();
    for (int i = 0; i < tree->topLevelItemCount(); ++i) t << tree->topLevelItem(i)->text(0);
    return t;
}

}  // namespace

class TestPlotRawSignal : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString log_;

private slots:
    void initTestCase() {
        QSettings().remove(QStringLiteral("plot/rawSignals"));  // a previous run's signals
        QVERIFY(dir_.isValid());
        log_ = writeLog(dir_.filePath(QStringLiteral("nodict.log")));
        QVERIFY(!log_.isEmpty());
    }

    void addRawSignalPlotsIt() {
        MainWindow w;
        w.setQuiet(true);
        w.resize(1400, 900);
        w.show();
        QVERIFY(openLoaded(w, log_));
        QVERIFY(w.showView(QStringLiteral("plot")));
        PlotDock* dock = w.plotDock();
        QVERIFY(dock->pickedSignals().empty());

        // The dialog, filled in by keys: speed = Motorola signed 16 bits from bit 7, x 0.5 - 10 rpm.
        bool typed = false;
        QString offered;
        ModalAnswerer fill([&](QWidget* modal) {
            auto* name = modal->findChild<QLineEdit*>(QStringLiteral("rawName"));
            if (!name) return false;
            auto* cob = modal->findChild<QLineEdit*>(QStringLiteral("rawCobId"));
            offered = cob->text();
            typeInto(name, QStringLiteral("speed"));
            typeInto(cob, QStringLiteral("0x2A0"));
            typeInto(modal->findChild<QSpinBox*>(QStringLiteral("rawStart")), QStringLiteral("7"));
            typeInto(modal->findChild<QSpinBox*>(QStringLiteral("rawLength")), QStringLiteral("16"));
            QTest::keyClick(modal->findChild<QComboBox*>(QStringLiteral("rawType")), Qt::Key_Down);   // Signed
            QTest::keyClick(modal->findChild<QComboBox*>(QStringLiteral("rawOrder")), Qt::Key_Down);  // Motorola
            typeInto(modal->findChild<QLineEdit*>(QStringLiteral("rawFactor")), QStringLiteral("0.5"));
            typeInto(modal->findChild<QLineEdit*>(QStringLiteral("rawOffset")), QStringLiteral("-10"));
            typeInto(modal->findChild<QLineEdit*>(QStringLiteral("rawUnit")), QStringLiteral("rpm"));
            auto* buttons = modal->findChild<QDialogButtonBox*>(QStringLiteral("buttonBox"));
            QTest::mouseClick(buttons->button(QDialogButtonBox::Ok), Qt::LeftButton);
            typed = true;
            return true;
        });
        auto* add = dock->findChild<QToolButton*>(QStringLiteral("addRawSignal"));
        QVERIFY(add);
        QTest::mouseClick(add, Qt::LeftButton);
        QVERIFY(typed);
        QCOMPARE(offered, QStringLiteral("0x2A0"));  // the PDO nothing describes is offered first

        // The log is recorded again with the signal; the dock picks it and plots every frame.
        QVERIFY(waitFor([&] {
            return dock->view()->plotted().size() == 1 && dock->view()->drawnPoints(0).size() == size_t(kFrames);
        }));
        QCOMPARE(dock->view()->plotted()[0].label, QStringLiteral("speed"));
        QCOMPARE(dock->view()->axisTitle(0), QStringLiteral("rpm"));
        const auto pts = dock->view()->drawnPoints(0);
        for (int i = 0; i < kFrames; ++i) QCOMPARE(pts[static_cast<size_t>(i)].second, speedRaw(i) * 0.5 - 10);
        QVERIFY(pts.front().second < 0 && pts.back().second > 0);
        QVERIFY(groups(dock).contains(QStringLiteral("COB-ID 2A0h (raw signals)")));

        // File ▸ Export PDO layout as DBC: node 16's TPDO1 from the log's SDO writes + the raw signal.
        const QString dbcPath = dir_.filePath(QStringLiteral("layout.dbc"));
        auto answer = answerFileDialog(dbcPath);
        QVERIFY(clickMenuItem(w, QStringLiteral("File"), QStringLiteral("Export PDO layout as DBC")));
        QVERIFY(waitFor([&] { return QFileInfo::exists(dbcPath) && QFileInfo(dbcPath).size() > 0; }));
        QFile f(dbcPath);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const dbc::File file = dbc::parse(f.readAll());
        QVERIFY2(file.errors.isEmpty(), qPrintable(file.errors.join(u'\n')));
        QVERIFY(file.messages.count(0x190));
        QCOMPARE(file.messages.at(0x190).sigs.size(), size_t(2));
        QVERIFY(file.messages.count(0x2A0));
        const dbc::Signal* speed = file.messages.at(0x2A0).find(QStringLiteral("speed"));
        QVERIFY(speed && !speed->intel && speed->isSigned && speed->unit == QStringLiteral("rpm"));
        const QByteArray frame = QByteArray::fromHex("FEE8");  // -280 raw
        QCOMPARE(dbc::decode(*speed, frame).value(), -150.0);
    }

    void offeredAgainAfterRestart() {
        // A new window (as after a restart) reads the same log: the raw signal is listed again
        // under its COB-ID, nothing to type.
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(openLoaded(w, log_));
        QCOMPARE(w.workspace()->rawSignals().size(), size_t(1));
        PlotDock* dock = w.plotDock();
        dissect::SignalKey key;
        key.raw = 1;
        QVERIFY(waitFor([&] {
            w.refresh();
            return dock->picker()->info(key) != nullptr;
        }));
        QCOMPARE(dock->picker()->info(key)->name, QStringLiteral("speed"));
        QCOMPARE(dock->picker()->scale(key).unit, QStringLiteral("rpm"));
        QVERIFY(groups(dock).contains(QStringLiteral("COB-ID 2A0h (raw signals)")));
    }
};

QTEST_MAIN(TestPlotRawSignal)
#include "test_plot_raw_signal.moc"
