// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/CanFrame.h"

#include <QtTest>

using namespace coscope;

class TestFrames : public QObject {
    Q_OBJECT
private slots:
    void parsesClassicFrame() {
        QString err;
        auto f = parseCansend(u"123#DEADBEEF", &err);
        QVERIFY2(f, qPrintable(err));
        QCOMPARE(f->id, 0x123u);
        QVERIFY(!f->isExtended());
        QCOMPARE(f->len, 4);
        QCOMPARE(f->data[0], 0xDE);
        QCOMPARE(f->data[3], 0xEF);
    }
    void parsesDotsAndExtended() {
        QString err;
        auto f = parseCansend(u"1F334455#11.22.33", &err);
        QVERIFY2(f, qPrintable(err));
        QVERIFY(f->isExtended());
        QCOMPARE(f->id, 0x1F334455u);
        QCOMPARE(f->len, 3);
        QCOMPARE(f->data[2], 0x33);
    }
    void parsesRemote() {
        QString err;
        auto f = parseCansend(u"701#R", &err);
        QVERIFY(f && f->isRemote() && f->len == 0);
        f = parseCansend(u"123#R4", &err);
        QVERIFY(f && f->isRemote() && f->len == 4);
        QCOMPARE(f->payloadSize(), 0);
    }
    void parsesFd() {
        QString err;
        auto f = parseCansend(QStringLiteral("123##1") + QString(24, u'A'), &err);
        QVERIFY2(f, qPrintable(err));
        QVERIFY(f->isFd());
        QVERIFY(f->flags & CanFrame::BitRateSwitch);
        QVERIFY(!(f->flags & CanFrame::ErrorState));
        QCOMPARE(f->len, 12);
    }
    void rejectsBadSyntax_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("reason");
        QTest::newRow("no hash") << "123DEAD"
                                 << "ID#DATA";
        QTest::newRow("id too big") << "800#00"
                                    << "above 7FF";
        QTest::newRow("ext too big") << "3FFFFFFF#00"
                                     << "above 1FFFFFFF";
        QTest::newRow("odd digits") << "123#ABC"
                                    << "odd number";
        QTest::newRow("too long") << "123#001122334455667788"
                                  << "more than 8";
        QTest::newRow("not hex") << "12G#00"
                                 << "not hexadecimal";
        QTest::newRow("fd bad len") << "123##0001122334455667788"
                                    << "not a CAN FD length";
        QTest::newRow("rtr bad") << "123#R9"
                                 << "0-8";
    }
    void rejectsBadSyntax() {
        QFETCH(QString, text);
        QFETCH(QString, reason);
        QString err;
        QVERIFY(!parseCansend(text, &err));
        QVERIFY2(err.contains(reason), qPrintable(err));
        QVERIFY(err.contains(text));
    }
    void formatsLikeCandump() {
        CanFrame f = CanFrame::classic(0x181, {0x37, 0x02});
        f.timestampNs = 1700000000123456789LL;
        QCOMPARE(formatCandumpL(f, u"can0"), QStringLiteral("(1700000000.123456) can0 181#3702"));
        CanFrame r;
        r.id = 0x12345678;
        r.flags = CanFrame::Extended | CanFrame::Remote;
        r.len = 2;
        QCOMPARE(formatCansend(r), QStringLiteral("12345678#R2"));
        CanFrame e;
        e.id = 0x4;
        e.flags = CanFrame::Error;
        e.len = 8;
        QCOMPARE(formatCansend(e), QStringLiteral("20000004#0000000000000000"));
    }
    void roundTripsThroughText() {
        for (const char* s :
             {"000#0100", "7FF#", "1FFFFFFF#0102030405060708", "123##3001122334455667788990011", "080#R"}) {
            QString err;
            auto f = parseCansend(QString::fromLatin1(s), &err);
            QVERIFY2(f, qPrintable(err));
            QCOMPARE(formatCansend(*f), QString::fromLatin1(s));
        }
    }
    void fdLengths() {
        QVERIFY(isValidFdLength(12));
        QVERIFY(!isValidFdLength(9));
        QCOMPARE(roundUpFdLength(9), 12);
        QCOMPARE(roundUpFdLength(33), 48);
        QCOMPARE(roundUpFdLength(65), -1);
    }
};

QTEST_GUILESS_MAIN(TestFrames)
#include "test_frames.moc"
