// SPDX-License-Identifier: GPL-3.0-or-later
// The "Baud rate and node-ID" wizard end to end against the virtual drives (sim://): node-ID by
// LSS and by the drive's own parameter for every personality, bit rate with reconnect, a device
// without node-ID found by LSS Fastscan, failures (SDO abort, LSS store error) stop and explain,
// the dry run sends nothing, listen-only refuses.
#include "app/gui/session/Workspace.h"
#include "app/gui/wizards/WizardMenu.h"
#include "app/gui/wizards/common/ScriptPreview.h"
#include "app/gui/wizards/common/WizardFramesPane.h"
#include "app/gui/wizards/nodeid/NodeIdPages.h"
#include "app/gui/wizards/nodeid/NodeIdWizard.h"
#include "core/sim/SimBus.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"

#include <QLabel>
#include <QPushButton>
#include <QTemporaryDir>
#include <QtTest>

using namespace coscope;
using namespace coscope::gui;

namespace {
template <typename Pred>
bool waitFor(Pred pred, int timeoutMs = 10000) {
    QElapsedTimer t;
    t.start();
    while (!pred()) {
        if (t.elapsed() > timeoutMs) return false;
        QTest::qWait(20);
    }
    return true;
}

const QString kAll = QStringLiteral("sim://?nodes=1:delta-asda-a2,2:aimotor,3:dexmart-dev,4:generic-cia402");

// A workspace connected to a virtual network, and the wizard on it.
struct Bench {
    Workspace ws;
    std::unique_ptr<NodeIdWizard> wizard;
    bool open(const QString& url = kAll, int node = -1, bool scan = true) {
        QString error;
        if (!ws.connectBus(url, &error)) return false;
        if (!waitFor([&] { return ws.bus() && ws.bus()->state() == CanBus::State::Open; })) return false;
        if (!waitFor([&] { return ws.nodes().snapshot().size() >= 1; })) return false;
        wizard = std::make_unique<NodeIdWizard>(&ws, node);
        wizard->show();
        if (!scan || ws.bus()->isListenOnly()) return true;
        QSignalSpy spy(wizard.get(), &NodeIdWizard::scanFinished);
        wizard->findPage()->scanButton()->click();
        return spy.wait(15000);
    }
    sim::SimNetwork* net() const { return static_cast<SimBus*>(ws.bus())->network(); }
    int nodeIdOfSerial(uint8_t firstId) {
        int id = -1;
        net()->runOnNetworkThread([&] {
            for (const auto& n : net()->nodes())
                if (auto* d = dynamic_cast<sim::VirtualDevice*>(n.get()); d && d->serialNumber() == 0x51000000u + firstId) id = d->nodeId();
        });
        return id;
    }
    template <typename F>
    void onDevice(uint8_t node, F fn) {
        net()->runOnNetworkThread([&] {
            if (auto* d = net()->device(node)) fn(*d);
        });
    }
    // Goes to the last page (dry run) and waits for the sequence.
    bool toRunPage() {
        QSignalSpy ready(wizard.get(), &NodeIdWizard::dryRunReady);
        while (wizard->currentId() != NodeIdWizard::RunPageId) {
            if (!wizard->currentPage()->isComplete()) return false;
            wizard->next();
        }
        return (ready.count() > 0 || ready.wait(8000)) && ready.last().at(0).toBool();
    }
    // Clicks "Change it now" and waits for the outcome.
    bool run(int timeoutMs = 30000) {
        QSignalSpy done(wizard.get(), &NodeIdWizard::finished);
        wizard->runPage()->runButton()->click();
        return done.wait(timeoutMs) && done.last().at(0).toBool();
    }
};
}  // namespace

class TestWizardNodeId : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { eds::installSimulatorDictionaries(); }

    void registeredInTheCommissionMenu() {
        bool found = false;
        for (const auto& e : wizardEntries()) found |= e.id == u"nodeid";
        QVERIFY(found);
    }

    void nodeIdByLssForEveryPersonality() {
        Bench b;
        QVERIFY(b.open());
        QCOMPARE(b.wizard->node(), 1);  // the first node found is preselected
        for (uint8_t node = 1; node <= 4; ++node) {
            b.wizard->restart();
            b.wizard->selectNode(node);
            b.wizard->setChange(NodeIdWizard::Change::NodeId);
            b.wizard->setMethod(NodeIdWizard::Method::Lss);
            b.wizard->setNewNodeId(40 + node);
            QVERIFY2(b.toRunPage(), qPrintable(b.wizard->planError() + b.wizard->blockingProblem()));
            QCOMPARE(b.wizard->plan()->beforeReconnect.steps.front().kind, canopen::ScriptStep::Kind::LssSwitchSelective);
            QVERIFY2(b.run(), qPrintable(b.wizard->outcomeText()));
            QCOMPARE(b.nodeIdOfSerial(node), 40 + node);
            QVERIFY(b.wizard->outcomeText().contains(QStringLiteral("node-ID %1").arg(40 + node)));
        }
        // The frames pane showed the LSS and NMT traffic.
        b.wizard->framesPane()->poll();
        QVERIFY(b.wizard->framesPane()->rowCount() > 10);
    }

    void nodeIdByVendorParameter() {
        Bench b;
        QVERIFY(b.open());
        const std::pair<uint8_t, QString> cases[] = {{1, QStringLiteral("delta-asda-a2")}, {2, QStringLiteral("aimotor")}, {3, QStringLiteral("dexmart-dev")}};
        for (const auto& [node, dict] : cases) {
            b.wizard->restart();
            b.wizard->selectNode(node);
            b.wizard->setDictionary(dict);  // the technician confirms the device type
            b.wizard->setChange(NodeIdWizard::Change::NodeId);
            QVERIFY(b.wizard->vendorMethodAvailable());
            b.wizard->setMethod(NodeIdWizard::Method::Vendor);
            b.wizard->setNewNodeId(50 + node);
            b.wizard->next();
            // The page says which parameter and when it takes effect.
            QVERIFY(b.wizard->changePage()->explanationLabel()->text().contains(QStringLiteral("Takes effect")));
            QVERIFY2(b.toRunPage(), qPrintable(b.wizard->planError()));
            QCOMPARE(b.wizard->plan()->beforeReconnect.steps.front().kind, canopen::ScriptStep::Kind::SdoWrite);
            QVERIFY2(b.run(), qPrintable(b.wizard->outcomeText()));
            QCOMPARE(b.nodeIdOfSerial(node), 50 + node);
        }
        // Generic CiA 402: no vendor parameter, LSS only.
        b.wizard->restart();
        b.wizard->selectNode(4);
        QVERIFY(!b.wizard->vendorMethodAvailable());
    }

    void bitRateByLssAndByVendorReconnects() {
        Bench b;
        QVERIFY(b.open());
        // AIMOTOR by LSS to 250 kbit/s: the wizard warns about the other nodes, reconnects,
        // finds the node at the new rate.
        b.wizard->selectNode(2);
        b.wizard->setChange(NodeIdWizard::Change::BitRate);
        b.wizard->setMethod(NodeIdWizard::Method::Lss);
        b.wizard->setNewBitRate(250000);
        b.wizard->next();
        const QString text = b.wizard->changePage()->explanationLabel()->text();
        QVERIFY2(text.contains(QStringLiteral("Every other node")) && text.contains(QStringLiteral("nodes 1, 3, 4")), qPrintable(text));
        if (const QString dir = qEnvironmentVariable("COSCOPE_GRAB_DIR"); !dir.isEmpty()) b.wizard->grab().save(dir + QStringLiteral("/nodeid-change.png"));
        QVERIFY(b.toRunPage());
        QVERIFY(b.wizard->plan()->reconnect);
        QVERIFY2(b.run(), qPrintable(b.wizard->outcomeText()));
        if (const QString dir = qEnvironmentVariable("COSCOPE_GRAB_DIR"); !dir.isEmpty()) b.wizard->grab().save(dir + QStringLiteral("/nodeid-run.png"));
        QCOMPARE(b.ws.bus()->url().bitrate(), 250000);
        uint32_t rate = 0;
        b.onDevice(2, [&](sim::VirtualDevice& d) { rate = d.bitRate(); });
        QCOMPARE(rate, 250000u);
        // Node 1 (Delta, still at 500 kbit/s) is not heard at 250 kbit/s; now Delta by P3-01:
        // reconnect at 500 kbit/s first, then change it to 1 Mbit/s.
        QString error;
        b.wizard.reset();
        QVERIFY(b.ws.connectBus(b.ws.bus()->url().toString().replace(QStringLiteral("bitrate=250000"), QStringLiteral("bitrate=500000")), &error));
        QVERIFY(waitFor([&] { return b.ws.canTransmit() && b.ws.nodes().node(1).has_value(); }));
        b.wizard = std::make_unique<NodeIdWizard>(&b.ws, 1);
        b.wizard->show();
        b.wizard->setDictionary(QStringLiteral("delta-asda-a2"));
        b.wizard->setChange(NodeIdWizard::Change::BitRate);
        b.wizard->setMethod(NodeIdWizard::Method::Vendor);
        b.wizard->setNewBitRate(1000000);
        QVERIFY(b.toRunPage());
        QCOMPARE(b.wizard->plan()->beforeReconnect.steps.front().toLine(), QStringLiteral("sdo write 1 0x2301:00 0x0403"));
        QVERIFY2(b.run(), qPrintable(b.wizard->outcomeText()));
        QCOMPARE(b.ws.bus()->url().bitrate(), 1000000);
        b.onDevice(1, [&](sim::VirtualDevice& d) { rate = d.bitRate(); });
        QCOMPARE(rate, 1000000u);
    }

    void deviceWithoutNodeIdByFastscan() {
        Bench b;
        QVERIFY(b.open(QStringLiteral("sim://?nodes=1:delta-asda-a2,5:aimotor"), 1, false));
        b.onDevice(5, [](sim::VirtualDevice& d) { d.makeUnconfigured(); });
        QSignalSpy found(b.wizard.get(), &NodeIdWizard::fastscanFinished);
        b.wizard->findPage()->fastscanButton()->click();
        QVERIFY(found.wait(20000));
        QVERIFY2(found.last().at(0).toBool(), qPrintable(found.last().at(1).toString()));
        QCOMPARE(b.wizard->node(), 0xFF);
        b.wizard->setNewNodeId(9);
        QVERIFY(b.toRunPage());
        QVERIFY2(b.run(), qPrintable(b.wizard->outcomeText()));
        QCOMPARE(b.nodeIdOfSerial(5), 9);
    }

    void sdoAbortStopsAndExplains() {
        Bench b;
        QVERIFY(b.open());
        b.onDevice(1, [](sim::VirtualDevice& d) { d.sdoFaults().abortOn = std::make_tuple(uint16_t(0x2300), uint8_t(0), uint32_t(0x08000022)); });
        b.wizard->selectNode(1);
        b.wizard->setDictionary(QStringLiteral("delta-asda-a2"));
        b.wizard->setMethod(NodeIdWizard::Method::Vendor);
        b.wizard->setNewNodeId(12);
        QVERIFY(b.toRunPage());
        QVERIFY(!b.run());
        QCOMPARE(b.wizard->outcome(), NodeIdWizard::Outcome::Failed);
        const QString text = b.wizard->outcomeText();
        QVERIFY2(text.contains(QStringLiteral("step 1")) && text.contains(QStringLiteral("2300h")), qPrintable(text));
        QVERIFY2(text.contains(QStringLiteral("08000022")), qPrintable(text));  // the device's answer
        QVERIFY(text.contains(QStringLiteral("What to check")));
        QCOMPARE(b.wizard->runPage()->statusLabel()->text(), text);
        QCOMPARE(b.nodeIdOfSerial(1), 1);
    }

    void lssStoreErrorIsUndone() {
        Bench b;
        QVERIFY(b.open());
        b.onDevice(4, [](sim::VirtualDevice& d) { d.lssFaults().storeError = 2; });
        b.wizard->selectNode(4);
        b.wizard->setMethod(NodeIdWizard::Method::Lss);
        b.wizard->setNewNodeId(14);
        QVERIFY(b.toRunPage());
        QVERIFY(!b.run());
        const QString text = b.wizard->outcomeText();
        QVERIFY2(text.contains(QStringLiteral("store")) && text.contains(QStringLiteral("Put back")), qPrintable(text));
        int pending = 0;
        b.onDevice(4, [&](sim::VirtualDevice& d) { pending = d.pendingNodeId(); });
        QCOMPARE(pending, 4);
        QCOMPARE(b.nodeIdOfSerial(4), 4);
    }

    void dryRunSendsNothingAndSaves() {
        Bench b;
        QVERIFY(b.open());
        b.wizard->selectNode(2);
        b.wizard->setMethod(NodeIdWizard::Method::Lss);
        b.wizard->setNewNodeId(22);
        QTest::qWait(300);
        const uint64_t tx = b.ws.bus()->counters().tx;
        QVERIFY(b.toRunPage());
        QTest::qWait(300);
        QCOMPARE(b.ws.bus()->counters().tx, tx);  // the identity came from the scan
        QCOMPARE(b.wizard->preview()->rowCount(), int(b.wizard->plan()->whole().steps.size()));
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("nodeid.cosc"));
        QString error;
        QVERIFY2(b.wizard->preview()->saveTo(file, &error), qPrintable(error));
        const auto script = canopen::CommandScript::load(file, &error);
        QVERIFY2(script, qPrintable(error));
        QCOMPARE(script->steps.size(), b.wizard->plan()->whole().steps.size());
        QCOMPARE(b.nodeIdOfSerial(2), 2);
    }

    void listenOnlyRefuses() {
        Bench b;
        QVERIFY(b.open(QStringLiteral("sim://?listen-only=1"), 1, false));
        QVERIFY(!b.wizard->sendRefusal().isEmpty());
        QVERIFY(!b.wizard->findPage()->isComplete());
        QVERIFY(!b.wizard->findPage()->scanButton()->isEnabled());
        QVERIFY(b.wizard->findPage()->refusalLabel()->text().contains(QStringLiteral("listen-only")));
        b.wizard->setNewNodeId(9);
        b.wizard->prepareDryRun();
        QString why;
        QVERIFY(!b.wizard->start(&why));
        QVERIFY(!why.isEmpty());
        QCOMPARE(b.ws.bus()->counters().tx, uint64_t(0));
    }
};

QTEST_MAIN(TestWizardNodeId)
#include "test_wizard_nodeid.moc"
