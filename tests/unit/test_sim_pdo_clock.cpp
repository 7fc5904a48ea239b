// SPDX-License-Identifier: GPL-3.0-or-later
// A virtual device driven by a simulated clock (no network thread, no wall time): event-driven
// TPDOs on entering OPERATIONAL and on re-enabling, event timer and inhibit time to within 1 ms,
// RPDOs only in OPERATIONAL, and the SYNC counter per 1019h. Expectations from CiA 301 §7.2.2,
// §7.2.5, §7.3.2 and §7.5.2.22, and from the manuals' PDO sections (extract-aimotor §3.6).
#include "core/canopen/SdoAbort.h"
#include "core/sim/VirtualDevice.h"
#include "eds/SimulatorDictionaries.h"

#include <QtTest>

#include <memory>
#include <vector>

using namespace coscope;
using namespace coscope::sim;

namespace {
constexpr int64_t kMs = 1'000'000;

// One device on a bus of its own; the test is the rest of the bus.
struct Rig {
    std::unique_ptr<VirtualDevice> dev;
    std::vector<CanFrame> sent;
    int64_t now = 0;

    explicit Rig(const QString& spec, uint8_t node) {
        QString err;
        dev = VirtualDevice::create(node, spec, &err);
        QVERIFY2(dev, qPrintable(err));
        dev->setTransmitter([this](const CanFrame& f) {
            CanFrame c = f;
            c.timestampNs = now;
            sent.push_back(c);
        });
        dev->powerOn(now);
    }
    void frame(const CanFrame& f) { dev->onFrame(f, now); }
    // Runs the simulated clock for `ns` in steps of `stepNs`.
    void run(int64_t ns, int64_t stepNs = kMs) {
        const int64_t end = now + ns;
        while (now < end) {
            now = std::min(end, now + stepNs);
            dev->tick(now);
        }
    }
    void nmt(uint8_t cs) { frame(CanFrame::classic(0x000, {cs, 0})); }
    void set(uint16_t index, uint8_t sub, uint64_t v) {
        QString why;
        QVERIFY2(dev->setValue(index, sub, od::Value::unsignedInt(v), &why), qPrintable(why));
    }
    std::vector<int64_t> times(uint32_t id) const {
        std::vector<int64_t> t;
        for (const CanFrame& f : sent)
            if (f.id == id) t.push_back(f.timestampNs);
        return t;
    }
};
}  // namespace

class TestSimPdoClock : public QObject {
    Q_OBJECT
    static constexpr uint8_t G = 3;

private slots:
    void initTestCase() { eds::installSimulatorDictionaries(); }

    // generic-cia402 TPDO1 (6041h, type FFh) goes out once on NMT start, not again while the
    // statusword stays, and once more after Pre-operational -> Operational.
    void eventTpdoOnceOnEnteringOperational() {
        Rig r(QStringLiteral("generic-cia402"), G);
        r.run(20 * kMs);
        QCOMPARE(r.times(0x183).size(), size_t(0));  // PRE-OPERATIONAL: none
        r.nmt(0x01);
        r.run(50 * kMs);
        QCOMPARE(r.times(0x183).size(), size_t(1));
        r.nmt(0x80);
        r.run(20 * kMs);
        r.nmt(0x01);
        r.run(20 * kMs);
        QCOMPARE(r.times(0x183).size(), size_t(2));
    }

    // Re-enabling one TPDO (COB-ID bit 31 cleared) sends it once; writing another PDO's
    // parameters does not resend the TPDOs whose configuration did not change.
    void eventTpdoOnceWhenReEnabled() {
        Rig r(QStringLiteral("generic-cia402"), G);
        r.nmt(0x01);
        r.run(10 * kMs);
        QCOMPARE(r.times(0x183).size(), size_t(1));
        QCOMPARE(r.times(0x283).size(), size_t(1));
        QCOMPARE(r.dev->writeFromSdo(0x1800, 1, QByteArray::fromHex("83010080")), 0u);  // disable TPDO1
        r.run(10 * kMs);
        QCOMPARE(r.dev->writeFromSdo(0x1800, 1, QByteArray::fromHex("83010000")), 0u);  // enable again
        r.run(10 * kMs);
        QCOMPARE(r.times(0x183).size(), size_t(2));
        QCOMPARE(r.times(0x283).size(), size_t(1));
        QCOMPARE(r.dev->writeFromSdo(0x1400, 3, QByteArray::fromHex("0000")), 0u);  // an RPDO parameter
        r.run(10 * kMs);
        QCOMPARE(r.times(0x183).size(), size_t(2));
        QCOMPARE(r.times(0x283).size(), size_t(1));
    }

    // Event timer 10 ms with the clock ticking in 700 µs steps: the n-th transmission stays
    // within 1 ms of n x 10 ms after the first (the timer restarts at each transmission).
    void eventTimerWithinOneMillisecond() {
        Rig r(QStringLiteral("generic-cia402"), G);
        r.set(0x1800, 5, 10);
        r.nmt(0x01);
        r.run(1000 * kMs, 700'000);
        const auto t = r.times(0x183);
        QVERIFY2(t.size() >= 99 && t.size() <= 101, qPrintable(QString::number(t.size())));
        for (size_t n = 1; n < t.size(); ++n) {
            const int64_t err = t[n] - t[0] - int64_t(n) * 10 * kMs;
            QVERIFY2(err >= 0 && err < kMs,
                     qPrintable(QStringLiteral("TPDO %1 at %2 ns, %3 ns late").arg(n).arg(t[n]).arg(err)));
        }
    }

    // Inhibit time 2.5 ms (25 x 100 µs) on a TPDO whose data (607Ah) changes every 200 µs:
    // transmissions are at least 2.5 ms apart and at most 1 ms later than the inhibit time allows.
    void inhibitTimeWithinOneMillisecond() {
        Rig r(QStringLiteral("generic-cia402"), G);
        QCOMPARE(r.dev->writeFromSdo(0x1800, 1, QByteArray::fromHex("83010080")), 0u);
        QCOMPARE(r.dev->writeFromSdo(0x1A00, 0, QByteArray::fromHex("00")), 0u);
        QCOMPARE(r.dev->writeFromSdo(0x1A00, 1, QByteArray::fromHex("20007A60")), 0u);  // 607A:00, 32 bit
        QCOMPARE(r.dev->writeFromSdo(0x1A00, 0, QByteArray::fromHex("01")), 0u);
        QCOMPARE(r.dev->writeFromSdo(0x1800, 1, QByteArray::fromHex("83010000")), 0u);
        r.set(0x1800, 3, 25);
        r.nmt(0x01);
        for (int i = 1; i <= 1000; ++i) {
            QVERIFY(r.dev->setValue(0x607A, 0, od::Value::signedInt(i)));
            r.run(200'000, 200'000);
        }
        const auto t = r.times(0x183);
        QVERIFY2(t.size() >= 70, qPrintable(QString::number(t.size())));
        for (size_t n = 1; n < t.size(); ++n) {
            const int64_t gap = t[n] - t[n - 1];
            QVERIFY2(gap >= 2'500'000 && gap < 3'500'000, qPrintable(QString::number(gap)));
        }
    }

    // aimotor RPDO1 (type 1: applied at the next SYNC). An RPDO in PRE-OPERATIONAL is ignored;
    // one received in OPERATIONAL but not yet applied is dropped when the node leaves it.
    void rpdoIgnoredOutsideOperational() {
        Rig r(QStringLiteral("aimotor"), 2);
        const auto rpdo = CanFrame::classic(0x202, {0x06, 0x00, 0x01, 0x10, 0x27, 0x00, 0x00});  // 0006h, pp, 10000
        r.frame(rpdo);
        r.frame(CanFrame::classic(0x080, {}));
        r.run(5 * kMs);
        QCOMPARE(r.dev->value(0x607A, 0)->toInt64().value_or(-1), 0);
        r.nmt(0x01);
        r.run(2 * kMs);
        r.frame(rpdo);
        r.nmt(0x80);
        r.run(2 * kMs);
        r.nmt(0x01);
        r.run(2 * kMs);
        r.frame(CanFrame::classic(0x080, {}));
        r.run(2 * kMs);
        QCOMPARE(r.dev->value(0x607A, 0)->toInt64().value_or(-1), 0);
        r.frame(rpdo);
        r.frame(CanFrame::classic(0x080, {}));
        r.run(2 * kMs);
        QCOMPARE(r.dev->value(0x607A, 0)->toInt64().value_or(-1), 10000);
    }

    // 1019h = 0: the SYNC counter is not processed, so the SYNC start value has no effect and a
    // SYNC with a data byte is an unexpected length (EMCY 8240h). 1019h = 5: the first TPDO goes
    // at the SYNC whose counter equals the SYNC start value.
    void syncCounterOverflow() {
        Rig r(QStringLiteral("generic-cia402"), G);
        QCOMPARE(r.dev->writeFromSdo(0x1800, 1, QByteArray::fromHex("83010080")), 0u);
        QCOMPARE(r.dev->writeFromSdo(0x1800, 2, QByteArray::fromHex("02")), 0u);  // every 2nd SYNC
        QCOMPARE(r.dev->writeFromSdo(0x1800, 6, QByteArray::fromHex("03")), 0u);  // SYNC start value 3
        QCOMPARE(r.dev->writeFromSdo(0x1800, 1, QByteArray::fromHex("83010000")), 0u);
        r.nmt(0x01);
        r.run(kMs);
        r.sent.clear();
        // 1019h = 0: counter ignored; a SYNC with one byte is reported and still a SYNC.
        r.frame(CanFrame::classic(0x080, {1}));
        r.run(kMs);
        r.frame(CanFrame::classic(0x080, {2}));
        r.run(kMs);
        QCOMPARE(r.times(0x083).size(), size_t(2));  // EMCY 8240h twice
        QCOMPARE(int(r.sent.front().data[0]) | int(r.sent.front().data[1]) << 8, 0x8240);
        QCOMPARE(r.times(0x183).size(), size_t(1));  // second SYNC: TPDO1 (counter not used)

        // 1019h may change only while 1006h is 0.
        QCOMPARE(r.dev->writeFromSdo(0x1006, 0, QByteArray::fromHex("10270000")), 0u);
        QCOMPARE(r.dev->writeFromSdo(0x1019, 0, QByteArray::fromHex("05")), canopen::sdoabort::DeviceState);
        QCOMPARE(r.dev->writeFromSdo(0x1006, 0, QByteArray::fromHex("00000000")), 0u);
        QCOMPARE(r.dev->writeFromSdo(0x1019, 0, QByteArray::fromHex("05")), 0u);
        QCOMPARE(r.dev->writeFromSdo(0x1019, 0, QByteArray::fromHex("01")), canopen::sdoabort::InvalidValue);
        r.nmt(0x80);
        r.nmt(0x01);
        r.run(kMs);
        r.sent.clear();
        std::vector<int> counters;
        for (uint8_t c : {4, 5, 1, 2, 3, 4, 5, 1, 2}) {
            const size_t before = r.times(0x183).size();
            r.frame(CanFrame::classic(0x080, {c}));
            r.run(kMs);
            if (r.times(0x183).size() > before) counters.push_back(c);
            QVERIFY(r.times(0x083).empty());  // DLC 1 matches 1019h = 5
        }
        QCOMPARE(counters, (std::vector<int>{3, 5, 2}));
        // A SYNC without the counter byte while 1019h = 5 is an unexpected length.
        r.frame(CanFrame::classic(0x080, {}));
        QCOMPARE(r.times(0x083).size(), size_t(1));
    }

    // DEXMART DEV: TPDO1 of type FEh (its default, inhibit and event time 0Ah) is the answer to
    // RPDO1 and its event timer has no function (extract-dexmart §4.2-4.3, §8.3).
    void dexmartFeTpdoAnswersRpdo() {
        Rig r(QStringLiteral("dexmart-dev"), 4);
        r.nmt(0x01);
        r.run(100 * kMs);
        QCOMPARE(r.times(0x184).size(), size_t(0));
        r.frame(CanFrame::classic(0x204, {0x00, 0x00, 0x00, 0x00, 0x00}));  // RPDO1: 3051h CMD 0, data 0
        r.run(5 * kMs);
        QCOMPARE(r.times(0x184).size(), size_t(1));
        QCOMPARE(r.times(0x284).size(), size_t(0));  // TPDO2 answers RPDO2 only
        r.run(100 * kMs);
        QCOMPARE(r.times(0x184).size(), size_t(1));
    }
};

QTEST_GUILESS_MAIN(TestSimPdoClock)
#include "test_sim_pdo_clock.moc"
