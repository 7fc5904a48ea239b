// SPDX-License-Identifier: GPL-3.0-or-later
// Which RPDO a frame is aimed at, and whether its mapping carries a motion object: the transmit
// panel asks before such a frame goes out (issue 35). Expectations from the manuals' default
// mappings (extract-aimotor §2 object table: RPDO1 = 6040h, 6060h, 607Ah at 200h + node; RPDO2 =
// 60FFh, 6071h at 300h + node; RPDO3/4 unmapped) and CiA 301 §7.3.5 (pre-defined connection set).
#include "core/canopen/RpdoMotion.h"
#include "eds/DictionaryLibrary.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::canopen;

class TestRpdoMotion : public QObject {
    Q_OBJECT
    eds::DictionaryPtr aimotor_;

    std::optional<RpdoAddress> aimed(uint32_t id, bool extended = false, int driveWithoutDictionary = 0) {
        CanFrame f;
        f.id = id;
        if (extended) f.flags |= CanFrame::Extended;
        f.len = 8;
        return rpdoAddressed(
            f, [&](uint8_t node) { return node == 2 ? aimotor_.get() : nullptr; },
            [&](uint8_t node) { return node == driveWithoutDictionary; });
    }

private slots:
    void initTestCase() {
        QString error;
        aimotor_ = eds::DictionaryLibrary::shared().loadShared(QStringLiteral("aimotor"), nullptr, &error);
        QVERIFY2(aimotor_, qPrintable(error));
    }

    void motionObjectsOnEveryAxis() {
        for (uint16_t i : {0x6040, 0x607A, 0x60FF, 0x6071, 0x60C1, 0x6060, 0x6042, 0x60FE}) {
            QVERIFY2(isMotionObject(i), qPrintable(QString::number(i, 16)));
            QVERIFY(isMotionObject(static_cast<uint16_t>(i + 0x800)));  // axis 1 (CiA 402-2 §5.2)
        }
        for (uint16_t i : {0x6041, 0x6064, 0x606C, 0x1017, 0x2002, 0x6061, 0x6098})
            QVERIFY2(!isMotionObject(i), qPrintable(QString::number(i, 16)));
    }

    void defaultRpdosOfTheAimotor() {
        const auto r1 = aimed(0x202);
        QVERIFY(r1);
        QCOMPARE(r1->node, uint8_t(2));
        QCOMPARE(r1->number, 1);
        QVERIFY(r1->mappingKnown);
        QCOMPARE(r1->motion.size(), size_t(3));  // 6040h, 6060h, 607Ah
        QCOMPARE(r1->motion[0].encode(), 0x60400010u);
        QCOMPARE(r1->motion[2].encode(), 0x607A0020u);
        QVERIFY(r1->carriesMotion());

        const auto r2 = aimed(0x302);
        QVERIFY(r2);
        QCOMPARE(r2->number, 2);
        QCOMPARE(r2->motion.size(), size_t(2));  // 60FFh, 6071h

        const auto r3 = aimed(0x402);  // mapped to nothing by default: no motion
        QVERIFY(r3);
        QCOMPARE(r3->number, 3);
        QVERIFY(r3->mappingKnown);
        QVERIFY(!r3->carriesMotion());
    }

    void notAnRpdo() {
        QVERIFY(!aimed(0x182));        // TPDO1 of node 2
        QVERIFY(!aimed(0x602));        // SDO request
        QVERIFY(!aimed(0x202, true));  // a 29-bit identifier is another frame
        QVERIFY(!aimed(0x203));        // node 3: no dictionary, not known as a drive
    }

    void driveWithoutDictionaryByDefaultCobIds() {
        const auto r = aimed(0x405, false, 5);
        QVERIFY(r);
        QCOMPARE(r->node, uint8_t(5));
        QCOMPARE(r->number, 3);
        QVERIFY(!r->mappingKnown);
        QVERIFY(r->carriesMotion());  // unknown mapping of a drive: ask
    }
};

QTEST_GUILESS_MAIN(TestRpdoMotion)
#include "test_rpdo_motion.moc"
