// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/can/SocketcandProtocol.h"

#include <QtTest>

using namespace coscope;
using namespace coscope::socketcand;

class TestSocketcandProtocol : public QObject {
    Q_OBJECT
private slots:
    void parsesFrameAsTheDaemonWritesIt() {
        // state_raw.c writes the data as one run of hex digits.
        QString err;
        auto m = parseMessage("< frame 123 23.424242 11223344 >", &err);
        QVERIFY2(m, qPrintable(err));
        QCOMPARE(m->kind, Message::Kind::Frame);
        QCOMPARE(m->frame.id, 0x123u);
        QVERIFY(!m->frame.isExtended());
        QCOMPARE(m->frame.len, 4);
        QCOMPARE(m->frame.data[0], 0x11);
        QCOMPARE(m->frame.data[3], 0x44);
        QCOMPARE(m->frame.timestampNs, int64_t(23'424'242'000));
    }
    void parsesFrameAsTheDocumentShowsIt() {
        QString err;
        auto m = parseMessage("< frame 123 23.424242 11 22 33 44 >", &err);
        QVERIFY2(m, qPrintable(err));
        QCOMPARE(m->frame.len, 4);
        QCOMPARE(m->frame.data[1], 0x22);
    }
    void extendedByDigitsOrValue() {
        QString err;
        auto m = parseMessage("< frame 00000080 1.5 >", &err);  // 8 digits: 29-bit even if small
        QVERIFY2(m, qPrintable(err));
        QVERIFY(m->frame.isExtended());
        QCOMPARE(m->frame.id, 0x80u);
        QCOMPARE(m->frame.len, 0);
        QCOMPARE(m->frame.timestampNs, int64_t(1'500'000'000));
        m = parseMessage("< frame 1ABCDEF0 1.0 00 >", &err);
        QVERIFY(m && m->frame.isExtended() && m->frame.id == 0x1ABCDEF0u);
        m = parseMessage("< frame 7FF 1.0 >", &err);
        QVERIFY(m && !m->frame.isExtended());
    }
    void parsesFdRtrAndErrorFrames() {
        QString err;
        auto m = parseMessage("< fdframe 1A 03 10.000001 000102030405060708090A0B >", &err);
        QVERIFY2(m, qPrintable(err));
        QVERIFY(m->frame.isFd());
        QVERIFY(m->frame.flags & CanFrame::BitRateSwitch);
        QVERIFY(m->frame.flags & CanFrame::ErrorState);
        QCOMPARE(m->frame.len, 12);
        QCOMPARE(m->frame.data[11], 0x0B);
        m = parseMessage("< rtr 701 3.000000 1 >", &err);
        QVERIFY2(m, qPrintable(err));
        QVERIFY(m->frame.isRemote());
        QCOMPARE(m->frame.len, 1);
        m = parseMessage("< error 004 5.000000 >", &err);  // CAN_ERR_CRTL
        QVERIFY2(m, qPrintable(err));
        QCOMPARE(m->kind, Message::Kind::Frame);
        QVERIFY(m->frame.isError());
        QCOMPARE(m->frame.id, 0x4u);
    }
    void textErrorsAndCommands() {
        QString err;
        auto m = parseMessage("< error unknown command >", &err);
        QVERIFY(m);
        QCOMPARE(m->kind, Message::Kind::Error);
        QCOMPARE(m->text, QStringLiteral("unknown command"));
        m = parseMessage("< hi >", &err);
        QVERIFY(m && m->kind == Message::Kind::Hi);
        m = parseMessage("<ok>", &err);
        QVERIFY(m && m->kind == Message::Kind::Ok);
        m = parseMessage("< open vcan0 >", &err);
        QVERIFY(m && m->kind == Message::Kind::Open && m->text == u"vcan0");
        m = parseMessage("< rawmode >", &err);
        QVERIFY(m && m->kind == Message::Kind::RawMode);
        m = parseMessage("< statistics 1000 >", &err);
        QVERIFY(m && m->kind == Message::Kind::Other && m->word == u"statistics");
    }
    void rejectsMalformedFrames_data() {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("reason");
        QTest::newRow("no timestamp") << QByteArray("< frame 123 >") << "expected '< frame";
        QTest::newRow("bad id") << QByteArray("< frame XYZ 1.0 >") << "bad identifier";
        QTest::newRow("id too big") << QByteArray("< frame 3FFFFFFF 1.0 >") << "bad identifier";
        QTest::newRow("bad time") << QByteArray("< frame 123 soon 11 >") << "bad timestamp";
        QTest::newRow("odd data") << QByteArray("< frame 123 1.0 112 >") << "odd number";
        QTest::newRow("nine bytes") << QByteArray("< frame 123 1.0 112233445566778899 >") << "more than 8";
        QTest::newRow("send len mismatch") << QByteArray("< send 123 3 11 22 >") << "length 3 but 2";
        QTest::newRow("send bad len") << QByteArray("< send 123 9 >") << "bad length";
        QTest::newRow("fd bad len") << QByteArray("< fdframe 123 00 1.0 112233445566778899 >") << "not a CAN FD length";
        QTest::newRow("empty") << QByteArray("<  >") << "empty message";
    }
    void rejectsMalformedFrames() {
        QFETCH(QByteArray, text);
        QFETCH(QString, reason);
        QString err;
        QVERIFY(!parseMessage(text, &err));
        QVERIFY2(err.contains(reason), qPrintable(err));
        QVERIFY2(err.startsWith(QStringLiteral("malformed socketcand message")), qPrintable(err));
    }
    void encodesClientCommandsExactly() {
        QCOMPARE(encodeOpen(QStringLiteral("can0")), QByteArray("< open can0 >"));
        QCOMPARE(encodeRawMode(), QByteArray("< rawmode >"));
        QCOMPARE(encodeSend(CanFrame::classic(0x123, {})), QByteArray("< send 123 0 >"));
        QCOMPARE(encodeSend(CanFrame::classic(0x1AAAAAAA, {0x01, 0xF1}, true)),
                 QByteArray("< send 1AAAAAAA 2 01 F1 >"));
        QCOMPARE(encodeSend(CanFrame::classic(0x80, {0xDE, 0xAD}, true)), QByteArray("< send 00000080 2 DE AD >"));
        CanFrame rtr = CanFrame::classic(0x701, {});
        rtr.flags |= CanFrame::Remote;
        rtr.len = 1;
        QCOMPARE(encodeSend(rtr), QByteArray("< sendrtr 701 1 >"));
        CanFrame fd = CanFrame::classic(0x10, {});
        fd.flags |= CanFrame::Fd | CanFrame::BitRateSwitch;
        fd.len = 12;
        for (int i = 0; i < 12; ++i) fd.data[i] = static_cast<uint8_t>(i);
        QCOMPARE(encodeSend(fd), QByteArray("< fdsend 010 1 12 00 01 02 03 04 05 06 07 08 09 0A 0B >"));
    }
    void sendRoundTripsThroughTheServerParser() {
        QString err;
        for (const CanFrame& f : {CanFrame::classic(0x123, {1, 2, 3}), CanFrame::classic(0x1FFFFFFF, {0xFF}, true),
                                  CanFrame::classic(0x7FF, {})}) {
            auto m = parseMessage(encodeSend(f), &err);
            QVERIFY2(m, qPrintable(err));
            QCOMPARE(m->kind, Message::Kind::Send);
            QCOMPARE(m->frame, f);
        }
    }
    void frameRoundTripsThroughTheClientParser() {
        QString err;
        CanFrame f = CanFrame::classic(0x1ABCDEF, {0xCA, 0xFE}, true);
        f.timestampNs = 1'700'000'000'123'456'000;
        QCOMPARE(encodeFrame(f), QByteArray("< frame 01ABCDEF 1700000000.123456 CAFE >"));
        auto m = parseMessage(encodeFrame(f), &err);
        QVERIFY2(m, qPrintable(err));
        QCOMPARE(m->frame, f);
        CanFrame e;
        e.flags = CanFrame::Error;
        e.id = 0x40;  // CAN_ERR_BUSOFF
        e.len = 8;
        e.timestampNs = 2'000'000'000;
        QCOMPARE(encodeFrame(e), QByteArray("< error 040 2.000000 >"));
        m = parseMessage(encodeFrame(e), &err);
        QVERIFY(m && m->frame.isError() && m->frame.id == 0x40u);
    }
    void splitterHandlesFragmentsAndBursts() {
        MessageSplitter s;
        QString discarded;
        s.feed("< h");
        QVERIFY(!s.next(&discarded));
        s.feed("i >< ok >\n< frame 123 1.0 ");
        QCOMPARE(s.next(&discarded).value_or(QByteArray()), QByteArray("< hi >"));
        QCOMPARE(s.next(&discarded).value_or(QByteArray()), QByteArray("< ok >"));
        QVERIFY(!s.next(&discarded));
        s.feed("11 >");
        QCOMPARE(s.next(&discarded).value_or(QByteArray()), QByteArray("< frame 123 1.0 11 >"));
        QVERIFY(!s.next(&discarded));
        QVERIFY(discarded.isEmpty());
    }
    void splitterDropsBrokenAndOverlongInput() {
        MessageSplitter s;
        QString discarded;
        s.feed("< frame 12< ok >");
        QCOMPARE(s.next(&discarded).value_or(QByteArray()), QByteArray("< ok >"));
        QVERIFY(discarded.contains(QStringLiteral("unterminated")));
        discarded.clear();
        s.feed("<" + QByteArray(MessageSplitter::kMaxMessage + 10, 'x'));
        QVERIFY(!s.next(&discarded));
        QVERIFY(discarded.contains(QStringLiteral("longer than")));
        discarded.clear();
        s.feed("< hi >");  // recovers after the garbage
        QCOMPARE(s.next(&discarded).value_or(QByteArray()), QByteArray("< hi >"));
    }
};

QTEST_GUILESS_MAIN(TestSocketcandProtocol)
#include "test_socketcand_protocol.moc"
