// SPDX-License-Identifier: GPL-3.0-or-later
// The Object Dictionary dock in the real main window against the virtual drives (sim://):
// select a node, read one object, read all with progress, write through the type's editor with
// the confirmation answered, the value marked as changed from the default, a write the drive
// refuses shows the abort text on its row, listen-only disables reading and writing, and the
// node's values exported as a DCF.
#include "app/gui/MainWindow.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/od/IntegerSpinBox.h"
#include "app/gui/od/ObjectDictionaryDock.h"
#include "app/gui/od/OdFilterModel.h"
#include "app/gui/od/OdTreeModel.h"
#include "app/gui/session/Workspace.h"
#include "core/canopen/DeviceConfiguration.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"
#include "eds/EdsReader.h"
#include "eds/SimulatorDictionaries.h"

#include <QAction>
#include <QCheckBox>
#include <QLineEdit>
#include <QProgressBar>
#include <QSettings>
#include <QTableView>
#include <QTemporaryDir>
#include <QToolBar>
#include <QTreeView>
#include <QtTest>

#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;

namespace {
using coscope::testing::waitFor;

sim::SimNetwork* network(MainWindow& w) { return static_cast<SimBus*>(w.workspace()->bus())->network(); }

std::optional<od::Value> deviceValue(MainWindow& w, uint8_t node, uint16_t index, uint8_t sub) {
    std::optional<od::Value> v;
    network(w)->runOnNetworkThread([&] {
        if (auto* d = network(w)->device(node)) v = d->value(index, sub);
    });
    return v;
}
}  // namespace

class TestOdDock : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    // Connects, waits for the nodes and selects node 1 (its dictionary assigned like a scan would).
    bool connectAndSelect(MainWindow& w, const QString& url) {
        if (!w.connectBus(url)) return false;
        if (!waitFor([&] { return w.workspace()->bus()->state() == CanBus::State::Open; })) return false;
        if (!waitFor([&] { return w.workspace()->nodes().node(1).has_value(); })) return false;
        w.nodesDock()->assignDictionary(1, QStringLiteral("delta-asda-a2"));
        w.odDock()->setNode(1);
        w.refresh();
        return w.odDock()->model()->hasDictionary();
    }

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_od_dock"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
        QVERIFY(dir_.isValid());
    }

    void readWriteAndExport() {
        MainWindow w;
        w.setQuiet(true);
        w.show();
        w.showView(QStringLiteral("od"));
        QVERIFY(connectAndSelect(w, QStringLiteral("sim://")));
        ObjectDictionaryDock* dock = w.odDock();
        OdTreeModel* m = dock->model();
        QCOMPARE(dock->dictionaryName(), QStringLiteral("delta-asda-a2"));
        QVERIFY(m->indexOf(0x1017, 0).isValid());
        QCOMPARE(m->data(m->indexOf(0x1017, 0, OdTreeModel::Name), Qt::DisplayRole).toString(),
                 QStringLiteral("Producer heartbeat time"));

        // Read one: 1018h:01 vendor-ID of the Delta drive (dictionary 0x000001DD).
        QVERIFY(dock->readEntry(0x1018, 1));
        QVERIFY(waitFor([&] { return m->actualValue(0x1018, 1).has_value(); }));
        QCOMPARE(*m->actualValue(0x1018, 1)->toUInt64(), uint64_t(0x1DD));
        QVERIFY(m->data(m->indexOf(0x1018, 1, OdTreeModel::Value), Qt::DisplayRole)
                    .toString()
                    .contains(QStringLiteral("000001DDh")));

        // Read all: progress to completion, values in the rows.
        QVERIFY(dock->readAll());
        QVERIFY(dock->isBusy());
        QVERIFY(dock->progressBar()->maximum() > 100);
        QVERIFY(waitFor([&] { return !dock->isBusy(); }, 30000));
        QCOMPARE(dock->progressBar()->value(), dock->progressBar()->maximum());
        QVERIFY(dock->hasContent());
        QVERIFY(m->valuesRead() > 100);
        QVERIFY(m->actualValue(0x6041, 0).has_value());  // statusword
        QVERIFY2(dock->messageText().contains(QStringLiteral("values read")), qPrintable(dock->messageText()));

        // Edit 1017h through the view's editor (the integer field, UNSIGNED16): the
        // confirmation is answered, the write goes out, the value is read back and marked as
        // changed from the default (0).
        dock->setAutoConfirm(true);
        QVERIFY(!m->isChanged(0x1017, 0));
        const QModelIndex valueCell = dock->filter()->mapFromSource(m->indexOf(0x1017, 0, OdTreeModel::Value));
        QVERIFY(valueCell.flags() & Qt::ItemIsEditable);
        dock->view()->setCurrentIndex(valueCell);
        dock->view()->edit(valueCell);
        auto* spin = dock->view()->findChild<IntegerSpinBox*>(QStringLiteral("odValueEditor"));
        QVERIFY(spin);
        QTest::keyClick(spin, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(spin, QStringLiteral("750"));
        QTest::keyClick(spin, Qt::Key_Return);
        QVERIFY(
            waitFor([&] { return deviceValue(w, 1, 0x1017, 0) && deviceValue(w, 1, 0x1017, 0)->toUInt64() == 750u; }));
        QVERIFY(waitFor([&] { return m->actualValue(0x1017, 0) && *m->actualValue(0x1017, 0)->toUInt64() == 750u; }));
        QVERIFY(m->isChanged(0x1017, 0));
        QVERIFY(m->data(m->indexOf(0x1017, 0, OdTreeModel::Value), Qt::FontRole).value<QFont>().bold());
        // "Only changed" keeps 1017h and hides unchanged 1005h.
        dock->onlyChangedBox()->setChecked(true);
        QVERIFY(dock->filter()->mapFromSource(m->indexOf(0x1017, 0)).isValid());
        QVERIFY(!dock->filter()->mapFromSource(m->indexOf(0x1005, 0)).isValid());
        dock->onlyChangedBox()->setChecked(false);
        // The search box finds by index and by name.
        dock->searchBox()->setText(QStringLiteral("0x1017"));
        QVERIFY(dock->filter()->mapFromSource(m->indexOf(0x1017, 0)).isValid());
        QVERIFY(!dock->filter()->mapFromSource(m->indexOf(0x1005, 0)).isValid());
        dock->searchBox()->setText(QStringLiteral("heartbeat"));
        QVERIFY(dock->filter()->mapFromSource(m->indexOf(0x1017, 0)).isValid());
        dock->searchBox()->clear();

        // The confirmation says exactly what is written.
        QCOMPARE(dock->writeQuestion(0x6060, 0, od::Value::signedInt(1)),
                 QStringLiteral("Write 6060h:00 Modes of operation = 1 (Profile position (PP)) to node 1?"));

        // A write the drive refuses: the abort text on that row (red, tool tip) and in the message line.
        network(w)->runOnNetworkThread([&] {
            network(w)->device(1)->sdoFaults().abortOn =
                std::make_tuple(uint16_t(0x6083), uint8_t(0), uint32_t(0x08000022));
        });
        QVERIFY(dock->writeEntryText(0x6083, 0, QStringLiteral("1234")));
        QVERIFY(waitFor([&] { return m->state(0x6083, 0) == OdTreeModel::State::Error; }));
        const QString error = m->errorText(0x6083, 0);
        QVERIFY2(error.contains(QStringLiteral("08000022")) && error.contains(QStringLiteral("6083")),
                 qPrintable(error));
        const QModelIndex bad = m->indexOf(0x6083, 0, OdTreeModel::Value);
        QCOMPARE(m->data(bad, Qt::ToolTipRole).toString(), error);
        QCOMPARE(m->data(bad, Qt::ForegroundRole).value<QBrush>().color(), QColor(0xB0, 0x00, 0x20));
        QVERIFY(m->data(bad, Qt::DisplayRole).toString().contains(QStringLiteral("device state"), Qt::CaseInsensitive));
        QVERIFY2(dock->messageText().contains(QStringLiteral("08000022")), qPrintable(dock->messageText()));
        network(w)->runOnNetworkThread([&] { network(w)->device(1)->sdoFaults().abortOn.reset(); });
        // A value outside the limits is refused before anything is sent.
        QVERIFY(!dock->writeEntryText(0x1017, 0, QStringLiteral("70000")));
        QVERIFY(dock->messageText().contains(QStringLiteral("70000")));

        // Export: the DCF has the values read, 1017h = 750.
        const QString path = dir_.filePath(QStringLiteral("node1.dcf"));
        QVERIFY(dock->exportDcf(path));
        const eds::ReadResult dcf = eds::readDictionaryFile(path);
        QVERIFY(dcf.usable);
        QCOMPARE(dcf.dictionary.nodeId(), uint8_t(1));
        const od::SubObject* hb = dcf.dictionary.entry(0x1017, 0);
        QVERIFY(hb);
        QCOMPARE(hb->resolvedValue(1)->toUInt64().value_or(0), uint64_t(750));
        QVERIFY(!dcf.dictionary.entry(0x6041, 0)->parameterValue.isEmpty());
    }

    void applyDcfFromTheDock() {
        MainWindow w;
        w.setQuiet(true);
        QVERIFY(connectAndSelect(w, QStringLiteral("sim://")));
        ObjectDictionaryDock* dock = w.odDock();
        dock->setAutoConfirm(true);
        // Write a DCF with 1017h = 321 and apply it: only that value differs from the node's.
        const QString path = dir_.filePath(QStringLiteral("apply.dcf"));
        QVERIFY(dock->exportDcf(path));  // reads all first
        QVERIFY(waitFor([&] { return !dock->isBusy() && QFile::exists(path); }, 30000));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QString text = QString::fromUtf8(f.readAll());
        f.close();
        const int at = text.indexOf(QStringLiteral("[1017]"));
        QVERIFY(at >= 0);
        const int pv = text.indexOf(QStringLiteral("ParameterValue="), at);
        text.replace(pv, text.indexOf(u'\r', pv) - pv, QStringLiteral("ParameterValue=321"));
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(text.toUtf8());
        f.close();
        QVERIFY(dock->applyDcf(path));
        QVERIFY(waitFor([&] { return !dock->isBusy() && !dock->lastApplyResults().empty(); }, 30000));
        QCOMPARE(dock->lastApplyResults().size(), size_t(1));
        QVERIFY(dock->lastApplyResults().front().ok);
        QCOMPARE(dock->lastApplyResults().front().index, uint16_t(0x1017));
        QVERIFY(
            waitFor([&] { return deviceValue(w, 1, 0x1017, 0) && deviceValue(w, 1, 0x1017, 0)->toUInt64() == 321u; }));
        QVERIFY(waitFor([&] {
            return dock->model()->actualValue(0x1017, 0) && *dock->model()->actualValue(0x1017, 0)->toUInt64() == 321u;
        }));
    }

    void listenOnlyDisablesSdo() {
        MainWindow w;
        w.setQuiet(true);
        QVERIFY(connectAndSelect(w, QStringLiteral("sim://?listen-only=1")));
        ObjectDictionaryDock* dock = w.odDock();
        dock->setAutoConfirm(true);
        w.refresh();
        QVERIFY(!dock->canTransmit());
        const QModelIndex valueCell =
            dock->filter()->mapFromSource(dock->model()->indexOf(0x1017, 0, OdTreeModel::Value));
        QVERIFY(!(valueCell.flags() & Qt::ItemIsEditable));
        QVERIFY(!dock->readAll());
        QVERIFY(!dock->readEntry(0x1017, 0));
        QVERIFY(!dock->writeEntryText(0x1017, 0, QStringLiteral("100")));
        QVERIFY2(dock->messageText().contains(QStringLiteral("listen-only")), qPrintable(dock->messageText()));
        QTest::qWait(100);
        const auto& s = *w.workspace()->store();
        for (size_t n = 0; n < s.size(); ++n) QVERIFY(!(s.record(static_cast<FrameNo>(n)).flags & CanFrame::Tx));
    }

    void progressBarCountsTheNodeShown() {
        // Read all of node 1 by its button, then a click on node 3 in the Nodes dock: the bar
        // shows node 3's reads or nothing, never node 1's count.
        MainWindow w;
        w.setQuiet(true);
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        w.showView(QStringLiteral("od"));
        QVERIFY(w.connectBus(QStringLiteral("sim://"), true));  // identified by the scan on connect
        QVERIFY(waitFor([&] {
            const auto a = w.workspace()->nodes().node(1), b = w.workspace()->nodes().node(2);
            return a && b && !a->dictionary.isEmpty() && !b->dictionary.isEmpty();
        }));
        auto clickNode = [&](int node) {
            QTableView* view = w.nodesDock()->view();
            const int row = w.nodesDock()->model()->rowOfNode(node);
            QTest::mouseClick(view->viewport(), Qt::LeftButton, {},
                              view->visualRect(view->model()->index(row, 0)).center());
            return waitFor([&] { return w.odDock()->node() == node && w.odDock()->model()->hasDictionary(); });
        };
        QWidget* readAll = nullptr;
        for (QToolBar* bar : w.odDock()->findChildren<QToolBar*>())
            for (QAction* a : bar->actions())
                if (a->objectName() == u"odReadAll") readAll = bar->widgetForAction(a);
        QVERIFY(readAll);
        QProgressBar* bar = w.odDock()->progressBar();
        QVERIFY(clickNode(1));
        QVERIFY(waitFor([&] { return readAll->isEnabled(); }));
        QTest::mouseClick(readAll, Qt::LeftButton);
        QVERIFY(waitFor([&] { return bar->value() > 5; }));
        const int nodeOneTotal = bar->maximum();
        QVERIFY(clickNode(2));  // the AIMOTOR: another count than the Delta's
        QVERIFY2(bar->text().isEmpty(), qPrintable(bar->text()));
        QVERIFY2(!w.odDock()->messageText().contains(QStringLiteral("objects of node 1")),
                 qPrintable(w.odDock()->messageText()));
        // Node 2's own read: its own count.
        QVERIFY(waitFor([&] { return readAll->isEnabled(); }));
        QTest::mouseClick(readAll, Qt::LeftButton);
        QVERIFY(waitFor([&] { return bar->value() > 0; }));
        QVERIFY(bar->maximum() != nodeOneTotal);
        QVERIFY2(bar->text().endsWith(QStringLiteral(" / %1").arg(bar->maximum())), qPrintable(bar->text()));
        QVERIFY(waitFor([&] { return !w.odDock()->isBusy(); }, 30000));
        QCOMPARE(bar->value(), bar->maximum());
    }

    void noDictionaryOffersAssign() {
        MainWindow w;
        w.setQuiet(true);
        QVERIFY(w.connectBus(QStringLiteral("sim://")));
        QVERIFY(waitFor([&] { return w.workspace()->nodes().node(2).has_value(); }));
        w.odDock()->setNode(2);
        QVERIFY(!w.odDock()->model()->hasDictionary());
        w.odDock()->assignDictionary(QStringLiteral("aimotor"));
        QVERIFY(w.odDock()->model()->hasDictionary());
        QCOMPARE(w.workspace()->nodes().node(2)->dictionary, QStringLiteral("aimotor"));
    }
};

QTEST_MAIN(TestOdDock)
#include "test_od_dock.moc"
