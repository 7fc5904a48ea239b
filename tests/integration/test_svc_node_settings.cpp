// SPDX-License-Identifier: GPL-3.0-or-later
// The node-ID / bit-rate service (canopen::NodeSettingsChanger) and its CLI verbs against the
// virtual drives: plans, LSS and vendor-parameter paths for every personality, bit rates on the
// simulated bus, failures stop, report and put back what was changed.
#include "core/can/BusUrl.h"
#include "core/canopen/NodeSettingsChanger.h"
#include "core/canopen/ServiceWait.h"
#include "core/sim/BusAtBitRate.h"
#include "core/sim/SimBus.h"
#include "core/sim/SimNetwork.h"
#include "core/sim/VirtualDevice.h"
#include "core/trace/CaptureSession.h"
#include "eds/SimulatorDictionaries.h"
#include "tests/CliRun.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;

namespace {

const QString kSpec = QStringLiteral("1:delta-asda-a2,2:aimotor,3:dexmart-dev,4:generic-cia402");

// One master endpoint on a (shared) virtual network.
struct Endpoint {
    std::unique_ptr<SimBus> bus;
    CaptureSession session;
    std::unique_ptr<MasterContext> context;
    std::unique_ptr<SdoClient> sdo;
    std::unique_ptr<NodeSettingsChanger> changer;
    std::vector<CanFrame> seen;  // every frame received (not our own)
    bool open(const QString& url, std::shared_ptr<sim::SimNetwork> net) {
        auto parsed = BusUrl::parse(url, nullptr);
        if (!parsed) return false;
        bus = std::make_unique<SimBus>(*parsed, std::move(net));
        context = std::make_unique<MasterContext>(bus.get());
        session.addConsumer(context->dispatcher().consumer());
        bus->open();
        if (!bus->waitForOpen(2000)) return false;
        session.start(bus.get());
        sdo = std::make_unique<SdoClient>(*context);
        sdo->setDefaultTimeout(300);
        changer = std::make_unique<NodeSettingsChanger>(*context, *sdo);
        return true;
    }
    ~Endpoint() {
        changer.reset();
        sdo.reset();
        session.stop();
        if (bus) bus->close();
    }
};

struct Net {
    std::shared_ptr<sim::SimNetwork> network;
    explicit Net(const QString& spec = kSpec) {
        eds::installSimulatorDictionaries();
        network = std::shared_ptr<sim::SimNetwork>(sim::SimNetwork::fromSpec(spec, nullptr));
    }
    ~Net() { network->stop(); }
    template <typename F>
    auto onDevice(uint8_t node, F fn) {
        decltype(fn(std::declval<sim::VirtualDevice&>())) out{};
        network->runOnNetworkThread([&] {
            if (auto* d = network->device(node)) out = fn(*d);
        });
        return out;
    }
    // The device that was created as `firstId` (serial 51000000h + first node-ID).
    int nodeIdOfSerial(uint8_t firstId) {
        int id = -1;
        network->runOnNetworkThread([&] {
            for (const auto& n : network->nodes())
                if (auto* d = dynamic_cast<sim::VirtualDevice*>(n.get());
                    d && d->serialNumber() == 0x51000000u + firstId)
                    id = d->nodeId();
        });
        return id;
    }
    uint32_t bitRateOfSerial(uint8_t firstId) {
        uint32_t r = 0;
        network->runOnNetworkThread([&] {
            for (const auto& n : network->nodes())
                if (auto* d = dynamic_cast<sim::VirtualDevice*>(n.get());
                    d && d->serialNumber() == 0x51000000u + firstId)
                    r = d->bitRate();
        });
        return r;
    }
};

std::optional<NodeSettingsPlan> prepare(Endpoint& e, const NodeSettingsRequest& r, QString* error) {
    using Res = std::pair<std::optional<NodeSettingsPlan>, QString>;
    auto res = waitForResult<Res>(
        [&](auto cb) { e.changer->prepare(r, [cb](auto p, QString err) {
                           cb(Res{p, err});
                       }); }, 10000);
    if (!res) {
        *error = QStringLiteral("no result");
        return std::nullopt;
    }
    *error = res->second;
    return res->first;
}

NodeSettingsOutcome runPart(Endpoint& e, const NodeSettingsPlan& plan, int part) {
    auto out = waitForResult<NodeSettingsOutcome>([&](auto cb) { e.changer->run(plan, part, {}, {}, cb); }, 20000);
    return out ? *out : NodeSettingsOutcome{};
}

NodeSettingsRequest nodeIdRequest(uint8_t node, uint8_t newId, NodeSettingsRequest::Method m, const QString& dict) {
    NodeSettingsRequest r;
    r.change = NodeSettingsRequest::Change::NodeId;
    r.method = m;
    r.node = node;
    r.newNodeId = newId;
    r.dictionary = dict;
    r.waitMs = 3000;
    return r;
}

}  // namespace

class TestSvcNodeSettings : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { eds::installSimulatorDictionaries(); }

    void vendorTableFromTheManuals() {
        const auto delta = vendorNodeSettings(QStringLiteral("delta-asda-a2"));
        QVERIFY(delta && delta->nodeId && delta->bitRate);
        QCOMPARE(delta->nodeId->index, uint16_t(0x2300));
        QCOMPARE(delta->bitRate->index, uint16_t(0x2301));
        // P3-01 digit Z: 4 = 1 Mbit/s, other digits kept (manual §1.3.1: P3-01 = 0403h).
        QCOMPARE(*encodeVendorBitRate(*delta->bitRate, 1000000, 0x0203), 0x0403u);
        QCOMPARE(decodeVendorBitRate(*delta->bitRate, 0x0103), 250000);
        QVERIFY(!encodeVendorBitRate(*delta->bitRate, 800000, 0x0203));
        const auto ai = vendorNodeSettings(QStringLiteral("aimotor"));
        QVERIFY(ai && ai->nodeId && !ai->bitRate);  // H0C-08 codes are not documented
        QCOMPARE(ai->maxNodeId, 63);
        QVERIFY(!vendorNodeSettings(QStringLiteral("generic-cia402")));
    }

    void planSaysWhatAndRefusesNonsense() {
        QString error;
        auto r = nodeIdRequest(1, 5, NodeSettingsRequest::Method::Vendor, QStringLiteral("delta-asda-a2"));
        auto p = planNodeSettings(r, &error);
        QVERIFY2(p, qPrintable(error));
        QCOMPARE(p->beforeReconnect.steps.front().toLine(), QStringLiteral("sdo write 1 0x2300:00 0x0005"));
        QVERIFY(p->takesEffect.contains(QStringLiteral("power cycle")));
        QCOMPARE(p->beforeReconnect.steps.back().kind, ScriptStep::Kind::WaitForNode);
        QVERIFY(!p->reconnect);
        r.dictionary = QStringLiteral("generic-cia402");
        QVERIFY(!planNodeSettings(r, &error));
        QVERIFY(error.contains(QStringLiteral("LSS")));
        r = nodeIdRequest(2, 64, NodeSettingsRequest::Method::Vendor, QStringLiteral("aimotor"));
        QVERIFY(!planNodeSettings(r, &error));  // AIMOTOR: 63 stations
        r.change = NodeSettingsRequest::Change::BitRate;
        r.method = NodeSettingsRequest::Method::Lss;
        r.newBitRate = 750000;  // Delta's rate, not in the CiA 305 table
        QVERIFY(!planNodeSettings(r, &error));
        r.newBitRate = 250000;
        p = planNodeSettings(r, &error);
        QVERIFY2(p, qPrintable(error));
        QVERIFY(p->reconnect);
        QCOMPARE(p->reconnectBitRate, 250000);
        QCOMPARE(p->beforeReconnect.steps.back().kind, ScriptStep::Kind::LssActivateBitTiming);
        // The whole sequence parses back as a script.
        QVERIFY(CommandScript::parse(p->whole().toText(), &error));
    }

    void bitRateSeparatesTheBus() {
        Net net;
        Endpoint slow;
        QVERIFY(slow.open(QStringLiteral("sim://?bitrate=250000"), net.network));
        Endpoint normal;
        QVERIFY(normal.open(QStringLiteral("sim://?bitrate=500000"), net.network));
        // Node 1 answers at 500 kbit/s but not at 250 kbit/s.
        auto a = waitForResult<SdoResult>([&](auto cb) { normal.sdo->upload(1, 0x1000, 0, cb); }, 3000);
        QVERIFY(a && a->ok);
        auto b = waitForResult<SdoResult>([&](auto cb) { slow.sdo->upload(1, 0x1000, 0, cb); }, 3000);
        QVERIFY(b && !b->ok && b->timedOut);
        // An endpoint without bitrate= is rate-agnostic: it reaches both.
        Endpoint any;
        QVERIFY(any.open(QStringLiteral("sim://"), net.network));
        auto c = waitForResult<SdoResult>([&](auto cb) { any.sdo->upload(1, 0x1000, 0, cb); }, 3000);
        QVERIFY(c && c->ok);
    }

    void nodeIdByLssForEveryPersonality() {
        Net net;
        Endpoint e;
        QVERIFY(e.open(QStringLiteral("sim://"), net.network));
        const uint8_t first[] = {1, 2, 3, 4};
        for (uint8_t node : first) {
            const auto newId = uint8_t(20 + node);
            QString error;
            auto plan = prepare(e, nodeIdRequest(node, newId, NodeSettingsRequest::Method::Lss, {}), &error);
            QVERIFY2(plan, qPrintable(error));
            const auto out = runPart(e, *plan, 0);
            QVERIFY2(out.ok, qPrintable(out.step + u' ' + out.answer));
            QCOMPARE(net.nodeIdOfSerial(node), int(newId));
            // It answers SDO at the new node-ID.
            auto r = waitForResult<SdoResult>([&](auto cb) { e.sdo->upload(newId, 0x1000, 0, cb); }, 3000);
            QVERIFY(r && r->ok);
        }
    }

    void nodeIdByVendorParameter() {
        Net net;
        Endpoint e;
        QVERIFY(e.open(QStringLiteral("sim://"), net.network));
        const std::pair<uint8_t, QString> cases[] = {
            {1, QStringLiteral("delta-asda-a2")}, {2, QStringLiteral("aimotor")}, {3, QStringLiteral("dexmart-dev")}};
        for (const auto& [node, dict] : cases) {
            const auto newId = uint8_t(30 + node);
            QString error;
            auto plan = prepare(e, nodeIdRequest(node, newId, NodeSettingsRequest::Method::Vendor, dict), &error);
            QVERIFY2(plan, qPrintable(error));
            const auto out = runPart(e, *plan, 0);
            QVERIFY2(out.ok, qPrintable(dict + u' ' + out.step + u' ' + out.answer));
            QCOMPARE(net.nodeIdOfSerial(node), int(newId));
        }
        // Saved: after a power cycle the drives keep their new node-IDs (Delta EEPROM on write,
        // AIMOTOR 1010h save).
        net.network->runOnNetworkThread([&] {
            for (const auto& n : net.network->nodes())
                if (auto* d = dynamic_cast<sim::VirtualDevice*>(n.get())) d->powerCycle();
        });
        QCOMPARE(net.nodeIdOfSerial(1), 31);
        QCOMPARE(net.nodeIdOfSerial(2), 32);
    }

    void bitRateByLssAndVendorThenReconnect() {
        Net net;
        struct Case {
            uint8_t node;
            NodeSettingsRequest::Method method;
            QString dict;
            int rate;
        };
        const Case cases[] = {{2, NodeSettingsRequest::Method::Lss, {}, 250000},
                              {3, NodeSettingsRequest::Method::Lss, {}, 250000},
                              {4, NodeSettingsRequest::Method::Lss, {}, 1000000},
                              {1, NodeSettingsRequest::Method::Vendor, QStringLiteral("delta-asda-a2"), 1000000}};
        for (const Case& c : cases) {
            auto before = std::make_unique<Endpoint>();
            QVERIFY(before->open(QStringLiteral("sim://?bitrate=500000"), net.network));
            NodeSettingsRequest r;
            r.change = NodeSettingsRequest::Change::BitRate;
            r.method = c.method;
            r.node = c.node;
            r.newBitRate = c.rate;
            r.dictionary = c.dict;
            r.waitMs = 3000;
            QString error;
            auto plan = prepare(*before, r, &error);
            QVERIFY2(plan, qPrintable(error));
            auto out = runPart(*before, *plan, 0);
            QVERIFY2(out.ok, qPrintable(out.step + u' ' + out.answer));
            QVERIFY(plan->reconnect);
            QCOMPARE(net.bitRateOfSerial(c.node), uint32_t(c.rate));
            // Silent at the old rate.
            auto old = waitForResult<SdoResult>([&](auto cb) { before->sdo->upload(c.node, 0x1000, 0, cb); }, 3000);
            QVERIFY(old && old->timedOut);
            std::shared_ptr<sim::SimNetwork> keep;
            const QString url = sim::urlAtBitRate(*before->bus, plan->reconnectBitRate, &keep);
            QVERIFY(url.contains(QStringLiteral("bitrate=%1").arg(c.rate)));
            before.reset();
            Endpoint after;
            auto parsed = BusUrl::parse(url, nullptr);
            QVERIFY(parsed);
            QVERIFY(after.open(url, sim::SimNetwork::published(parsed->target)));
            out = runPart(after, *plan, 1);
            QVERIFY2(out.ok, qPrintable(c.dict + u' ' + out.step + u' ' + out.answer));
            auto now = waitForResult<SdoResult>([&](auto cb) { after.sdo->upload(c.node, 0x1000, 0, cb); }, 3000);
            QVERIFY(now && now->ok);
        }
    }

    void sdoAbortStopsAndSaysWhy() {
        Net net;
        Endpoint e;
        QVERIFY(e.open(QStringLiteral("sim://"), net.network));
        net.onDevice(1, [](sim::VirtualDevice& d) {
            d.sdoFaults().abortOn =
                std::make_tuple(uint16_t(0x2300), uint8_t(0), uint32_t(0x08000022));  // device state
            return 0;
        });
        QString error;
        auto plan = prepare(
            e, nodeIdRequest(1, 9, NodeSettingsRequest::Method::Vendor, QStringLiteral("delta-asda-a2")), &error);
        QVERIFY(plan);
        const auto out = runPart(e, *plan, 0);
        QVERIFY(!out.ok);
        QCOMPARE(out.failedStep, 0);
        QVERIFY2(out.answer.contains(QStringLiteral("08000022")), qPrintable(out.answer));
        QVERIFY(out.step.contains(QStringLiteral("2300h")));
        QVERIFY(!out.advice.isEmpty());
        QVERIFY(out.restored.isEmpty());  // nothing was changed
        QCOMPARE(net.nodeIdOfSerial(1), 1);
    }

    void lssStoreErrorPutsTheOldNodeIdBack() {
        Net net;
        Endpoint e;
        QVERIFY(e.open(QStringLiteral("sim://"), net.network));
        net.onDevice(2, [](sim::VirtualDevice& d) {
            d.lssFaults().storeError = 2;  // storage media access error
            return 0;
        });
        QString error;
        auto plan = prepare(e, nodeIdRequest(2, 12, NodeSettingsRequest::Method::Lss, {}), &error);
        QVERIFY2(plan, qPrintable(error));
        const auto out = runPart(e, *plan, 0);
        QVERIFY(!out.ok);
        QCOMPARE(plan->beforeReconnect.steps[size_t(out.failedStep)].kind, ScriptStep::Kind::LssStore);
        QVERIFY(out.restored.startsWith(QStringLiteral("Put back")));
        // Nothing pending: a reset communication keeps node 2.
        QCOMPARE(net.onDevice(2, [](sim::VirtualDevice& d) { return int(d.pendingNodeId()); }), 2);
        QCOMPARE(net.nodeIdOfSerial(2), 2);
    }

    void nodeNotComingBackGivesRecovery() {
        Net net;
        Endpoint e;
        QVERIFY(e.open(QStringLiteral("sim://"), net.network));
        QString error;
        auto r = nodeIdRequest(1, 9, NodeSettingsRequest::Method::Vendor, QStringLiteral("delta-asda-a2"));
        r.waitMs = 400;
        auto plan = prepare(e, r, &error);
        QVERIFY(plan);
        // The drive ignores the reset (the manual: only a power cycle applies P3-00).
        plan->beforeReconnect.steps[1] = ScriptStep::wait(10, QStringLiteral("no reset"));
        const auto out = runPart(e, *plan, 0);
        QVERIFY(!out.ok);
        QCOMPARE(plan->beforeReconnect.steps[size_t(out.failedStep)].kind, ScriptStep::Kind::WaitForNode);
        QVERIFY(out.advice.contains(QStringLiteral("off and on")));
    }

    void cliVerbs() {
        Run r = cli({QStringLiteral("node-id"), QStringLiteral("sim://?nodes=1:delta-asda-a2"), QStringLiteral("1"),
                     QStringLiteral("7"), QStringLiteral("--via"), QStringLiteral("vendor")},
                    30000);
        QCOMPARE(r.code, 0);
        QVERIFY(r.out.contains(QStringLiteral("node 1 is now node 7")));
        r = cli({QStringLiteral("bitrate"), QStringLiteral("sim://?nodes=2:aimotor"), QStringLiteral("2"),
                 QStringLiteral("250000")},
                30000);
        QCOMPARE(r.code, 0);
        QVERIFY(r.out.contains(QStringLiteral("node 2 runs at 250 kbit/s")));
        r = cli({QStringLiteral("node-id"), QStringLiteral("sim://?nodes=4:generic-cia402"), QStringLiteral("4"),
                 QStringLiteral("8"), QStringLiteral("--via"), QStringLiteral("vendor"), QStringLiteral("--dict"),
                 QStringLiteral("generic-cia402")},
                30000);
        QCOMPARE(r.code, 1);
        QVERIFY(r.err.contains(QStringLiteral("use LSS")));
        r = cli({QStringLiteral("node-id"), QStringLiteral("sim://"), QStringLiteral("1"), QStringLiteral("300")},
                30000);
        QCOMPARE(r.code, 2);
    }
};

QTEST_GUILESS_MAIN(TestSvcNodeSettings)
#include "test_svc_node_settings.moc"
