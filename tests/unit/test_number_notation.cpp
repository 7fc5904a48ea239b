// SPDX-License-Identifier: GPL-3.0-or-later
// One rule for numbers (core/od/NumberNotation.h): COB-IDs, PDO mapping entries and
// control/statuswords in CiA 301 hex wherever they are written, with values from CiA 301/402.
#include "core/can/CanFrame.h"
#include "core/canopen/CommandScript.h"
#include "core/od/NumberNotation.h"
#include "dissectors/NetworkContext.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::od;

namespace {
QString sdoSummary(dissect::NetworkContext& ctx, uint32_t id, std::initializer_list<uint8_t> bytes) {
    dissect::Dissection d;
    ctx.dissect(CanFrame::classic(id, bytes), d);
    return d.summary;
}
canopen::ScriptStep write(uint16_t index, uint8_t sub, QByteArray data) {
    canopen::ScriptStep s;
    s.kind = canopen::ScriptStep::Kind::SdoWrite;
    s.node = 2;
    s.index = index;
    s.sub = sub;
    s.data = std::move(data);
    return s;
}
}  // namespace

class TestNumberNotation : public QObject {
    Q_OBJECT
private slots:
    void ruleByObject() {
        // CiA 301 §7.3.5 pre-defined connection set: TPDO1 of node 2 = 180h + 2.
        QCOMPARE(hexValueText(0x1800, 1, 0x182, 32), QStringLiteral("182h"));
        QCOMPARE(hexValueText(0x1400, 1, 0x202, 32), QStringLiteral("202h"));
        QCOMPARE(hexValueText(0x1005, 0, 0x80, 32), QStringLiteral("080h"));              // SYNC
        QCOMPARE(hexValueText(0x1200, 2, 0x582, 32), QStringLiteral("582h"));             // SDO server -> client
        QCOMPARE(hexValueText(0x1801, 1, 0x80000282u, 32), QStringLiteral("80000282h"));  // bit 31: PDO not valid
        QCOMPARE(hexValueText(0x1800, 1, 0x20000182u, 32), QStringLiteral("20000182h"));  // 29-bit CAN-ID
        // CiA 301 §7.5.2.36: statusword 6041h:00, 16 bits -> 60410010h.
        QCOMPARE(hexValueText(0x1A00, 1, 0x60410010u, 32), QStringLiteral("60410010h"));
        QCOMPARE(hexValueText(0x1600, 0x40, 0x60400010u, 32), QStringLiteral("60400010h"));
        QCOMPARE(hexValueText(0x1A00, 0, 2, 8), QString());  // sub 0 is the number of entries
        // CiA 402: controlword "Shutdown" 0006h, statusword "Switched on" 0633h (any axis).
        QCOMPARE(hexValueText(0x6040, 0, 6, 16), QStringLiteral("0006h"));
        QCOMPARE(hexValueText(0x6041, 0, 0x650, 16), QStringLiteral("0650h"));
        QCOMPARE(hexValueText(0x6841, 0, 0x633, 16), QStringLiteral("0633h"));
        QCOMPARE(hexValueText(0x1018, 1, 0x1DD, 32), QStringLiteral("000001DDh"));
        QCOMPARE(hexValueText(0x1010, 1, 0x65766173u, 32), QStringLiteral("65766173h"));
        // Quantities stay decimal.
        QCOMPARE(hexValueText(0x1017, 0, 1000, 16), QString());
        QCOMPARE(hexValueText(0x1800, 5, 100, 16), QString());  // event timer
        QCOMPARE(hexValueText(0x6060, 0, 1, 8), QString());
        QCOMPARE(hexValueText(0x607A, 0, 1000, 32), QString());
        QCOMPARE(hexValueText(0x2000, 0, 1, 16), QString());
    }

    void valueTextWithoutType() {
        QCOMPARE(valueText(0x1A00, 1, 0x60410010u, 32), QStringLiteral("60410010h"));
        QCOMPARE(valueText(0x1017, 0, 1000, 16), QStringLiteral("1000"));
        QCOMPARE(valueText(0x607A, 0, 0xFFFFFF9Cu, 32), QStringLiteral("-100 (FFFFFF9Ch)"));
        QCOMPARE(objectText(0x1A00, 1), QStringLiteral("1A00h:01"));
        QCOMPARE(hexText(0x650, 4), QStringLiteral("0650h"));
        // PDO transmission types 254/255 by name, never "-1 (FFh)" (CiA 301 §7.2.2.2).
        QCOMPARE(valueText(0x1800, 2, 0xFF, 8), QStringLiteral("FFh (event)"));
        QCOMPARE(valueText(0x1401, 2, 0xFE, 8), QStringLiteral("FEh (event, manufacturer)"));
        QCOMPARE(valueText(0x2000, 2, 0xFF, 8), QStringLiteral("-1 (FFh)"));  // not a transmission type: no name
        QCOMPARE(valueText(0x1800, 2, 1, 8), QStringLiteral("1"));
        QCOMPARE(transmissionTypeText(240), QStringLiteral("240"));
    }

    // The trace and the wizards' frames panes: SDO summaries decoded by the dissectors.
    void sdoSummaries() {
        dissect::NetworkContext ctx;
        // Write 1A00h:01 = 60410010h to node 2 (expedited, 4 bytes: 23h).
        QString s = sdoSummary(ctx, 0x602, {0x23, 0x00, 0x1A, 0x01, 0x10, 0x00, 0x41, 0x60});
        QVERIFY2(s.contains(QStringLiteral("= 60410010h")), qPrintable(s));
        // Write 1800h:01 = 182h.
        s = sdoSummary(ctx, 0x602, {0x23, 0x00, 0x18, 0x01, 0x82, 0x01, 0x00, 0x00});
        QVERIFY2(s.contains(QStringLiteral("= 182h")), qPrintable(s));
        // Read 6041h:00 answered with 0650h (2 bytes: 4Bh).
        s = sdoSummary(ctx, 0x582, {0x4B, 0x41, 0x60, 0x00, 0x50, 0x06, 0x00, 0x00});
        QVERIFY2(s.contains(QStringLiteral("= 0650h")), qPrintable(s));
        // Producer heartbeat time stays decimal.
        s = sdoSummary(ctx, 0x602, {0x2B, 0x17, 0x10, 0x00, 0xE8, 0x03, 0x00, 0x00});
        QVERIFY2(s.contains(QStringLiteral("= 1000")), qPrintable(s));
        // Write 1800h:02 = 255: the transmission type by name.
        s = sdoSummary(ctx, 0x602, {0x2F, 0x00, 0x18, 0x02, 0xFF, 0x00, 0x00, 0x00});
        QVERIFY2(s.contains(QStringLiteral("= FFh (event)")), qPrintable(s));
    }

    // Step tables: what a step does, in the same notation.
    void scriptSteps() {
        QCOMPARE(write(0x1A00, 1, QByteArray::fromHex("10004160")).describe(),
                 QStringLiteral("Write 1A00h:01 = 60410010h on node 2"));
        QCOMPARE(write(0x1800, 1, QByteArray::fromHex("82010080")).describe(),
                 QStringLiteral("Write 1800h:01 = 80000182h on node 2"));
        QCOMPARE(write(0x6040, 0, QByteArray::fromHex("0600")).describe(),
                 QStringLiteral("Write 6040h:00 = 0006h on node 2"));
        QCOMPARE(write(0x1017, 0, QByteArray::fromHex("e803")).describe(),
                 QStringLiteral("Write 1017h:00 = 1000 on node 2"));
        QCOMPARE(write(0x1A00, 0, QByteArray::fromHex("02")).describe(),
                 QStringLiteral("Write 1A00h:00 = 2 on node 2"));
        QCOMPARE(write(0x1800, 2, QByteArray::fromHex("ff")).describe(),
                 QStringLiteral("Write 1800h:02 = FFh (event) on node 2"));
    }
};

QTEST_GUILESS_MAIN(TestNumberNotation)
#include "test_number_notation.moc"
