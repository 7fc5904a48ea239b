// SPDX-License-Identifier: GPL-3.0-or-later
// SignalRecorder::pdosSeen (dissectors/SignalRecorder.h): every PDO seen in the trace, once per
// bus and COB-ID, however often it repeats and whichever batch brings it (the plot says "no
// dictionary" for them). Default COB-IDs, CiA 301 §7.3.5 (TPDO1 180h + node, RPDO1 200h + node).
#include "dissectors/SignalRecorder.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::dissect;

namespace {
CanFrame pdo(uint32_t id, int bus, int64_t ns) {
    CanFrame f;
    f.id = id;
    f.bus = static_cast<uint8_t>(bus);
    f.len = 2;
    f.timestampNs = ns;
    return f;
}
}  // namespace

class SignalRecorderPdosTest : public QObject {
    Q_OBJECT
private slots:
    void eachPdoOncePerBusAndCobId() {
        TraceStore store;
        SignalRecorder rec;
        int64_t ns = 0;
        auto feed = [&](std::initializer_list<std::pair<uint32_t, int>> frames) {
            const FrameNo first = static_cast<FrameNo>(store.size());
            for (const auto& [id, bus] : frames) store.append(pdo(id, bus, ns += 1000));
            rec.consume(store, first, store.size() - first);
        };
        feed({{0x181, 0}, {0x181, 0}, {0x000, 0}, {0x181, 1}});
        feed({{0x181, 0}, {0x281, 0}, {0x181, 1}, {0x205, 1}, {0x701, 0}});
        feed({{0x181, 1}, {0x281, 0}, {0x205, 1}});
        const auto seen = rec.pdosSeen();
        QCOMPARE(seen.size(), size_t(4));
        QCOMPARE(seen[0].bus, 0);
        QCOMPARE(seen[0].cobId, 0x181u);
        QCOMPARE(seen[0].node, 1);
        QCOMPARE(seen[0].pdo, QStringLiteral("TPDO1"));
        QCOMPARE(seen[1].bus, 0);
        QCOMPARE(seen[1].cobId, 0x281u);
        QCOMPARE(seen[1].pdo, QStringLiteral("TPDO2"));
        QCOMPARE(seen[2].bus, 1);
        QCOMPARE(seen[2].cobId, 0x181u);
        QCOMPARE(seen[3].bus, 1);
        QCOMPARE(seen[3].cobId, 0x205u);
        QCOMPARE(seen[3].node, 5);
        QCOMPARE(seen[3].pdo, QStringLiteral("RPDO1"));
    }

    // A 29-bit frame whose identifier looks like a PDO is no CANopen PDO (CiA 301 uses 11-bit
    // COB-IDs by default): it neither shows up nor hides the 11-bit PDO with the same number.
    void extendedIdentifierIsNotThePdo() {
        TraceStore store;
        SignalRecorder rec;
        CanFrame ext = pdo(0x181, 0, 1000);
        ext.flags = CanFrame::Extended;
        store.append(ext);
        store.append(pdo(0x181, 0, 2000));
        rec.consume(store, 0, 2);
        const auto seen = rec.pdosSeen();
        QCOMPARE(seen.size(), size_t(1));
        QCOMPARE(seen[0].cobId, 0x181u);
    }
};

QTEST_GUILESS_MAIN(SignalRecorderPdosTest)
#include "test_signal_recorder_pdos.moc"
