// SPDX-License-Identifier: GPL-3.0-or-later
// Raw signals (dissectors/RawSignal.h): bits of a payload by the DBC conventions, values worked
// out by hand from the bytes.
#include "dissectors/DecodeOutput.h"
#include "dissectors/RawSignal.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

using namespace coscope;
using namespace coscope::dissect;

namespace {
RawSignal sig(int start, int len, RawSignal::Type t, RawSignal::Order o = RawSignal::Order::Intel) {
    RawSignal s;
    s.name = QStringLiteral("x");
    s.cobId = 0x181;
    s.startBit = start;
    s.length = len;
    s.type = t;
    s.order = o;
    return s;
}
double raw(const RawSignal& s, std::initializer_list<uint8_t> bytes) {
    const std::vector<uint8_t> b(bytes);
    return s.rawValue(b.data(), static_cast<int>(b.size())).value_or(-12345.0);
}
using T = RawSignal::Type;
using O = RawSignal::Order;
}  // namespace

class RawSignalTest : public QObject {
    Q_OBJECT
private slots:
    void intel() {
        QCOMPARE(raw(sig(0, 16, T::Unsigned), {0x34, 0x12}), 4660.0);  // 1234h
        QCOMPARE(raw(sig(16, 8, T::Unsigned), {0, 0, 0xC8}), 200.0);
        // bits 4..15 of 30 FE = FE3h, 12-bit two's complement = -29
        QCOMPARE(raw(sig(4, 12, T::Signed), {0x30, 0xFE}), -29.0);
        QCOMPARE(raw(sig(0, 16, T::Signed), {0x38, 0xFF}), -200.0);  // FF38h
        QCOMPARE(raw(sig(3, 1, T::Unsigned), {0x08}), 1.0);
        QCOMPARE(raw(sig(0, 64, T::Signed), {0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF}), -1.0);
    }
    void motorola() {
        // DBC start bit 7 = MSB in bit 7 of byte 0; 7..0 then 15..8: 12 34 -> 1234h
        QCOMPARE(raw(sig(7, 16, T::Unsigned, O::Motorola), {0x12, 0x34}), 4660.0);
        // start bit 3: bits 3..0 of byte 0 (Ah) then 15..12 (Bh) -> ABh
        QCOMPARE(raw(sig(3, 8, T::Unsigned, O::Motorola), {0x0A, 0xB0}), 171.0);
        QCOMPARE(raw(sig(7, 16, T::Signed, O::Motorola), {0xFF, 0x38}), -200.0);
        // 12 bits from bit 11 (byte 1 bit 3): bits 11..8 of 0F = Fh, then 23..16 = E0h -> FE0h = -32
        QCOMPARE(raw(sig(11, 12, T::Signed, O::Motorola), {0x00, 0x0F, 0xE0}), -32.0);
        QCOMPARE(sig(7, 16, T::Unsigned, O::Motorola).bytesNeeded(), 2);
        QCOMPARE(sig(3, 8, T::Unsigned, O::Motorola).bytesNeeded(), 2);
    }
    void floats() {
        QCOMPARE(raw(sig(0, 32, T::Float), {0x00, 0x00, 0xC0, 0x3F}), 1.5);  // 3FC00000h
        QCOMPARE(raw(sig(7, 32, T::Float, O::Motorola), {0x3F, 0xC0, 0x00, 0x00}), 1.5);
        QCOMPARE(raw(sig(0, 64, T::Float), {0, 0, 0, 0, 0, 0, 0x02, 0xC0}), -2.25);  // C002000000000000h
        QVERIFY(!sig(0, 16, T::Float).problem().isEmpty());
    }
    void scaleAndShortPayload() {
        RawSignal s = sig(0, 8, T::Unsigned);
        s.factor = 0.5;
        s.offset = -40;
        const uint8_t b[] = {100};
        QCOMPARE(s.value(b, 1).value(), 10.0);
        QVERIFY(!sig(8, 8, T::Unsigned).rawValue(b, 1));
        QVERIFY(!sig(7, 16, T::Unsigned, O::Motorola).rawValue(b, 1));
    }
    void parse() {
        QString error;
        auto s = RawSignal::parse(QStringLiteral("speed=0x181:16:16:s:0.1:0:rpm"), &error);
        QVERIFY2(s, qPrintable(error));
        QCOMPARE(s->name, QStringLiteral("speed"));
        QCOMPARE(s->cobId, 0x181u);
        QVERIFY(!s->extended);
        QCOMPARE(s->startBit, 16);
        QCOMPARE(s->length, 16);
        QCOMPARE(s->type, T::Signed);
        QCOMPARE(s->order, O::Intel);
        QCOMPARE(s->factor, 0.1);
        QCOMPARE(s->unit, QStringLiteral("rpm"));
        s = RawSignal::parse(QStringLiteral("temp=641:7:16:u@0:0.5:-40"), &error);
        QVERIFY2(s, qPrintable(error));
        QCOMPARE(s->cobId, 641u);
        QCOMPARE(s->order, O::Motorola);
        QCOMPARE(s->offset, -40.0);
        QCOMPARE(RawSignal::parse(s->spec()).value(), *s);
        s = RawSignal::parse(QStringLiteral("ext=0x18FF0001:0:32:f"), &error);
        QVERIFY2(s && s->extended, qPrintable(error));
        QCOMPARE(RawSignal::parse(s->spec()).value(), *s);
        for (const char* bad : {"x=0x181:0:33:f", "x=0x181:0:8:q", "=0x181:0:8:u", "x=0x181:0:8", "x=zz:0:8:u",
                                "x=0x181:0:0:u", "x=0x181:0:8:u:0"})
            QVERIFY2(!RawSignal::parse(QString::fromLatin1(bad), &error), bad);
        QVERIFY(error.contains(QStringLiteral("factor")));
    }
    void inDissectionJson() {
        RawSignal s = *RawSignal::parse(QStringLiteral("speed=0x181:0:16:s:0.5:0:rpm"));
        const CanFrame f = CanFrame::classic(0x181, {0x38, 0xFF, 0x01});
        Dissection d;
        d.summary = QStringLiteral("TPDO1 node 1: 38 FF 01");
        applyRawSignals({s, *RawSignal::parse(QStringLiteral("other=0x182:0:8:u"))}, f, d);
        QCOMPARE(d.signalCount, 1);
        QCOMPARE(d.summary, QStringLiteral("TPDO1 node 1: 38 FF 01  | speed = -100 rpm"));
        QByteArray line;
        appendJson(line, f, d, QStringLiteral("can0"));
        const QJsonArray a = QJsonDocument::fromJson(line)
                                 .object()
                                 .value(QStringLiteral("fields"))
                                 .toObject()
                                 .value(QStringLiteral("pdo.signals"))
                                 .toArray();
        QCOMPARE(a.size(), 1);
        const QJsonObject o = a[0].toObject();
        QVERIFY(o.contains(QStringLiteral("obj")) && o.value(QStringLiteral("obj")).isNull());
        QCOMPARE(o.value(QStringLiteral("name")).toString(), QStringLiteral("speed"));
        QCOMPARE(o.value(QStringLiteral("value")).toDouble(), -100.0);
        QCOMPARE(o.value(QStringLiteral("unit")).toString(), QStringLiteral("rpm"));
    }
};

QTEST_GUILESS_MAIN(RawSignalTest)
#include "test_raw_signal.moc"
