// SPDX-License-Identifier: GPL-3.0-or-later
// od::Value: encode/decode of every CiA 301 basic type, parsing what people type, display.
#include "core/od/Value.h"

#include <QTest>

#include <cmath>

using namespace coscope::od;

class TestOdValue : public QObject {
    Q_OBJECT
private slots:
    void roundTripEveryType_data();
    void roundTripEveryType();
    void littleEndian();
    void decodeWrongSize();
    void parseIntegers();
    void parseErrorsSayWhy();
    void parseLimits();
    void parseRealBitPattern();
    void parseStringsAndBytes();
    void formatHexAndUnits();
    void timeOfDay();
    void dataTypeNames();
};

void TestOdValue::roundTripEveryType_data() {
    QTest::addColumn<int>("type");
    QTest::addColumn<QString>("text");
    QTest::addColumn<int>("size");
    QTest::newRow("BOOLEAN") << int(DataType::Boolean) << "true" << 1;
    QTest::newRow("INTEGER8") << int(DataType::Integer8) << "-128" << 1;
    QTest::newRow("INTEGER16") << int(DataType::Integer16) << "-12345" << 2;
    QTest::newRow("INTEGER24") << int(DataType::Integer24) << "-8388608" << 3;
    QTest::newRow("INTEGER32") << int(DataType::Integer32) << "-2147483648" << 4;
    QTest::newRow("INTEGER40") << int(DataType::Integer40) << "-549755813888" << 5;
    QTest::newRow("INTEGER48") << int(DataType::Integer48) << "140737488355327" << 6;
    QTest::newRow("INTEGER56") << int(DataType::Integer56) << "-36028797018963968" << 7;
    QTest::newRow("INTEGER64") << int(DataType::Integer64) << "-9223372036854775808" << 8;
    QTest::newRow("UNSIGNED8") << int(DataType::Unsigned8) << "255" << 1;
    QTest::newRow("UNSIGNED16") << int(DataType::Unsigned16) << "65535" << 2;
    QTest::newRow("UNSIGNED24") << int(DataType::Unsigned24) << "16777215" << 3;
    QTest::newRow("UNSIGNED32") << int(DataType::Unsigned32) << "4294967295" << 4;
    QTest::newRow("UNSIGNED40") << int(DataType::Unsigned40) << "1099511627775" << 5;
    QTest::newRow("UNSIGNED48") << int(DataType::Unsigned48) << "281474976710655" << 6;
    QTest::newRow("UNSIGNED56") << int(DataType::Unsigned56) << "72057594037927935" << 7;
    QTest::newRow("UNSIGNED64") << int(DataType::Unsigned64) << "18446744073709551615" << 8;
    QTest::newRow("REAL32") << int(DataType::Real32) << "1.5" << 4;
    QTest::newRow("REAL64") << int(DataType::Real64) << "-0.1" << 8;
    QTest::newRow("VISIBLE_STRING") << int(DataType::VisibleString) << "Drive 1" << 7;
    QTest::newRow("OCTET_STRING") << int(DataType::OctetString) << "01 02 FF" << 3;
    QTest::newRow("UNICODE_STRING") << int(DataType::UnicodeString) << "Ωm" << 4;
    QTest::newRow("DOMAIN") << int(DataType::Domain) << "DE AD BE EF 00" << 5;
    QTest::newRow("TIME_OF_DAY") << int(DataType::TimeOfDay) << "12345d 1000ms" << 6;
    QTest::newRow("TIME_DIFFERENCE") << int(DataType::TimeDifference) << "1d 5ms" << 6;
}

void TestOdValue::roundTripEveryType() {
    QFETCH(int, type);
    QFETCH(QString, text);
    QFETCH(int, size);
    const auto t = static_cast<DataType>(type);
    const ValueResult parsed = Value::parse(t, text);
    QVERIFY2(parsed.ok(), qPrintable(parsed.error));
    QString err;
    const QByteArray bytes = parsed.value.encode(t, &err);
    QVERIFY2(err.isEmpty(), qPrintable(err));
    QCOMPARE(bytes.size(), size);
    const ValueResult decoded = Value::decode(t, bytes);
    QVERIFY2(decoded.ok(), qPrintable(decoded.error));
    QCOMPARE(decoded.value, parsed.value);
    // Display text reads back to the same value.
    const QString shown = Value::format(t, decoded.value);
    const ValueResult again = Value::parse(t, shown);
    QVERIFY2(again.ok(), qPrintable(again.error + " for " + shown));
    QCOMPARE(again.value, parsed.value);
}

void TestOdValue::littleEndian() {
    QCOMPARE(Value::unsignedInt(0x12345678).encode(DataType::Unsigned32), QByteArray::fromHex("78563412"));
    QCOMPARE(Value::signedInt(-2).encode(DataType::Integer24), QByteArray::fromHex("feffff"));
    QCOMPARE(Value::decode(DataType::Integer16, QByteArray::fromHex("00 80")).value, Value::signedInt(-32768));
    QCOMPARE(Value::real(1.5).encode(DataType::Real32), QByteArray::fromHex("0000c03f"));
}

void TestOdValue::decodeWrongSize() {
    const ValueResult r = Value::decode(DataType::Unsigned16, QByteArray::fromHex("01"));
    QVERIFY(!r.ok());
    QVERIFY2(r.error.contains("2 bytes") && r.error.contains("got 1"), qPrintable(r.error));
    QVERIFY(!Value::decode(DataType::UnicodeString, QByteArray("abc")).ok());
    QVERIFY(!Value::decode(DataType::Boolean, QByteArray::fromHex("02")).ok());
    QString err;
    QVERIFY(Value::unsignedInt(256).encode(DataType::Unsigned8, &err).isEmpty());
    QVERIFY(err.contains("UNSIGNED8"));
}

void TestOdValue::parseIntegers() {
    QCOMPARE(Value::parse(DataType::Unsigned8, "0x1F").value, Value::unsignedInt(31));
    QCOMPARE(Value::parse(DataType::Integer8, "-5").value, Value::signedInt(-5));
    QCOMPARE(Value::parse(DataType::Integer8, "0xFF").value, Value::signedInt(-1));  // bit pattern
    QCOMPARE(Value::parse(DataType::Unsigned16, "0b101").value, Value::unsignedInt(5));
    QCOMPARE(Value::parse(DataType::Unsigned16, "010").value, Value::unsignedInt(10));  // people: decimal
    QCOMPARE(Value::parse(DataType::Unsigned16, "010", Limits{}, TextStyle::Eds).value,
             Value::unsignedInt(8));  // CiA 306: octal
    QCOMPARE(Value::parse(DataType::Unsigned16, "0099", Limits{}, TextStyle::Eds).value, Value::unsignedInt(99));
    QCOMPARE(Value::parse(DataType::Boolean, "false").value, Value::boolean(false));
    QCOMPARE(Value::parse(DataType::Integer64, " -9223372036854775808 ").value, Value::signedInt(INT64_MIN));
}

void TestOdValue::parseErrorsSayWhy() {
    ValueResult r = Value::parse(DataType::Unsigned8, "256");
    QVERIFY(!r.ok());
    QVERIFY2(r.error.contains("UNSIGNED8") && r.error.contains("0..255"), qPrintable(r.error));
    r = Value::parse(DataType::Unsigned16, "-1");
    QVERIFY(!r.ok());
    r = Value::parse(DataType::Integer8, "-129");
    QVERIFY(r.error.contains("-128..127"));
    r = Value::parse(DataType::Unsigned32, "twelve");
    QVERIFY2(r.error.contains("not a number"), qPrintable(r.error));
    QVERIFY(!Value::parse(DataType::Boolean, "maybe").ok());
    QVERIFY(!Value::parse(DataType::OctetString, "0G").ok());
    QVERIFY(!Value::parse(DataType::Real32, "1e50").ok());
    QVERIFY(!Value::parse(DataType::Unsigned64, "18446744073709551616").ok());
}

void TestOdValue::parseLimits() {
    Limits l;
    l.low = Value::signedInt(-10);
    l.high = Value::signedInt(100);
    QVERIFY(Value::parse(DataType::Integer16, "100", l).ok());
    ValueResult r = Value::parse(DataType::Integer16, "101", l);
    QVERIFY(!r.ok());
    QVERIFY2(r.error.contains("HighLimit 100"), qPrintable(r.error));
    r = Value::parse(DataType::Integer16, "-11", l);
    QVERIFY2(r.error.contains("LowLimit -10"), qPrintable(r.error));
}

void TestOdValue::parseRealBitPattern() {
    QCOMPARE(Value::parse(DataType::Real32, "0x3FC00000").value, Value::real(1.5));
    QCOMPARE(Value::parse(DataType::Real64, "0x4000000000000000").value, Value::real(2.0));
    QCOMPARE(Value::parse(DataType::Real32, "-2.5e1").value, Value::real(-25.0));
}

void TestOdValue::parseStringsAndBytes() {
    QCOMPARE(Value::parse(DataType::VisibleString, "\"say \\\"hi\\\"\"").value, Value::text("say \"hi\""));
    QCOMPARE(Value::parse(DataType::VisibleString, "plain text").value, Value::text("plain text"));
    QCOMPARE(Value::parse(DataType::OctetString, "0x0102").value, Value::bytes(QByteArray::fromHex("0102")));
    QCOMPARE(Value::parse(DataType::Domain, "\"AB\"").value, Value::bytes("AB"));
    QCOMPARE(Value::parse(DataType::OctetString, "01:02:ff").value, Value::bytes(QByteArray::fromHex("0102ff")));
    // VISIBLE_STRING on the wire: trailing NULs dropped, UTF-8 when valid.
    QCOMPARE(Value::decode(DataType::VisibleString, QByteArray("abc\0\0", 5)).value, Value::text("abc"));
    QCOMPARE(Value::decode(DataType::VisibleString, QByteArray("\xe2\x82\xac")).value,
             Value::text(QString(QChar(0x20AC))));
}

void TestOdValue::formatHexAndUnits() {
    FormatOptions hex;
    hex.hex = true;
    QCOMPARE(Value::format(DataType::Unsigned16, Value::unsignedInt(0x1F), hex), QString("0x001F"));
    QCOMPARE(Value::format(DataType::Integer8, Value::signedInt(-1), hex), QString("0xFF"));
    FormatOptions unit;
    unit.unit = "rpm";
    QCOMPARE(Value::format(DataType::Integer32, Value::signedInt(-1500), unit), QString("-1500 rpm"));
    unit.unit = "mm";
    unit.factor = 0.001;
    QCOMPARE(Value::format(DataType::Integer32, Value::signedInt(12500), unit), QString("12.5 mm"));
    QCOMPARE(Value::format(DataType::Real32, Value::real(0.1f)), QString("0.1"));
    QCOMPARE(Value::format(DataType::OctetString, Value::bytes(QByteArray::fromHex("0aff"))), QString("0A FF"));
}

void TestOdValue::timeOfDay() {
    // CiA 301 7.1.6.5: 28 bits ms after midnight, 4 reserved, 16 bits days since 1984-01-01.
    const Value v = Value::timeOfDay(1000, 2);
    QCOMPARE(v.encode(DataType::TimeOfDay), QByteArray::fromHex("e8030000 0200"));
    QCOMPARE(Value::format(DataType::TimeOfDay, v), QString("2d 1000ms"));
    QVERIFY(!Value::parse(DataType::TimeOfDay, "70000:1").ok());
}

void TestOdValue::dataTypeNames() {
    QCOMPARE(dataTypeName(DataType::Unsigned16), QString("UNSIGNED16"));
    QCOMPARE(dataTypeName(static_cast<DataType>(0x0040)), QString("DATATYPE_0040"));
    QCOMPARE(dataTypeFromString("integer24"), std::optional<DataType>(DataType::Integer24));
    QCOMPARE(dataTypeFromString("0x001B"), std::optional<DataType>(DataType::Unsigned64));
    QCOMPARE(bitSize(DataType::Unsigned56), 56);
    QCOMPARE(byteSize(DataType::TimeDifference), 6);
}

QTEST_GUILESS_MAIN(TestOdValue)
#include "test_od_value.moc"
