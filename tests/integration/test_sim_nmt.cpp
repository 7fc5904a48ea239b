// SPDX-License-Identifier: GPL-3.0-or-later
// NMT slave, error control (heartbeat, node guarding), EMCY, store/restore and the LSS slave of
// the virtual devices.
#include "SimTestHarness.h"

#include "core/canopen/Lss.h"
#include "core/canopen/SdoAbort.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::testing;
namespace lss = coscope::canopen::lss;

namespace {
CanFrame lssFrame(uint8_t cs, uint32_t v = 0, uint8_t b5 = 0, uint8_t b6 = 0, uint8_t b7 = 0) {
    return CanFrame::classic(lss::kMasterToSlave,
                             {cs, uint8_t(v), uint8_t(v >> 8), uint8_t(v >> 16), uint8_t(v >> 24), b5, b6, b7});
}
bool isLss(const CanFrame& f) { return f.id == lss::kSlaveToMaster; }
}  // namespace

class TestSimNmt : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { eds::installSimulatorDictionaries(); }

    void nmtStatesInHeartbeat() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("3:generic-cia402"), &err));
        QVERIFY(h.download(3, 0x1017, 0, SimHarness::u16(50)).ok());
        auto hb = [&] { return h.waitFor([](const CanFrame& f) { return f.id == 0x703; }, 300); };
        QCOMPARE(hb()->data[0], uint8_t(0x7F));
        h.send(CanFrame::classic(0x000, {0x01, 0x03}));
        h.clear();
        QCOMPARE(hb()->data[0], uint8_t(0x05));
        h.send(CanFrame::classic(0x000, {0x02, 0x00}));  // stop, broadcast
        h.clear();
        QCOMPARE(hb()->data[0], uint8_t(0x04));
        // STOPPED: no SDO.
        QVERIFY(!h.sdoRequest(3, canopen::sdo::initiateUpload(3, 0x1000, 0), 100));
        // Reset communication: boot-up, PRE-OPERATIONAL; 1017h is back to its default 0.
        h.send(CanFrame::classic(0x000, {0x82, 0x03}));
        QVERIFY(h.waitFor([](const CanFrame& f) { return f.id == 0x703 && f.data[0] == 0; }, 300));
        QCOMPARE(h.read(3, 0x1017, 0).value_or(1), 0u);
    }

    void nodeGuardingToggles() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("3:generic-cia402"), &err));
        CanFrame rtr = CanFrame::classic(0x703, {});
        rtr.flags |= CanFrame::Remote;
        rtr.len = 1;
        uint8_t expectToggle = 0;
        for (int i = 0; i < 4; ++i) {
            h.send(rtr);
            auto r = h.waitFor([](const CanFrame& f) { return f.id == 0x703 && !f.isRemote(); }, 300);
            QVERIFY(r);
            QCOMPARE(r->data[0] & 0x7F, 0x7F);
            QCOMPARE(r->data[0] & 0x80, int(expectToggle));  // CiA 301 §7.2.8.3.2.1: starts at 0
            expectToggle ^= 0x80;
        }
        // Life guarding: guard time 20 ms x factor 2 without a request -> EMCY 8130h.
        QVERIFY(h.download(3, 0x100C, 0, SimHarness::u16(20)).ok());
        QVERIFY(h.download(3, 0x100D, 0, SimHarness::u8(2)).ok());
        h.send(rtr);
        auto e = h.waitFor([](const CanFrame& f) { return f.id == 0x83; }, 500);
        QVERIFY(e);
        QCOMPARE(e->data[0] | (e->data[1] << 8), 0x8130);
    }

    void emcyHistory() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("1:delta-asda-a2"), &err));
        h.withDevice(1, [](sim::VirtualDevice& d) { d.injectDriveFault(QStringLiteral("AL009")); });
        auto e = h.waitFor([](const CanFrame& f) { return f.id == 0x81; }, 300);
        QVERIFY(e);
        QCOMPARE(e->data[0] | (e->data[1] << 8), 0x8611);
        // 1003h: one entry, (alarm number << 16) | error code.
        QCOMPARE(h.read(1, 0x1003, 0).value_or(0), 1u);
        QCOMPARE(h.read(1, 0x1003, 1).value_or(0), 0x00098611u);
        QVERIFY(h.read(1, 0x1001, 0).value_or(0) & 0x01);
        QCOMPARE(h.download(1, 0x1003, 0, SimHarness::u8(1)).abort, canopen::sdoabort::InvalidValue);
        QVERIFY(h.download(1, 0x1003, 0, SimHarness::u8(0)).ok());
        QCOMPARE(h.upload(1, 0x1003, 1).abort, canopen::sdoabort::NoData);
    }

    void storeAndRestore() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("3:generic-cia402"), &err));
        QVERIFY(h.download(3, 0x1017, 0, SimHarness::u16(250)).ok());
        QVERIFY(h.download(3, 0x1010, 1, SimHarness::u32(0x65766173)).ok());  // "save"
        QVERIFY(h.download(3, 0x1017, 0, SimHarness::u16(300)).ok());
        h.send(CanFrame::classic(0x000, {0x81, 0x03}));  // reset node: stored values come back
        QVERIFY(h.waitFor([](const CanFrame& f) { return f.id == 0x703 && f.data[0] == 0; }, 300));
        QCOMPARE(h.read(3, 0x1017, 0).value_or(0), 250u);
        QCOMPARE(h.read(3, 0x1010, 1).value_or(0), 1u);
        QVERIFY(h.download(3, 0x1011, 1, SimHarness::u32(0x64616F6C)).ok());  // "load"
        QCOMPARE(h.read(3, 0x1017, 0).value_or(0), 250u);                     // effective after reset
        h.withDevice(3, [](sim::VirtualDevice& d) { d.powerCycle(); });
        QCOMPARE(h.read(3, 0x1017, 0).value_or(1), 0u);
    }

    void lssSwitchConfigureStore() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("5:aimotor,6:generic-cia402"), &err));
        uint32_t vendor = 0, product = 0, revision = 0, serial = 0;
        h.withDevice(6, [&](sim::VirtualDevice& d) {
            vendor = uint32_t(d.value(0x1018, 1)->toUInt64().value_or(0));
            product = uint32_t(d.value(0x1018, 2)->toUInt64().value_or(0));
            revision = uint32_t(d.value(0x1018, 3)->toUInt64().value_or(0));
            serial = d.serialNumber();
        });
        // Switch state selective: only node 6 answers 44h.
        h.send(lssFrame(lss::SwitchSelectiveVendor, vendor));
        h.send(lssFrame(lss::SwitchSelectiveProduct, product));
        h.send(lssFrame(lss::SwitchSelectiveRevision, revision));
        h.send(lssFrame(lss::SwitchSelectiveSerial, serial));
        QVERIFY(
            h.waitFor([](const CanFrame& f) { return isLss(f) && f.data[0] == lss::SwitchSelectiveResponse; }, 300));
        QVERIFY(!h.waitFor(isLss, 50));
        // Inquire: serial and node-ID.
        h.send(lssFrame(lss::InquireSerial));
        auto s = h.waitFor(isLss, 300);
        QVERIFY(s);
        QCOMPARE(SimHarness::le(QByteArray(reinterpret_cast<const char*>(s->data.data() + 1), 4)), serial);
        h.send(lssFrame(lss::InquireNodeId));
        QCOMPARE(h.waitFor(isLss, 300)->data[1], uint8_t(6));
        // Configure node-ID 0x20 (200 is refused), bit timing 250 kbit/s (index 3), store.
        h.send(lssFrame(lss::ConfigureNodeId, 200));
        QCOMPARE(h.waitFor(isLss, 300)->data[1], uint8_t(1));
        h.send(lssFrame(lss::ConfigureNodeId, 0x20));
        QCOMPARE(h.waitFor(isLss, 300)->data[1], uint8_t(0));
        h.send(CanFrame::classic(lss::kMasterToSlave, {lss::ConfigureBitTiming, 0, 3, 0, 0, 0, 0, 0}));
        QCOMPARE(h.waitFor(isLss, 300)->data[1], uint8_t(0));
        h.send(lssFrame(lss::StoreConfiguration));
        QCOMPARE(h.waitFor(isLss, 300)->data[1], uint8_t(0));
        h.send(lssFrame(lss::SwitchStateGlobal, 0));
        // Reset communication: the node boots as 20h.
        h.send(CanFrame::classic(0x000, {0x82, 0x06}));
        QVERIFY(h.waitFor([](const CanFrame& f) { return f.id == 0x720 && f.data[0] == 0; }, 300));
        QVERIFY(h.upload(0x20, 0x1000, 0).ok());
        // Stored: survives a power cycle, with the bit rate.
        uint32_t rate = 0;
        uint8_t id = 0;
        h.net()->runOnNetworkThread([&] {
            auto* d = h.net()->device(0x20);
            d->powerCycle();
            rate = d->bitRate();
            id = d->nodeId();
        });
        QCOMPARE(int(id), 0x20);
        QCOMPARE(rate, 250000u);
    }

    void lssIdentifyAndFastscan() {
        SimHarness h;
        QString err;
        QVERIFY(h.open(QStringLiteral("8:generic-cia402,9:generic-cia402"), &err));
        uint32_t id[4] = {};
        h.withDevice(9, [&](sim::VirtualDevice& d) {
            for (int i = 0; i < 4; ++i) id[i] = uint32_t(d.value(0x1018, uint8_t(i + 1))->toUInt64().value_or(0));
            d.makeUnconfigured();
        });
        // Identify remote slave with a range holding both serial numbers: both answer 4Fh.
        h.send(lssFrame(lss::IdentifyVendor, id[0]));
        h.send(lssFrame(lss::IdentifyProduct, id[1]));
        h.send(lssFrame(lss::IdentifyRevisionLow, 0));
        h.send(lssFrame(lss::IdentifyRevisionHigh, 0xFFFFFFFF));
        h.send(lssFrame(lss::IdentifySerialLow, 0));
        h.send(lssFrame(lss::IdentifySerialHigh, 0xFFFFFFFF));
        const auto answers = h.collect(80);
        QCOMPARE(std::count_if(answers.begin(), answers.end(),
                               [](const CanFrame& f) { return isLss(f) && f.data[0] == lss::IdentifySlaveResponse; }),
                 2);
        h.send(lssFrame(lss::IdentifyNonConfigured));
        QCOMPARE(h.waitFor(isLss, 200)->data[0], lss::IdentifyNonConfiguredResponse);
        QVERIFY(!h.waitFor(isLss, 50));  // node 8 is configured

        // Fastscan (CiA 305 §6.7): find the unconfigured slave's 128-bit address bit by bit.
        h.send(lssFrame(lss::Fastscan, 0, 0x80, 0, 0));
        QVERIFY(h.waitFor(isLss, 100));
        uint32_t found[4] = {};
        for (int sub = 0; sub < 4; ++sub) {
            for (int bit = 31; bit >= 0; --bit) {
                h.send(lssFrame(lss::Fastscan, found[sub], uint8_t(bit), uint8_t(sub), uint8_t(sub)));
                if (!h.waitFor(isLss, 30)) found[sub] |= 1u << bit;  // no answer: the bit is 1
            }
            h.send(lssFrame(lss::Fastscan, found[sub], 0, uint8_t(sub), uint8_t(sub < 3 ? sub + 1 : 0)));
            QVERIFY2(h.waitFor(isLss, 100), qPrintable(QString::number(sub)));
            QCOMPARE(found[sub], id[sub]);
        }
        // The slave is now in configuration state: give it node-ID 0x30 and reset it.
        h.send(lssFrame(lss::ConfigureNodeId, 0x30));
        QCOMPARE(h.waitFor(isLss, 300)->data[1], uint8_t(0));
        h.send(CanFrame::classic(0x000, {0x82, 0x00}));
        QVERIFY(h.waitFor([](const CanFrame& f) { return f.id == 0x730 && f.data[0] == 0; }, 300));
    }
};

QTEST_GUILESS_MAIN(TestSimNmt)
#include "test_sim_nmt.moc"
