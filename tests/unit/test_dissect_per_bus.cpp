// SPDX-License-Identifier: GPL-3.0-or-later
// One network context per bus: node 5 on bus 0 and node 5 on bus 1 are different devices, with
// their own PDO mappings (learned from SDO, CiA 301 §7.5.2.35..38), NMT state and identity.
#include "core/can/CanFrame.h"
#include "dissectors/NetworkContext.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::dissect;
using canopen::Service;

namespace {

CanFrame on(uint8_t bus, uint32_t id, std::vector<uint8_t> b) {
    CanFrame f = CanFrame::classic(id, {});
    f.len = static_cast<uint8_t>(b.size());
    std::copy(b.begin(), b.end(), f.data.begin());
    f.bus = bus;
    return f;
}

// Confirmed expedited writes mapping TPDO1 of node 5 to one object (`mapEntry`, CiA 301 §7.4.8.2).
std::vector<CanFrame> mapTpdo1(uint8_t bus, uint32_t mapEntry) {
    const std::vector<std::vector<uint8_t>> writes = {
        {0x2F, 0x00, 0x1A, 0x00, 0x00, 0, 0, 0},
        {0x23, 0x00, 0x1A, 0x01, uint8_t(mapEntry), uint8_t(mapEntry >> 8), uint8_t(mapEntry >> 16),
         uint8_t(mapEntry >> 24)},
        {0x2F, 0x00, 0x1A, 0x00, 0x01, 0, 0, 0}};
    std::vector<CanFrame> v;
    for (const auto& w : writes) {
        v.push_back(on(bus, 0x605, w));
        v.push_back(on(bus, 0x585, {0x60, w[1], w[2], w[3], 0, 0, 0, 0}));
    }
    return v;
}

}  // namespace

class DissectPerBus : public QObject {
    Q_OBJECT
private slots:
    void sameNodeIdDifferentMappings() {
        NetworkContext ctx;
        Dissection d;
        // Interleaved configuration: bus 0 maps statusword 6041h (16 bit), bus 1 maps position
        // actual 6064h (32 bit), to the same TPDO1 of the same node-ID.
        const auto a = mapTpdo1(0, 0x60410010);
        const auto b = mapTpdo1(1, 0x60640020);
        for (size_t i = 0; i < a.size(); ++i) {
            ctx.dissect(a[i], d);
            ctx.dissect(b[i], d);
        }
        QCOMPARE(ctx.busCount(), 2);
        ctx.dissect(on(0, 0x185, {0x37, 0x16}), d);
        QCOMPARE(d.service, Service::Tpdo1);
        QCOMPARE(d.signalCount, 1);
        QCOMPARE(d.pdoSignals[0].index, 0x6041);
        QCOMPARE(d.pdoSignals[0].value.u, 0x1637u);
        ctx.dissect(on(1, 0x185, {0x00, 0x88, 0x13, 0x00}), d);
        QCOMPARE(d.signalCount, 1);
        QCOMPARE(d.pdoSignals[0].index, 0x6064);
        QCOMPARE(d.pdoSignals[0].value.i, 1280000);
        // The mapping of bus 0 is still in force after a bus 1 frame.
        ctx.dissect(on(0, 0x185, {0x37, 0x02}), d);
        QCOMPARE(d.pdoSignals[0].index, 0x6041);
        // A snapshot (checkpoint) keeps both buses.
        NetworkContext snapshot = ctx;
        Dissection d2;
        snapshot.dissect(on(1, 0x185, {0x00, 0x88, 0x13, 0x00}), d2);
        QCOMPARE(d2.pdoSignals[0].index, 0x6064);
    }

    void nmtAndIdentityPerBus() {
        NetworkContext ctx;
        Dissection d;
        ctx.dissect(on(0, 0x705, {0x05}), d);  // heartbeat node 5 on bus 0: operational
        ctx.dissect(on(1, 0x705, {0x7F}), d);  // node 5 on bus 1: pre-operational
        QCOMPARE(ctx.node(0, 5).nmtState, 5);
        QCOMPARE(ctx.node(1, 5).nmtState, 127);
        ctx.dissect(on(1, 0x000, {0x02, 0x00}), d);  // NMT stop, all nodes, on bus 1 only
        QCOMPARE(ctx.node(0, 5).nmtState, 5);
        QCOMPARE(ctx.node(1, 5).nmtState, 4);
        // Identity read on bus 1 (Delta: vendor 1DDh, product 6000h) names only bus 1's node 5.
        for (const auto& f : {on(1, 0x605, {0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0}),
                              on(1, 0x585, {0x43, 0x18, 0x10, 0x01, 0xDD, 0x01, 0, 0}),
                              on(1, 0x605, {0x40, 0x18, 0x10, 0x02, 0, 0, 0, 0}),
                              on(1, 0x585, {0x43, 0x18, 0x10, 0x02, 0x00, 0x60, 0, 0})})
            ctx.dissect(f, d);
        QCOMPARE(ctx.node(1, 5).dictionaryName, QStringLiteral("delta-asda-a2"));
        QVERIFY(ctx.node(0, 5).dictionaryName.isEmpty());
        // An SDO transfer in progress on bus 0 is not disturbed by one on bus 1.
        ctx.dissect(on(0, 0x605, {0x40, 0x08, 0x10, 0x00, 0, 0, 0, 0}), d);  // read 1008h on bus 0
        ctx.dissect(on(1, 0x605, {0x40, 0x09, 0x10, 0x00, 0, 0, 0, 0}), d);  // read 1009h on bus 1
        QVERIFY2(d.warnings.isEmpty(), qPrintable(d.warnings.join('|')));
        ctx.dissect(on(0, 0x585, {0x43, 0x08, 0x10, 0x00, 0x41, 0x42, 0x43, 0x44}), d);
        QVERIFY2(d.warnings.isEmpty(), qPrintable(d.warnings.join('|')));
        QVERIFY(d.hasTransfer);
        QCOMPARE(d.transfer.index, 0x1008);
    }

    void userDictionaryOnEveryBus() {
        NetworkContext ctx;
        QString error;
        QVERIFY(ctx.assignDictionary(5, QStringLiteral("aimotor"), &error));
        Dissection d;
        ctx.dissect(on(3, 0x705, {0x05}), d);  // a bus first seen after the assignment
        QCOMPARE(ctx.node(3, 5).dictionaryName, QStringLiteral("aimotor"));
        QCOMPARE(ctx.node(0, 5).dictionaryName, QStringLiteral("aimotor"));
        QCOMPARE(ctx.node(2, 5).dictionaryName, QStringLiteral("aimotor"));  // unseen: the defaults
    }
};

QTEST_GUILESS_MAIN(DissectPerBus)
#include "test_dissect_per_bus.moc"
