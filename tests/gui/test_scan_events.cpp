// SPDX-License-Identifier: GPL-3.0-or-later
// A network scan started from the Nodes dock's context menu reads the optional objects 1008h,
// 1009h, 100Ah and 1018h sub 2-4 (CiA 301 §7.5.2.9-11, §7.5.2.21). The virtual Delta ASDA-A2
// has none of 1008h/1009h/100Ah and no 1018h:04 (extract-delta §9): its aborts are in the trace,
// the Nodes dock says "not present", and the Events dock shows no SDO abort for them.
#include "app/gui/MainWindow.h"
#include "app/gui/events/EventsDock.h"
#include "app/gui/events/EventsModel.h"
#include "app/gui/nodes/NodesDock.h"
#include "app/gui/nodes/NodesModel.h"
#include "app/gui/session/Workspace.h"
#include "dissectors/NetworkHealth.h"
#include "eds/SimulatorDictionaries.h"
#include "tests/gui/ModalAnswer.h"

#include <QContextMenuEvent>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QTableView>
#include <QtTest>

#include <limits>

#include "tests/gui/WaitFor.h"

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::answerBox;

namespace {
using coscope::testing::waitFor;

// Clicks the item starting with `item` in the next popup menu, however late it shows.
class MenuClicker {
public:
    explicit MenuClicker(const QString& item) {
        QObject::connect(&poll_, &QTimer::timeout, [this, item] {
            auto* menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
            if (!menu || !menu->isVisible()) return;
            for (QAction* a : menu->actions())
                if (a->text().remove(u'&').startsWith(item)) {
                    poll_.stop();
                    clicked_ = a->isEnabled();
                    QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(a).center());
                    return;
                }
        });
        poll_.start(30);
    }
    bool clicked() const { return clicked_; }

private:
    QTimer poll_;
    bool clicked_ = false;
};

QString cellOfNode(NodesModel* m, int node, int column) {
    for (int r = 0; r < m->rowCount(); ++r)
        if (m->nodeAt(r) == node) return m->data(m->index(r, column), Qt::DisplayRole).toString();
    return QStringLiteral("(no row)");
}
}  // namespace

class TestScanEvents : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("coscope-test-scan-events"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
    }

    void optionalObjectAbortsAreNoEvents() {
        MainWindow w;
        w.setQuiet(true);  // no "save the capture?" at the end
        w.show();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        // Bus ▸ Connect to virtual drives (sim://), by clicks on the menu bar and the item.
        QAction* busTitle = nullptr;
        for (QAction* a : w.menuBar()->actions())
            if (a->menu() && a->text().remove(u'&') == u"Bus") busTitle = a;
        QVERIFY(busTitle);
        QAction* sim = nullptr;
        for (QAction* a : busTitle->menu()->actions())
            if (a->text().contains(QStringLiteral("virtual drives"))) sim = a;
        QVERIFY(sim);
        QTest::mouseClick(w.menuBar(), Qt::LeftButton, {}, w.menuBar()->actionGeometry(busTitle).center());
        QVERIFY(waitFor([&] { return busTitle->menu()->isVisible(); }));
        QTest::mouseClick(busTitle->menu(), Qt::LeftButton, {}, busTitle->menu()->actionGeometry(sim).center());
        QVERIFY(waitFor([&] { return w.workspace()->bus() && w.workspace()->bus()->state() == CanBus::State::Open; }));
        NodesModel* nodes = w.nodesDock()->model();
        QVERIFY(waitFor([&] {
            w.refresh();
            return nodes->rowCount() >= 3;
        }));

        // Connecting scans by itself; once that is done, right-click in the node table ▸ Scan
        // network, then Yes in the confirmation.
        QVERIFY(waitFor(
            [&] {
                w.refresh();
                return w.nodesDock()->scanAction()->isEnabled();
            },
            30000));
        auto* view = w.nodesDock()->findChild<QTableView*>();
        QVERIFY(view);
        QString asked;
        auto yes = answerBox(QMessageBox::Yes, &asked);
        MenuClicker clicker(QStringLiteral("Scan network"));
        const QPoint at = view->viewport()->rect().center();
        QContextMenuEvent menuEvent(QContextMenuEvent::Mouse, at, view->viewport()->mapToGlobal(at));
        QApplication::sendEvent(view->viewport(), &menuEvent);
        QVERIFY(clicker.clicked());
        QVERIFY(waitFor([&] { return yes->answered(); }));
        QVERIFY2(asked.contains(QStringLiteral("1000h")), qPrintable(asked));

        // The Delta (node 1) has no 1008h: "not present"; its identity lacks the serial number.
        QVERIFY(waitFor(
            [&] {
                w.refresh();
                return cellOfNode(nodes, 1, NodesModel::DeviceName) == QStringLiteral("not present") &&
                       cellOfNode(nodes, 1, NodesModel::Identity).contains(QStringLiteral("s/n not present"));
            },
            30000));
        QVERIFY(waitFor([&] {
            w.refresh();
            return cellOfNode(nodes, 3, NodesModel::DeviceName) != QString() &&
                   !cellOfNode(nodes, 3, NodesModel::DeviceName).contains(u'(');
        }));
        QVERIFY(cellOfNode(nodes, 3, NodesModel::DeviceName) !=
                QStringLiteral("not present"));  // the generic drive has 1008h
        QTest::qWait(500);
        w.refresh();

        // The trace has the Delta's aborts: 581h, command 80h, 1008h:00, 1009h:00 and 1018h:04.
        const auto& store = *w.workspace()->store();
        auto abortIn = [&](uint16_t index, uint8_t sub) {
            for (size_t n = 0; n < store.size(); ++n) {
                const auto& r = store.record(static_cast<FrameNo>(n));
                if (r.id == 0x581 && r.len == 8 && r.data[0] == 0x80 && (r.data[1] | r.data[2] << 8) == index &&
                    r.data[3] == sub)
                    return true;
            }
            return false;
        };
        QVERIFY(abortIn(0x1008, 0));
        QVERIFY(abortIn(0x1009, 0));
        // (100Ah is there: every virtual drive takes a program download and shows its version, issue 36.)
        QVERIFY(abortIn(0x1018, 4));

        // The Events dock lists no SDO abort.
        EventsModel* events = w.eventsDock()->model();
        QVERIFY(events->rowCount() >= 3);  // the boot-ups are there
        for (int r = 0; r < events->rowCount(); ++r)
            QVERIFY2(events->eventAt(r).kind != TraceEvent::Kind::SdoAbort, qPrintable(events->eventAt(r).text));

        // Issue 37: the Health report names the scan's aborts and unanswered probes as CoScope's
        // own traffic (the frames it sent are Tx), at info, never a device's error or warning.
        QStringList rules;
        QVERIFY(waitFor([&] {
            rules.clear();
            for (const dissect::HealthFinding& f :
                 w.workspace()->health().report(std::numeric_limits<int64_t>::min()).findings) {
                rules << QStringLiteral("%1 %2 (%3)").arg(f.rule, dissect::severityName(f.severity), f.what);
                if (f.rule.startsWith(QLatin1String("sdo."))) return false;
            }
            return rules.filter(QStringLiteral("coscope.sdo_abort info")).size() > 0;
        }));
        for (const QString& r : rules)
            QVERIFY2(!r.contains(QLatin1String(" error (")) && !r.contains(QLatin1String(" critical (")),
                     qPrintable(rules.join(u'\n')));
    }
};

QTEST_MAIN(TestScanEvents)
#include "test_scan_events.moc"
