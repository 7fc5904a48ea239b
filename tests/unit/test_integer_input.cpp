// SPDX-License-Identifier: GPL-3.0-or-later
// The one reader of the app's integer fields (core/od/IntegerInput.h, README "Numbers", issue 35):
// decimal, "-" for signed decimal, hex "0x1F"/"0X1f" and "1Fh"/"1fH", anything else refused;
// each data type's range (CiA 301 §7.1.4.4 UNSIGNEDn, §7.1.4.5 INTEGERn, two's complement for a
// hex bit pattern), overflow refused, limits narrowing it; the value shown in its object's notation.
#include "core/od/IntegerInput.h"

#include <QtTest>

using namespace coscope::od;
using Problem = IntegerInput::Problem;

Q_DECLARE_METATYPE(coscope::od::DataType)

class IntegerInputTest : public QObject {
    Q_OBJECT
private slots:
    void notations() {
        for (const char* text : {"31", "0x1F", "0X1f", "0x001F", "1Fh", "1fh", "1FH", "001Fh", " 31 ", "+31", "031"}) {
            const IntegerInput in = readInteger(DataType::Unsigned16, QString::fromLatin1(text));
            QVERIFY2(in.ok(), text);
            QCOMPARE(in.value, Value::unsignedInt(31));
        }
        QCOMPARE(readInteger(DataType::Integer32, QStringLiteral("-31")).value, Value::signedInt(-31));
        QCOMPARE(readInteger(DataType::Integer16, QStringLiteral("FFFFh")).value, Value::signedInt(-1));  // bit pattern
        QCOMPARE(readInteger(DataType::Integer8, QStringLiteral("0x80")).value, Value::signedInt(-128));
        QCOMPARE(readInteger(DataType::Unsigned8, QStringLiteral("10h")).value, Value::unsignedInt(16));
        QCOMPARE(readInteger(DataType::Unsigned8, QStringLiteral("10")).value, Value::unsignedInt(10));
    }

    void refused() {
        // Today's bug: "0x1F" became 1 in 6040h's editor. Every other notation is refused, not cut.
        for (const char* text : {"0x", "h", "0x1G", "1Gh", "1F", "0x1Fh", "0b101", "1.5", "1e3", "--5", "5-", "0x-1",
                                 "x1F", "1F h", "31 h", "twelve", "1,000"}) {
            const IntegerInput in = readInteger(DataType::Unsigned16, QString::fromLatin1(text));
            QVERIFY2(!in.ok(), text);
            QCOMPARE(in.problem, Problem::NotANumber);
        }
        QCOMPARE(readInteger(DataType::Unsigned16, QStringLiteral("  ")).problem, Problem::Empty);
    }

    void rangePerType_data() {
        QTest::addColumn<DataType>("type");
        QTest::addColumn<QString>("lowest");
        QTest::addColumn<QString>("highest");
        QTest::addColumn<QString>("below");
        QTest::addColumn<QString>("above");
        QTest::newRow("UNSIGNED8") << DataType::Unsigned8 << "0"
                                   << "255"
                                   << "-1"
                                   << "256";
        QTest::newRow("UNSIGNED16") << DataType::Unsigned16 << "0"
                                    << "65535"
                                    << "-1"
                                    << "10000h";
        QTest::newRow("UNSIGNED24") << DataType::Unsigned24 << "0"
                                    << "FFFFFFh"
                                    << "-1"
                                    << "16777216";
        QTest::newRow("UNSIGNED32") << DataType::Unsigned32 << "0"
                                    << "4294967295"
                                    << "-1"
                                    << "0x100000000";
        QTest::newRow("UNSIGNED64") << DataType::Unsigned64 << "0"
                                    << "18446744073709551615"
                                    << "-1"
                                    << "18446744073709551616";
        QTest::newRow("INTEGER8") << DataType::Integer8 << "-128"
                                  << "127"
                                  << "-129"
                                  << "128";
        QTest::newRow("INTEGER16") << DataType::Integer16 << "-32768"
                                   << "32767"
                                   << "-32769"
                                   << "32768";
        QTest::newRow("INTEGER32") << DataType::Integer32 << "-2147483648"
                                   << "2147483647"
                                   << "-2147483649"
                                   << "2147483648";
        QTest::newRow("INTEGER64") << DataType::Integer64 << "-9223372036854775808"
                                   << "9223372036854775807"
                                   << "-9223372036854775809"
                                   << "9223372036854775808";
    }
    void rangePerType() {
        QFETCH(DataType, type);
        QFETCH(QString, lowest);
        QFETCH(QString, highest);
        QFETCH(QString, below);
        QFETCH(QString, above);
        const IntegerInput lo = readInteger(type, lowest), hi = readInteger(type, highest);
        QVERIFY(lo.ok() && hi.ok());
        QCOMPARE(lo.value, lo.low);
        QCOMPARE(hi.value, hi.high);
        QCOMPARE(readInteger(type, below).problem, Problem::OutOfRange);
        QCOMPARE(readInteger(type, above).problem, Problem::OutOfRange);
        // Beyond 64 bits: refused as out of range, never wrapped.
        for (const char* huge :
             {"99999999999999999999999", "0x1FFFFFFFFFFFFFFFF", "1FFFFFFFFFFFFFFFFh", "-99999999999999999999999"})
            QCOMPARE(readInteger(type, QString::fromLatin1(huge)).problem, Problem::OutOfRange);
    }

    void limitsNarrowTheRange() {
        const Limits l{Value::signedInt(-10), Value::signedInt(100)};
        QVERIFY(readInteger(DataType::Integer16, QStringLiteral("100"), l).ok());
        const IntegerInput in = readInteger(DataType::Integer16, QStringLiteral("0x65"), l);
        QCOMPARE(in.problem, Problem::OutOfRange);
        QCOMPARE(in.low, Value::signedInt(-10));
        QCOMPARE(in.high, Value::signedInt(100));
        QCOMPARE(readInteger(DataType::Integer16, QStringLiteral("-11"), l).problem, Problem::OutOfRange);
        // A limit outside the type (an EDS mistake) does not widen it.
        const auto r = integerRange(DataType::Unsigned8, Limits{std::nullopt, Value::unsignedInt(1000)});
        QCOMPARE(r.second, Value::unsignedInt(255));
    }

    void shownInTheObjectsNotation() {
        // README "Numbers": 6040h controlword in hex padded to its size, a COB-ID as its CAN-ID,
        // everything else decimal.
        QCOMPARE(integerText(DataType::Unsigned16, Value::unsignedInt(31), hexKindFor(0x6040, 0)),
                 QStringLiteral("001Fh"));
        QCOMPARE(integerText(DataType::Unsigned32, Value::unsignedInt(0x182), hexKindFor(0x1800, 1)),
                 QStringLiteral("182h"));
        QCOMPARE(integerText(DataType::Unsigned32, Value::unsignedInt(0x80000182u), hexKindFor(0x1800, 1)),
                 QStringLiteral("80000182h"));
        QCOMPARE(integerText(DataType::Unsigned16, Value::unsignedInt(31), hexKindFor(0x1800, 5)),
                 QStringLiteral("31"));
        QCOMPARE(integerText(DataType::Integer32, Value::signedInt(-1000), hexKindFor(0x607A, 0)),
                 QStringLiteral("-1000"));
        // What is shown reads back to the same value.
        QCOMPARE(readInteger(DataType::Unsigned16, QStringLiteral("001Fh")).value, Value::unsignedInt(31));
    }
};

QTEST_GUILESS_MAIN(IntegerInputTest)
#include "test_integer_input.moc"
