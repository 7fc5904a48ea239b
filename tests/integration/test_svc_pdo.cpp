// SPDX-License-Identifier: GPL-3.0-or-later
// PDO configurator against virtual drives: read a PDO set, write a mapping in the CiA 301
// order and verify it, refuse over-long or non-mappable mappings before sending, and roll back
// when a step fails.
#include "SvcTestRig.h"

#include "core/canopen/NmtMaster.h"
#include "core/canopen/PdoConfigurator.h"
#include "core/canopen/ServiceWait.h"
#include "core/sim/VirtualDevice.h"
#include "eds/DictionaryLibrary.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;
using namespace svctest;

namespace {
template <typename R, typename F>
R wait(F start) {
    auto r = waitForResult<R>(start, 30000);
    return r ? *r : R{};
}
od::ObjectDictionary dictionary(const QString& name) {
    eds::DictionaryLibrary lib;
    return lib.load(name).dictionary;
}
uint64_t requests(Rig& rig, uint8_t node) {
    uint64_t n = 0;
    rig.onDevice(node, [&](sim::VirtualDevice& d) { n = d.sdoRequests(); });
    return n;
}
}  // namespace

class TestSvcPdo : public QObject {
    Q_OBJECT
private slots:
    void readSetOfAimotor() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("2:aimotor")));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        PdoConfigurator pdo(sdo);
        const auto set = wait<std::vector<PdoReadResult>>([&](auto cb) { pdo.readSet(2, cb); });
        QVERIFY(set.size() >= 2);
        const PdoReadResult& t1 = set.front();
        QVERIFY2(t1.ok, qPrintable(t1.error));
        QCOMPARE(t1.pdo.name(), QStringLiteral("TPDO1"));
        QCOMPARE(t1.config.cobId & 0x7FF, 0x182u);
        QCOMPARE(t1.config.entries.size(), size_t(3));  // EDS default: 6041/16, 6061/8, 6064/32
        QCOMPARE(t1.config.entries[0], (PdoMapEntry{0x6041, 0, 16}));
        QCOMPARE(t1.config.entries[2], (PdoMapEntry{0x6064, 0, 32}));
    }

    void mapWritesInOrderAndVerifies() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("3:generic-cia402")));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        NmtMaster nmt(*rig.context);
        PdoConfigurator pdo(sdo, &nmt);
        const od::ObjectDictionary dict = dictionary(QStringLiteral("generic-cia402"));
        PdoConfig want;
        want.entries = {{0x6041, 0, 0}, {0x6064, 0, 0}};
        want.transmissionType = 1;
        want.inhibitTime = 100;
        want.eventTimer = 50;
        const PdoId t1{true, 1};
        const auto r = wait<PdoWriteResult>([&](auto cb) { pdo.write(3, t1, want, &dict, cb); });
        QVERIFY2(r.ok, qPrintable(r.error));
        QCOMPARE(r.written.totalBits(), 48);
        // CiA 301 order.
        QCOMPARE(r.steps.size(), 9);
        // Communication parameters while the PDO is not valid (the inhibit time may not change
        // while it is, CiA 301 §7.5.2.35), then the mapping, then valid again.
        QVERIFY(r.steps[0].startsWith(QStringLiteral("1800:01 = 0x80000183")));
        QVERIFY(r.steps[1].startsWith(QStringLiteral("1800:02 = 0x01")));
        QVERIFY(r.steps[2].startsWith(QStringLiteral("1800:03 = 0x0064")));
        QVERIFY(r.steps[3].startsWith(QStringLiteral("1800:05 = 0x0032")));
        QVERIFY(r.steps[4].startsWith(QStringLiteral("1A00:00 = 0x00")));
        QVERIFY(r.steps[5].startsWith(QStringLiteral("1A00:01 = 0x60410010")));
        QVERIFY(r.steps[6].startsWith(QStringLiteral("1A00:02 = 0x60640020")));
        QVERIFY(r.steps[7].startsWith(QStringLiteral("1A00:00 = 0x02")));
        QVERIFY(r.steps[8].startsWith(QStringLiteral("1800:01 = 0x00000183")));
        const auto back = wait<PdoReadResult>([&](auto cb) { pdo.read(3, t1, cb); });
        QVERIFY(back.ok);
        QCOMPARE(back.config.entries, r.written.entries);
        QCOMPARE(back.config.transmissionType, uint8_t(1));
        QCOMPARE(back.config.eventTimer, std::optional<uint16_t>(50));
        canopen::NmtState state = canopen::NmtState::BootUp;
        rig.onDevice(3, [&](sim::VirtualDevice& d) { state = d.nmtState(); });
        QCOMPARE(state, canopen::NmtState::PreOperational);
    }

    void refusesBeforeSending() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("3:generic-cia402")));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        PdoConfigurator pdo(sdo);
        const od::ObjectDictionary dict = dictionary(QStringLiteral("generic-cia402"));
        QTest::qWait(50);
        const uint64_t before = requests(rig, 3);
        PdoConfig tooLong;
        tooLong.entries = {{0x6064, 0, 0}, {0x606C, 0, 0}, {0x6041, 0, 0}};  // 80 bits
        auto r = wait<PdoWriteResult>([&](auto cb) { pdo.write(3, PdoId{true, 1}, tooLong, &dict, cb); });
        QVERIFY(!r.ok);
        QVERIFY2(r.error.contains(QStringLiteral("80 bits")), qPrintable(r.error));
        PdoConfig notMappable;
        notMappable.entries = {{0x1000, 0, 0}};
        r = wait<PdoWriteResult>([&](auto cb) { pdo.write(3, PdoId{true, 1}, notMappable, &dict, cb); });
        QVERIFY(!r.ok);
        QVERIFY2(r.error.contains(QStringLiteral("not PDO-mappable")), qPrintable(r.error));
        PdoConfig readOnlyInRpdo;
        readOnlyInRpdo.entries = {{0x6041, 0, 0}};
        r = wait<PdoWriteResult>([&](auto cb) { pdo.write(3, PdoId{false, 1}, readOnlyInRpdo, &dict, cb); });
        QVERIFY(!r.ok);
        QTest::qWait(50);
        QCOMPARE(requests(rig, 3), before);  // nothing was sent
    }

    void failedStepRestoresPreviousMapping() {
        Rig rig;
        QVERIFY(rig.useSpec(QStringLiteral("3:generic-cia402")));
        QVERIFY(rig.open());
        SdoClient sdo(*rig.context);
        PdoConfigurator pdo(sdo);
        const od::ObjectDictionary dict = dictionary(QStringLiteral("generic-cia402"));
        const PdoId t1{true, 1};
        const auto before = wait<PdoReadResult>([&](auto cb) { pdo.read(3, t1, cb); });
        QVERIFY(before.ok);
        const uint8_t failingSub = static_cast<uint8_t>(before.config.entries.size() + 1);
        rig.onDevice(3, [&](sim::VirtualDevice& d) {
            d.sdoFaults().abortOn = std::make_tuple(uint16_t(0x1A00), failingSub, uint32_t(0x06040041));
        });
        PdoConfig want;
        for (size_t i = 0; i < failingSub; ++i)
            want.entries.push_back(i % 2 ? PdoMapEntry{0x6061, 0, 0} : PdoMapEntry{0x6041, 0, 0});
        want.transmissionType = 254;
        const auto r = wait<PdoWriteResult>([&](auto cb) { pdo.write(3, t1, want, &dict, cb); });
        QVERIFY(!r.ok);
        QVERIFY(r.restored);
        QVERIFY2(r.failedStep.contains(QStringLiteral("1A00:%1").arg(failingSub, 2, 10, QChar(u'0'))),
                 qPrintable(r.failedStep));
        QVERIFY2(r.error.contains(QStringLiteral("previous mapping restored")), qPrintable(r.error));
        rig.onDevice(3, [](sim::VirtualDevice& d) { d.sdoFaults().abortOn.reset(); });
        const auto after = wait<PdoReadResult>([&](auto cb) { pdo.read(3, t1, cb); });
        QVERIFY(after.ok);
        QCOMPARE(after.config.entries, before.config.entries);
        QCOMPARE(after.config.cobId, before.config.cobId);
        QCOMPARE(after.config.transmissionType, before.config.transmissionType);
    }

    void parsesNamesAndEntries() {
        QCOMPARE(parsePdoName(QStringLiteral("tpdo1"))->communicationIndex(), uint16_t(0x1800));
        QCOMPARE(parsePdoName(QStringLiteral("RPDO4"))->mappingIndex(), uint16_t(0x1603));
        QVERIFY(!parsePdoName(QStringLiteral("xpdo1")));
        QString error;
        const auto e = parsePdoEntries(QStringLiteral("6041:00,6064:00/32"), &error);
        QVERIFY(e);
        QCOMPARE(e->size(), size_t(2));
        QCOMPARE((*e)[1].bits, uint8_t(32));
        QVERIFY(!parsePdoEntries(QStringLiteral("6041-00"), &error));
    }
};

QTEST_GUILESS_MAIN(TestSvcPdo)
#include "test_svc_pdo.moc"
