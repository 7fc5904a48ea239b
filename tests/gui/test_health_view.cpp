// SPDX-License-Identifier: GPL-3.0-or-later
// The Health dock on the virtual drives (sim://) with faults injected in the simulator: node 2's
// heartbeat stops (its firmware sets 1017h to 0, no SDO on the bus) and node 1 raises a drive
// fault (EMCY). The user brings the dock up by clicking its tab; the findings and the node table
// must say both.
#include "app/gui/MainWindow.h"
#include "app/gui/health/HealthDock.h"
#include "app/gui/health/HealthModel.h"
#include "app/gui/session/Workspace.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"
#include "tests/gui/WaitFor.h"

#include <QSettings>
#include <QTabBar>
#include <QTableView>
#include <QtTest>

#include <qcustomplot.h>

using namespace coscope;
using namespace coscope::gui;
using coscope::testing::waitFor;

namespace {
QStringList column(const HealthModel* m, int col) {
    QStringList out;
    for (int r = 0; r < m->rowCount(); ++r) out << m->data(m->index(r, col)).toString();
    return out;
}
int rowOfNode(const HealthModel* m, int node) {
    for (int r = 0; r < m->rowCount(); ++r)
        if (m->data(m->index(r, 0), HealthModel::RawRole).toInt() == node) return r;
    return -1;
}
}  // namespace

class HealthViewTest : public QObject {
    Q_OBJECT
    std::unique_ptr<MainWindow> w_;

    sim::SimNetwork* net() { return static_cast<SimBus*>(w_->workspace()->bus())->network(); }
    void setHeartbeat(int node, uint16_t ms) {
        net()->runOnNetworkThread(
            [&] { net()->device(static_cast<uint8_t>(node))->setValue(0x1017, 0, od::Value::unsignedInt(ms)); });
    }

private slots:
    void initTestCase() {
        QCoreApplication::setOrganizationName(QStringLiteral("CoScopeTest"));
        QCoreApplication::setApplicationName(QStringLiteral("gui_health_view"));
        QSettings().clear();
        eds::installSimulatorDictionaries();
        w_ = std::make_unique<MainWindow>();
        w_->resize(1400, 900);
        w_->show();
        QVERIFY(QTest::qWaitForWindowExposed(w_.get()));
    }

    void showsStoppedHeartbeatAndEmcy() {
        QVERIFY(w_->connectBus(QStringLiteral("sim://")));
        QVERIFY(waitFor([&] { return w_->workspace()->canTransmit(); }));
        // Both drives beat every 100 ms.
        setHeartbeat(1, 100);
        setHeartbeat(2, 100);

        // The Health dock shares the bottom area with Events: click its tab.
        HealthDock* dock = w_->healthDock();
        QVERIFY(dock);
        QTabBar* bar = nullptr;
        int tab = -1;
        for (QTabBar* b : w_->findChildren<QTabBar*>())
            for (int i = 0; i < b->count(); ++i)
                if (b->tabText(i).remove(u'&') == dock->windowTitle()) bar = b, tab = i;
        QVERIFY2(bar, "no tab for the Health dock");
        QTest::mouseClick(bar, Qt::LeftButton, {}, bar->tabRect(tab).center());
        QVERIFY(waitFor([&] { return dock->isVisible(); }, 3000));

        HealthModel* nodes = dock->nodesModel();
        HealthModel* findings = dock->findingsModel();
        QVERIFY2(waitFor([&] {
                     const int r1 = rowOfNode(nodes, 1), r2 = rowOfNode(nodes, 2);
                     return r1 >= 0 && r2 >= 0 && nodes->data(nodes->index(r2, HealthModel::Beats)).toInt() >= 5 &&
                            nodes->data(nodes->index(r1, HealthModel::Beats)).toInt() >= 5;
                 }),
                 qPrintable(column(nodes, HealthModel::Beats).join(u',')));
        const int r2 = rowOfNode(nodes, 2);
        QCOMPARE(nodes->data(nodes->index(r2, HealthModel::ErrorControl)).toString(), QStringLiteral("heartbeat"));
        QVERIFY(!column(findings, HealthModel::Text).join(u'\n').contains(QStringLiteral("node 2 heartbeat stopped")));

        // Faults: node 2 falls silent, node 1's drive trips.
        setHeartbeat(2, 0);
        net()->runOnNetworkThread([&] { net()->device(1)->injectDriveFault(); });

        QVERIFY2(waitFor([&] {
                     const QString all = column(findings, HealthModel::Text).join(u'\n');
                     return all.contains(QStringLiteral("node 2 heartbeat stopped")) &&
                            all.contains(QStringLiteral("from node 1"));
                 }),
                 qPrintable(column(findings, HealthModel::Text).join(u'\n')));
        // The worst first: the stopped heartbeat is critical, on top.
        QCOMPARE(findings->data(findings->index(0, HealthModel::Severity), HealthModel::RawRole).toInt(),
                 int(dissect::HealthFinding::Critical));
        QVERIFY(findings->data(findings->index(0, HealthModel::Text))
                    .toString()
                    .contains(QStringLiteral("node 2 heartbeat stopped")));
        QVERIFY(column(findings, HealthModel::Text).join(u'\n').contains(QStringLiteral("EMCY ")));
        const int row2 = rowOfNode(nodes, 2), row1 = rowOfNode(nodes, 1);
        QCOMPARE(nodes->data(nodes->index(row2, HealthModel::ErrorControl)).toString(),
                 QStringLiteral("heartbeat stopped"));
        QVERIFY(nodes->data(nodes->index(row2, HealthModel::Timeouts)).toInt() >= 1);
        QVERIFY(nodes->data(nodes->index(row1, HealthModel::Emcys)).toInt() >= 1);
        // The views show the rows, and the load plot has data.
        QCOMPARE(dock->findingsView()->model()->rowCount(), findings->rowCount());
        QVERIFY(dock->loadPlot()->graph(0)->dataCount() > 0);
    }

    void cleanupTestCase() {
        w_->workspace()->disconnectBus();
        w_.reset();
    }
};

QTEST_MAIN(HealthViewTest)
#include "test_health_view.moc"
