// SPDX-License-Identifier: GPL-3.0-or-later
// A virtual drive starts with the defaults its manual gives (resources/README.md, "Defaults of
// the virtual drives", lists where each comes from): PDO transmission types, inhibit times and
// event timers, mapping counts, producer heartbeat time and the data type of 1017h.
#include "core/od/DataType.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::sim;

namespace {
struct PdoDefaults {
    int count;  // PDOs of each direction
    uint8_t rpdoType, tpdoType;
    uint16_t tpdoInhibit, tpdoEvent;
    std::vector<uint8_t> rpdoMapped, tpdoMapped;  // 1600h+n / 1A00h+n sub 0
};
struct Defaults {
    const char* name;
    PdoDefaults pdo;
    od::DataType heartbeatType;
    uint16_t heartbeatMs;
};

// From the seed manuals:
//  delta-asda-a2  extract-delta §3.2 (1017h U16 default 0; 1400h-1403h/1800h-1803h type 0,
//                 inhibit and event timer 0) and §5 (no default mapping: every :00 is 0).
//  aimotor        extract-aimotor §2.3 (1017h UINT32 default 0) and §3.6 (8 PDOs of type 1,
//                 event timers 0, RPDO1/2 and TPDO1/2 mapped with 3 and 2 objects).
//  dexmart-dev    extract-dexmart §2.5 (1017h u16 default 0000h), §4.7 and §8.3 (type FEh,
//                 inhibit 0Ah, event time 0Ah).
const Defaults kManuals[] = {
    {"delta-asda-a2", {4, 0x00, 0x00, 0, 0, {0, 0, 0, 0}, {0, 0, 0, 0}}, od::DataType::Unsigned16, 0},
    {"aimotor", {4, 0x01, 0x01, 0, 0, {3, 2, 0, 0}, {3, 2, 0, 0}}, od::DataType::Unsigned32, 0},
    {"dexmart-dev", {4, 0xFE, 0xFE, 0x0A, 0x0A, {}, {}}, od::DataType::Unsigned16, 0},
};

uint64_t u(const VirtualDevice& d, uint16_t index, uint8_t sub) {
    const auto v = d.value(index, sub);
    return v ? v->toUInt64().value_or(~0ull) : ~0ull;
}
}  // namespace

class TestSimManualDefaults : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { eds::installSimulatorDictionaries(); }

    void startsWithTheManualsDefaults_data() {
        QTest::addColumn<int>("row");
        for (int i = 0; i < int(std::size(kManuals)); ++i) QTest::newRow(kManuals[i].name) << i;
    }
    void startsWithTheManualsDefaults() {
        QFETCH(int, row);
        const Defaults& m = kManuals[row];
        QString err;
        auto dev = VirtualDevice::create(5, QString::fromLatin1(m.name), &err);
        QVERIFY2(dev, qPrintable(err));
        const od::SubObject* hb = dev->entry(0x1017, 0);
        QVERIFY(hb);
        QCOMPARE(hb->dataType, m.heartbeatType);
        QCOMPARE(u(*dev, 0x1017, 0), uint64_t(m.heartbeatMs));
        for (int n = 0; n < m.pdo.count; ++n) {
            const auto rc = static_cast<uint16_t>(0x1400 + n), tc = static_cast<uint16_t>(0x1800 + n);
            QVERIFY2(dev->entry(rc, 2) && dev->entry(tc, 2), qPrintable(QStringLiteral("PDO %1 missing").arg(n + 1)));
            QCOMPARE(u(*dev, rc, 2), uint64_t(m.pdo.rpdoType));
            QCOMPARE(u(*dev, tc, 2), uint64_t(m.pdo.tpdoType));
            if (dev->entry(tc, 3)) QCOMPARE(u(*dev, tc, 3), uint64_t(m.pdo.tpdoInhibit));
            QCOMPARE(u(*dev, tc, 5), uint64_t(m.pdo.tpdoEvent));
            QCOMPARE(u(*dev, rc, 1), uint64_t(0x200 + 0x100 * n + 5));  // valid, default COB-ID
            QCOMPARE(u(*dev, tc, 1), uint64_t(0x180 + 0x100 * n + 5));
            if (!m.pdo.rpdoMapped.empty())
                QCOMPARE(u(*dev, static_cast<uint16_t>(0x1600 + n), 0), uint64_t(m.pdo.rpdoMapped[size_t(n)]));
            if (!m.pdo.tpdoMapped.empty())
                QCOMPARE(u(*dev, static_cast<uint16_t>(0x1A00 + n), 0), uint64_t(m.pdo.tpdoMapped[size_t(n)]));
        }
    }
};

QTEST_GUILESS_MAIN(TestSimManualDefaults)
#include "test_sim_manual_defaults.moc"
