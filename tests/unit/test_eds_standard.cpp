// SPDX-License-Identifier: GPL-3.0-or-later
// The standard objects (eds::standardDictionary): types and names as CiA 301 v4.2 section 7.5
// and CiA 402-2 give them, and a device's own entry winning over the standard one.
#include "eds/DictionaryLibrary.h"
#include "eds/StandardDictionary.h"

#include <QtTest>

using coscope::od::DataType;

class TestEdsStandard : public QObject {
    Q_OBJECT
private slots:
    void types_data() {
        QTest::addColumn<int>("index");
        QTest::addColumn<int>("sub");
        QTest::addColumn<int>("type");
        // CiA 301 7.5.2
        QTest::newRow("1000 device type") << 0x1000 << 0 << int(DataType::Unsigned32);
        QTest::newRow("1001 error register") << 0x1001 << 0 << int(DataType::Unsigned8);
        QTest::newRow("1002 status register") << 0x1002 << 0 << int(DataType::Unsigned32);
        QTest::newRow("1008 device name") << 0x1008 << 0 << int(DataType::VisibleString);
        QTest::newRow("1009 hardware version") << 0x1009 << 0 << int(DataType::VisibleString);
        QTest::newRow("100A software version") << 0x100A << 0 << int(DataType::VisibleString);
        QTest::newRow("100C guard time") << 0x100C << 0 << int(DataType::Unsigned16);
        QTest::newRow("100D life time factor") << 0x100D << 0 << int(DataType::Unsigned8);
        QTest::newRow("1012 COB-ID TIME") << 0x1012 << 0 << int(DataType::Unsigned32);
        QTest::newRow("1015 inhibit time EMCY") << 0x1015 << 0 << int(DataType::Unsigned16);
        QTest::newRow("1016:01 consumer heartbeat") << 0x1016 << 1 << int(DataType::Unsigned32);
        QTest::newRow("1017 producer heartbeat") << 0x1017 << 0 << int(DataType::Unsigned16);
        QTest::newRow("1018:04 serial number") << 0x1018 << 4 << int(DataType::Unsigned32);
        QTest::newRow("1019 sync overflow") << 0x1019 << 0 << int(DataType::Unsigned8);
        QTest::newRow("1021 store EDS") << 0x1021 << 0 << int(DataType::Domain);
        QTest::newRow("1027:01 module list") << 0x1027 << 1 << int(DataType::Unsigned16);
        QTest::newRow("1028:7F emergency consumer") << 0x1028 << 0x7F << int(DataType::Unsigned32);
        QTest::newRow("1029:01 error behaviour") << 0x1029 << 1 << int(DataType::Unsigned8);
        QTest::newRow("1201:03 SDO server client node") << 0x1201 << 3 << int(DataType::Unsigned8);
        QTest::newRow("1280:01 SDO client COB-ID") << 0x1280 << 1 << int(DataType::Unsigned32);
        QTest::newRow("15FF:05 RPDO512 event timer") << 0x15FF << 5 << int(DataType::Unsigned16);
        QTest::newRow("1804:03 TPDO5 inhibit") << 0x1804 << 3 << int(DataType::Unsigned16);
        QTest::newRow("1804:06 TPDO5 SYNC start") << 0x1804 << 6 << int(DataType::Unsigned8);
        QTest::newRow("1A00:40 TPDO1 mapping 64") << 0x1A00 << 0x40 << int(DataType::Unsigned32);
        QTest::newRow("1BFF:00 TPDO512 mapping count") << 0x1BFF << 0 << int(DataType::Unsigned8);
        // CiA 402-2
        QTest::newRow("6040 controlword") << 0x6040 << 0 << int(DataType::Unsigned16);
        QTest::newRow("6041 statusword") << 0x6041 << 0 << int(DataType::Unsigned16);
        QTest::newRow("6060 modes of operation") << 0x6060 << 0 << int(DataType::Integer8);
        QTest::newRow("6061 modes display") << 0x6061 << 0 << int(DataType::Integer8);
        QTest::newRow("6064 position actual") << 0x6064 << 0 << int(DataType::Integer32);
        QTest::newRow("606C velocity actual") << 0x606C << 0 << int(DataType::Integer32);
        QTest::newRow("607A target position") << 0x607A << 0 << int(DataType::Integer32);
        QTest::newRow("6081 profile velocity") << 0x6081 << 0 << int(DataType::Unsigned32);
        QTest::newRow("6083 profile acceleration") << 0x6083 << 0 << int(DataType::Unsigned32);
        QTest::newRow("6084 profile deceleration") << 0x6084 << 0 << int(DataType::Unsigned32);
        QTest::newRow("6098 homing method") << 0x6098 << 0 << int(DataType::Integer8);
        QTest::newRow("60FF target velocity") << 0x60FF << 0 << int(DataType::Integer32);
    }
    void types() {
        QFETCH(int, index);
        QFETCH(int, sub);
        QFETCH(int, type);
        const auto* e =
            coscope::eds::standardDictionary().entry(static_cast<uint16_t>(index), static_cast<uint8_t>(sub));
        QVERIFY(e);
        QCOMPARE(int(e->dataType), type);
    }

    void names() {
        const auto& d = coscope::eds::standardDictionary();
        QCOMPARE(d.displayName(0x1008, 0), QStringLiteral("Manufacturer device name"));
        QCOMPARE(d.displayName(0x1017, 0), QStringLiteral("Producer heartbeat time"));
        QVERIFY2(d.displayName(0x1805, 1).startsWith(QStringLiteral("TPDO6 communication parameter")),
                 qPrintable(d.displayName(0x1805, 1)));
        QVERIFY(d.displayName(0x1805, 1).contains(QStringLiteral("COB-ID used by TPDO")));
        QVERIFY(!d.entry(0x1C00, 0));
        QVERIFY(!d.entry(0x2000, 0));  // manufacturer objects are not standard
    }

    void deviceEntryWins() {
        const auto aimotor = coscope::eds::DictionaryLibrary().load(QStringLiteral("aimotor"));
        QVERIFY(aimotor.usable);
        const coscope::od::ObjectDictionary* from = nullptr;
        const auto* e = coscope::eds::entryWithStandard(&aimotor.dictionary, 0x1017, 0, &from);
        QVERIFY(e);
        QCOMPARE(e->dataType, DataType::Unsigned32);  // the AIMOTOR EDS, not CiA 301's UNSIGNED16
        QCOMPARE(from, &aimotor.dictionary);
        // An object the EDS leaves out comes from the standard.
        e = coscope::eds::entryWithStandard(&aimotor.dictionary, 0x1008, 0, &from);
        QVERIFY(e);
        QCOMPARE(e->dataType, DataType::VisibleString);
        QCOMPARE(from, &coscope::eds::standardDictionary());
        QVERIFY(!coscope::eds::entryWithStandard(nullptr, 0x2FF0, 1));
    }
};

QTEST_GUILESS_MAIN(TestEdsStandard)
#include "test_eds_standard.moc"
